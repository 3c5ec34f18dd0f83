#include <common/io/timer.h>
#include <common/problems/contact_application.h>
#include <common/problems/contact_run.h>

#include <deal.II/fe/fe_q.h>

#include <chrono>

namespace Common
{
  namespace Problems
  {
    using namespace dealii;

    template <int dim>
    ContactApplication<dim>::ContactApplication(
      const ContactRunParameters &parameters,
      const unsigned int          element_degree,
      const std::string          &application_name)
      : run_parameters(parameters)
      , application_name(application_name)
      , mpi_communicator(MPI_COMM_WORLD)
      , console(parameters.output.verbosity, mpi_communicator)
      , triangulation(mpi_communicator)
      , fe(FE_Q<dim>(element_degree), dim)
      , mapping(element_degree)
      , dof_handler(triangulation)
    {}



    template <int dim>
    void
    ContactApplication<dim>::setup_contact_problem(
      std::unique_ptr<Physics::SolidOperator<dim>>   solid_operator,
      std::unique_ptr<Contact::ContactGeometry<dim>> geometry,
      const double                                   reference_modulus)
    {
      constraints_dirichlet_and_hanging_nodes.close();
      solid            = std::move(solid_operator);
      contact_geometry = std::move(geometry);
      contact_problem  = std::make_unique<ContactNewtonProblem<dim>>(
        dof_handler,
        mapping,
        *solid,
        *contact_geometry,
        run_parameters.contact,
        run_parameters.linear_solver,
        run_parameters.nonlinear_solver,
        reference_modulus,
        mpi_communicator);
      contact_problem->setup(constraints_dirichlet_and_hanging_nodes);
    }



    template <int dim>
    void
    ContactApplication<dim>::write_plots(
      const std::vector<std::pair<std::string, IO::PlotDescription>> &plots)
    {
      const auto missing =
        IO::write_plots(run_parameters.output.directory, plots);
      if (missing.empty())
        return;
      if (!IO::gnuplot_available())
        console.stream() << "  Note: gnuplot not available; plot scripts "
                            "written without PNG."
                         << std::endl;
      else
        for (const auto &name : missing)
          console.stream() << "  Warning: gnuplot could not draw " << name
                           << ".gp; its script is written, without PNG."
                           << std::endl;
    }



    template <int dim>
    double
    ContactApplication<dim>::final_load_factor() const
    {
      const auto &program = run_parameters.load_program;
      return program.state(program.stages.size()).load_factor();
    }



    template <int dim>
    void
    ContactApplication<dim>::write_summary(
      const Solvers::LoadSteppingStatistics &stepping,
      const SummaryBlocks                   &blocks) const
    {
      IO::JsonObject summary;
      summary.set("benchmark", application_name)
        .set("case", blocks.case_description)
        .set("mesh", blocks.mesh)
        .set("newton", newton_summary(stepping))
        .set("results", blocks.results)
        .set("reference", blocks.reference)
        .set("ratios", blocks.ratios)
        .set("timing_s", timings);
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        summary.write(run_parameters.output.path("summary.json"));
    }



    template <int dim>
    void
    ContactApplication<dim>::run()
    {
      const auto start = std::chrono::steady_clock::now();
      console.stream() << title() << std::endl;
      make_grid();
      setup_system();
      timings.set("setup_s", IO::seconds_since(start));
      std::vector<std::string> files = {"summary.json",
                                        "contact_profile.csv",
                                        "reference_profile.csv",
                                        "contact_pressure.png",
                                        "contact_pressure.gp",
                                        "tangential_traction.png",
                                        "tangential_traction.gp",
                                        "slip.png",
                                        "slip.gp",
                                        "solution.pvd",
                                        "reactions.csv"};
      for (const auto &file : result_files())
        files.push_back(file);
      if (!begin_run<dim>(console,
                          dof_handler,
                          *contact_problem,
                          run_parameters,
                          files))
        return;

      const ExternalLoad load     = external_load();
      const auto         stepping = run_load_steps<dim>(
        *contact_problem,
        load,
        run_parameters.load_program,
        run_parameters.output,
        dof_handler,
        mapping,
        console,
        [this](const Solvers::StepInfo         &step,
               const Solvers::NewtonStatistics &statistics) {
          postprocess_step(step, statistics);
        },
        timings);
      measure_contact_cost(*contact_problem,
                           load,
                           run_parameters.load_program.state(
                             run_parameters.load_program.stages.size()),
                           run_parameters,
                           console,
                           timings);
      timings.set("total_s", IO::seconds_since(start));
      output_results(stepping);
    }

    template class ContactApplication<2>;
    template class ContactApplication<3>;
  } // namespace Problems
} // namespace Common
