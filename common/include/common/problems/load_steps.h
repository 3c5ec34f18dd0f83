/**
 * @file load_steps.h
 * The quasi-static load-step loop of a small-strain contact problem, as the
 * applications run it: solve each step (cut back on failure), commit an
 * accepted step, let the application report it, write the ParaView output
 * (displacement, stress, contact fields), and record the solve times.
 */
#ifndef common_problems_load_steps_h
#define common_problems_load_steps_h

#include <common/io/console.h>
#include <common/io/json_writer.h>
#include <common/io/output_parameters.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/problems/contact_run_parameters.h>
#include <common/problems/small_strain_contact_problem.h>
#include <common/solvers/load_stepping.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <functional>
#include <string>
#include <vector>

namespace Common
{
  namespace Problems
  {
    /**
     * @brief Print the size of the discretisation and of the contact
     * pairing: "Mesh: <cells> active cells, <DoFs> degrees of freedom,
     * Q<degree>" and "Contact: <n> secondary nodes, <m> paired, <k>
     * initially closed".
     */
    template <int dim>
    void
    print_setup(IO::Console                          &console,
                const dealii::DoFHandler<dim>        &dof_handler,
                const SmallStrainContactProblem<dim> &problem);

    /**
     * @brief The common start of a contact run once the mesh and the
     * contact problem are set up: print_setup(); for a dry run, say that
     * the input is valid and return false; otherwise clear the output
     * directory of @p result_files (IO::OutputParameters::
     * prepare_directory()), write used_parameters.prm and return true.
     */
    template <int dim>
    bool
    begin_run(IO::Console                          &console,
              const dealii::DoFHandler<dim>        &dof_handler,
              const SmallStrainContactProblem<dim> &problem,
              const ContactRunParameters           &parameters,
              const std::vector<std::string>       &result_files);

    /**
     * @brief The Newton record of a run for summary.json: total_iterations,
     * max_iterations_per_step, iterations_per_step, n_cutbacks.
     */
    IO::JsonObject
    newton_summary(const Solvers::LoadSteppingStatistics &stepping);

    /** Called after a load step is accepted and committed: step number,
     * load factor, Newton statistics. */
    using StepReport =
      std::function<void(const unsigned int               step,
                         const double                     load_factor,
                         const Solvers::NewtonStatistics &statistics)>;

    /**
     * @brief Run the load steps of @p problem from load factor 0 to 1 with
     * cutback (Solvers::run_load_stepping()). After each accepted step:
     * commit, @p report, and, if @p output asks for graphical output,
     * write "solution" (displacement, stress of @p physics, and the contact
     * pressure, status, tangential traction and slip). Adds to @p timings
     * the keys contact_setup_s, contact_solve_s, load_stepping_s,
     * assembly_s, linear_solve_s, residual_s and active_set_update_s
     * (seconds).
     */
    template <int dim>
    Solvers::LoadSteppingStatistics
    run_load_steps(SmallStrainContactProblem<dim>            &problem,
                   const ExternalLoad                        &load,
                   const Solvers::LoadSteppingParameters     &load_stepping,
                   const IO::OutputParameters                &output,
                   const Physics::SmallStrainElasticity<dim> &physics,
                   const dealii::DoFHandler<dim>             &dof_handler,
                   const dealii::Mapping<dim>                &mapping,
                   IO::Console                               &console,
                   const StepReport                          &report,
                   IO::JsonObject                            &timings);
  } // namespace Problems
} // namespace Common

#endif
