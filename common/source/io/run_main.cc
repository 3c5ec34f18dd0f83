#include <common/io/run_main.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace Common
{
  namespace IO
  {
    namespace
    {
      void
      print_usage(const std::string &name, const std::string &description)
      {
        std::cout << name << ": " << description << "\n\n"
                  << "Usage:\n"
                  << "  " << name << " <file.prm>           run the case\n"
                  << "  " << name
                  << " --print-parameters   list every .prm entry with "
                     "its documentation and default\n"
                  << "  " << name << " --help               this text\n";
      }


      /** True if the file has a line other than blanks and comments. */
      bool
      has_entries(const std::string &filename)
      {
        std::ifstream in(filename);
        std::string   line;
        while (std::getline(in, line))
          {
            const auto first = line.find_first_not_of(" \t\r");
            if (first != std::string::npos && line[first] != '#')
              return true;
          }
        return false;
      }



      /**
       * Report an error in one line and end the run with exit code 1. In
       * parallel the other ranks may be waiting for this one in a
       * collective call, so every rank is ended (MPI_Abort). An error of
       * the input occurs on every rank at once: rank 0 reports it, and the
       * other ranks wait a moment first, so that the abort ends them
       * before they repeat it; an error on another rank alone is reported
       * by that rank, with its number.
       */
      int
      end_with_error(const std::string &application_name,
                     const std::string &message)
      {
        const unsigned int n_ranks =
          dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
        const unsigned int rank =
          dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
        if (n_ranks == 1)
          {
            std::cerr << application_name << ": error: " << message
                      << std::endl;
            return 1;
          }
        if (rank != 0)
          std::this_thread::sleep_for(std::chrono::seconds(2));
        std::cerr << application_name << ": error"
                  << (rank == 0 ? std::string() :
                                  " (MPI rank " + std::to_string(rank) + ")")
                  << ": " << message << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
        return 1;
      }
    } // namespace



    std::string
    one_line_message(const std::exception &exception)
    {
      std::ostringstream raw;
      if (const auto *deal_exception =
            dynamic_cast<const dealii::ExceptionBase *>(&exception))
        deal_exception->print_info(raw);
      else
        raw << exception.what();

      std::string line;
      bool        space = false;
      for (const char c : raw.str())
        {
          if (std::isspace(static_cast<unsigned char>(c)))
            space = !line.empty();
          else
            {
              if (space)
                line += ' ';
              line += c;
              space = false;
            }
        }
      return line.empty() ? std::string(exception.what()) : line;
    }



    int
    run_main(
      int                                                    argc,
      char                                                 **argv,
      const std::string                                     &application_name,
      const std::string                                     &description,
      const std::function<void(dealii::ParameterHandler &)> &declare_parameters,
      const std::function<void(const std::string &)>        &run)
    {
      // deal.II's exceptions print their own banner to std::cerr before
      // they are thrown from some places (e.g. in debug mode): suppress
      // that, this function reports every error in one line.
      dealii::deal_II_exceptions::disable_abort_on_exception();
      dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();

      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool                               root =
        dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

      if (argc != 2)
        {
          if (root)
            print_usage(application_name, description);
          return 1;
        }

      const std::string argument = argv[1];
      try
        {
          if (argument == "--help" || argument == "-h")
            {
              if (root)
                print_usage(application_name, description);
              return 0;
            }
          if (argument == "--print-parameters")
            {
              dealii::ParameterHandler prm;
              declare_parameters(prm);
              if (root)
                prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
              return 0;
            }
          AssertThrow(std::filesystem::is_regular_file(argument),
                      dealii::ExcMessage("cannot open parameter file <" +
                                         argument + ">"));
          // A file without entries would run the defaults: a case that no
          // file describes.
          AssertThrow(has_entries(argument),
                      dealii::ExcMessage(
                        "parameter file <" + argument +
                        "> has no entries (it is empty or holds only "
                        "comments)"));
          run(argument);
        }
      catch (const std::exception &exception)
        {
          return end_with_error(application_name, one_line_message(exception));
        }
      catch (...)
        {
          return end_with_error(application_name, "unknown exception");
        }
      return 0;
    }
  } // namespace IO
} // namespace Common
