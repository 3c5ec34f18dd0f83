#include <common/contact/contact_postprocessor.h>
#include <common/io/solution_output.h>
#include <common/io/timer.h>
#include <common/problems/load_steps.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <utility>
#include <vector>

namespace Common
{
  namespace Problems
  {
    using namespace dealii;

    IO::JsonObject
    newton_summary(const Solvers::LoadSteppingStatistics &stepping)
    {
      unsigned int total_iterations = 0, max_iterations = 0;
      for (const auto n : stepping.newton_iterations)
        {
          total_iterations += n;
          max_iterations = std::max(max_iterations, n);
        }
      IO::JsonObject newton;
      newton.set("total_iterations", total_iterations)
        .set("max_iterations_per_step", max_iterations)
        .set("iterations_per_step", stepping.newton_iterations)
        .set("n_cutbacks", stepping.n_cutbacks)
        .set("n_steps_converged_on_step_tolerance",
             stepping.n_converged_on_step);
      return newton;
    }



    template <int dim>
    void
    print_setup(IO::Console                          &console,
                const DoFHandler<dim>                &dof_handler,
                const SmallStrainContactProblem<dim> &problem)
    {
      const auto  &coupling = problem.coupling();
      unsigned int n_paired = 0;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        n_paired += coupling.row(j).has_partner;
      console.stream() << "Mesh: "
                       << dof_handler.get_triangulation().n_active_cells()
                       << " active cells, " << dof_handler.n_dofs()
                       << " degrees of freedom, Q"
                       << dof_handler.get_fe().degree << std::endl
                       << "Contact: " << coupling.n_rows()
                       << " secondary nodes, " << n_paired << " paired, "
                       << problem.enforcement().n_active()
                       << " initially closed" << std::endl;
    }



    template <int dim>
    bool
    begin_run(IO::Console                          &console,
              const DoFHandler<dim>                &dof_handler,
              const SmallStrainContactProblem<dim> &problem,
              const ContactRunParameters           &parameters,
              const std::vector<std::string>       &result_files)
    {
      print_setup<dim>(console, dof_handler, problem);
      if (parameters.run_control.dry_run)
        {
          console.stream() << "Dry run: parameters, mesh and contact pairing "
                              "are valid."
                           << std::endl;
          return false;
        }
      std::vector<std::string> files = result_files;
      files.push_back("used_parameters.prm");
      parameters.output.prepare_directory(files,
                                          dof_handler.get_communicator());
      if (console.is_root())
        {
          std::ofstream used(parameters.output.path("used_parameters.prm"));
          used << parameters.used_parameters;
        }
      return true;
    }



    template <int dim>
    Solvers::LoadSteppingStatistics
    run_load_steps(SmallStrainContactProblem<dim>            &problem,
                   const ExternalLoad                        &load,
                   const Solvers::LoadSteppingParameters     &load_stepping,
                   const IO::OutputParameters                &output,
                   const Physics::SmallStrainElasticity<dim> &physics,
                   const DoFHandler<dim>                     &dof_handler,
                   const Mapping<dim>                        &mapping,
                   IO::Console                               &console,
                   const StepReport                          &report,
                   IO::JsonObject                            &timings)
    {
      IO::SolutionOutput<dim>                 solution_output(output,
                                              "solution",
                                              dof_handler.get_communicator());
      const Physics::StressPostprocessor<dim> stress(physics);

      Solvers::LoadStepCallbacks callbacks;
      callbacks.solve = [&](const double load_factor) {
        return problem.solve(load_factor,
                             load,
                             console.stream(IO::Verbosity::verbose));
      };
      callbacks.accept = [&](const unsigned int               step,
                             const double                     load_factor,
                             const Solvers::NewtonStatistics &statistics) {
        problem.commit();
        report(step, load_factor, statistics);
        if (output.write_graphical_output)
          {
            std::vector<IO::NodalScalarField> contact_fields;
            for (auto &[name, values] :
                 Contact::contact_nodal_fields(problem.coupling(),
                                               problem.enforcement()))
              contact_fields.push_back({name, std::move(values)});
            solution_output.write(dof_handler,
                                  mapping,
                                  problem.displacement(),
                                  {&stress},
                                  contact_fields,
                                  load_factor,
                                  step);
          }
      };
      callbacks.reject = [&]() {
        problem.restore();
      };

      const auto start = std::chrono::steady_clock::now();
      const auto stepping =
        Solvers::run_load_stepping(load_stepping, callbacks, console);
      const auto &times = problem.times();
      timings.set("contact_setup_s", times.contact_setup)
        .set("contact_solve_s", times.contact_setup + times.newton)
        .set("load_stepping_s", IO::seconds_since(start))
        .set("assembly_s", times.assembly)
        .set("linear_solve_s", times.linear_solve)
        .set("residual_s", times.residual)
        .set("active_set_update_s", times.active_set_update);
      return stepping;
    }

    template void
    print_setup(IO::Console &,
                const DoFHandler<2> &,
                const SmallStrainContactProblem<2> &);
    template void
    print_setup(IO::Console &,
                const DoFHandler<3> &,
                const SmallStrainContactProblem<3> &);
    template bool
    begin_run(IO::Console &,
              const DoFHandler<2> &,
              const SmallStrainContactProblem<2> &,
              const ContactRunParameters &,
              const std::vector<std::string> &);
    template bool
    begin_run(IO::Console &,
              const DoFHandler<3> &,
              const SmallStrainContactProblem<3> &,
              const ContactRunParameters &,
              const std::vector<std::string> &);
    template Solvers::LoadSteppingStatistics
    run_load_steps(SmallStrainContactProblem<2> &,
                   const ExternalLoad &,
                   const Solvers::LoadSteppingParameters &,
                   const IO::OutputParameters &,
                   const Physics::SmallStrainElasticity<2> &,
                   const DoFHandler<2> &,
                   const Mapping<2> &,
                   IO::Console &,
                   const StepReport &,
                   IO::JsonObject &);
    template Solvers::LoadSteppingStatistics
    run_load_steps(SmallStrainContactProblem<3> &,
                   const ExternalLoad &,
                   const Solvers::LoadSteppingParameters &,
                   const IO::OutputParameters &,
                   const Physics::SmallStrainElasticity<3> &,
                   const DoFHandler<3> &,
                   const Mapping<3> &,
                   IO::Console &,
                   const StepReport &,
                   IO::JsonObject &);
  } // namespace Problems
} // namespace Common
