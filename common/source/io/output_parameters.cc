#include <common/io/output_parameters.h>

#include <filesystem>

namespace Common
{
  namespace IO
  {
    using namespace dealii;

    void
    OutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Output directory",
                          "results",
                          Patterns::DirectoryName(),
                          "Directory for summary.json, profile CSV files, "
                          "plots and ParaView files. Created if missing. "
                          "Must not be named 'output' (the test driver "
                          "uses that name).");
        prm.declare_entry("Write graphical output",
                          "true",
                          Patterns::Bool(),
                          "Write .vtu/.pvd files for ParaView.");
        prm.declare_entry("Write plots",
                          "true",
                          Patterns::Bool(),
                          "Write PNG plots with gnuplot (skipped with a "
                          "notice when gnuplot is not installed).");
        prm.declare_entry(
          "Reaction boundary ids",
          "",
          Patterns::List(Patterns::Integer(0, 255)),
          "Comma-separated boundary ids whose reaction forces are written, "
          "for every accepted load step, to reactions.csv against "
          "pseudo-time: the sum over every DoF of the boundary of the "
          "internal forces minus the applied loads, per component (a node "
          "the boundary shares with another support counts in both, a "
          "contact node adds its contact force). Units: "
          "N per mm of thickness in plane strain, N over the full ring when "
          "axisymmetric, N in 3D. Empty: no file.");
        prm.declare_entry("Verbosity",
                          "normal",
                          Patterns::Selection("quiet|normal|verbose"),
                          "Console output: quiet (errors and final "
                          "summary), normal (per load step), verbose (also "
                          "Newton residuals).");
      }
      prm.leave_subsection();
    }



    void
    OutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        directory = prm.get("Output directory");
        AssertThrow(!directory.empty(),
                    ExcMessage("Output: 'Output directory' is empty."));
        AssertThrow(std::filesystem::path(directory).filename() != "output",
                    ExcMessage("Output: 'Output directory' must not be named "
                               "'output'."));
        reaction_boundary_ids.clear();
        for (const auto &id :
             Utilities::split_string_list(prm.get("Reaction boundary ids")))
          reaction_boundary_ids.push_back(Utilities::string_to_int(id));
        write_graphical_output = prm.get_bool("Write graphical output");
        write_plots            = prm.get_bool("Write plots");
        const std::string v    = prm.get("Verbosity");
        verbosity              = (v == "quiet"  ? Verbosity::quiet :
                                  v == "normal" ? Verbosity::normal :
                                                  Verbosity::verbose);
      }
      prm.leave_subsection();
    }



    void
    OutputParameters::prepare_directory(
      const std::vector<std::string> &result_files,
      const MPI_Comm                  mpi_communicator) const
    {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        {
          std::filesystem::create_directories(directory);
          for (const auto &name : result_files)
            std::filesystem::remove(path(name));
        }
      MPI_Barrier(mpi_communicator);
    }



    std::string
    OutputParameters::path(const std::string &file_name) const
    {
      return (std::filesystem::path(directory) / file_name).string();
    }
  } // namespace IO
} // namespace Common
