/**
 * @file contact_run.h
 * The run of a contact problem as every application makes it, so that an
 * application is only its geometry, boundary conditions, load program and
 * benchmark-specific postprocessing: the set-up report and the dry run,
 * the load program with commit, per-step report and ParaView output, the
 * per-step console header, and the blocks of summary.json that every
 * application writes (case, mesh, Newton record, timings).
 */
#ifndef common_problems_contact_run_h
#define common_problems_contact_run_h

#include <common/io/console.h>
#include <common/io/json_writer.h>
#include <common/io/output_parameters.h>
#include <common/problems/contact_newton_problem.h>
#include <common/problems/contact_run_parameters.h>
#include <common/solvers/load_program.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

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
    print_setup(IO::Console                     &console,
                const dealii::DoFHandler<dim>   &dof_handler,
                const ContactNewtonProblem<dim> &problem);

    /**
     * @brief The common start of a contact run once the mesh and the
     * contact problem are set up: print_setup(); for a dry run, say that
     * the input is valid and return false; otherwise clear the output
     * directory of @p result_files (IO::OutputParameters::
     * prepare_directory()), write used_parameters.prm and return true.
     */
    template <int dim>
    bool
    begin_run(IO::Console                     &console,
              const dealii::DoFHandler<dim>   &dof_handler,
              const ContactNewtonProblem<dim> &problem,
              const ContactRunParameters      &parameters,
              const std::vector<std::string>  &result_files);

    /**
     * @brief The Newton record of a run for summary.json: total_iterations,
     * max_iterations_per_step, iterations_per_step (the accepted attempt of
     * each step: its stabilized solves and multiplier updates included),
     * n_cutbacks, failed_attempt_iterations (the iterations of the attempts
     * that were cut back, not in total_iterations),
     * max_iterations_per_step_with_cutbacks (a step's accepted attempt and
     * the failed attempts since the step before it),
     * failed_attempt_iterations_per_step,
     * n_steps_converged_on_step_tolerance, the extra active-set solves
     * (first_iteration_extra_solves, later_iterations_extra_solves,
     * extra_solves_per_step, max_linear_solves_per_step_with_cutbacks),
     * stabilized_solves, max_stabilized_solves_per_step and
     * stabilized_solves_per_step (the solves with springs of steps that
     * had no equilibrium near the last state, failed attempts included),
     * stabilization_energy and
     * stabilization_energy_per_step (the energy that their springs
     * dissipated, NewtonStatistics::stabilization_energy, in the model's
     * units: N mm, per mm of depth in plane strain) and
     * max_iterations_per_solve (the most Newton iterations of one solve,
     * plain or stabilized, over every attempt).
     */
    IO::JsonObject
    newton_summary(const Solvers::LoadSteppingStatistics &stepping);

    /**
     * @brief The case block of summary.json that every contact application
     * shares: element_degree, enforcement, friction_law,
     * friction_coefficient, penalty_stiffness_MPa_per_mm (penalty only),
     * n_load_steps (nominal, all stages), n_load_stages and n_mpi_ranks.
     * The application adds its own keys (model, refinements).
     */
    IO::JsonObject
    case_summary(const ContactRunParameters &parameters,
                 const unsigned int          element_degree,
                 const MPI_Comm              mpi_communicator);

    /**
     * @brief The mesh block of summary.json: n_active_cells, n_dofs and
     * smallest_cell_in_contact_zone_mm, the smallest cell whose centre
     * lies where @p contact_distance (mm) is below the cell's diameter.
     */
    template <int dim>
    IO::JsonObject
    mesh_summary(const dealii::DoFHandler<dim> &dof_handler,
                 const std::function<double(const dealii::Point<dim> &)>
                   &contact_distance);

    /**
     * @brief The console line of an accepted step: "Load step k of n, load
     * factor x: Newton iterations i, active contact nodes m" for a
     * single-stage program of the load factor, "Stage s of S (name), step
     * k of n, pseudo-time t: ..." otherwise. Step counts beyond the
     * nominal number come from cutbacks.
     */
    template <int dim>
    void
    print_step(IO::Console                     &console,
               const Solvers::StepInfo         &step,
               const Solvers::NewtonStatistics &statistics,
               const ContactNewtonProblem<dim> &problem);

    /**
     * @brief Warn on the console if the contact zone reaches the edge of
     * the search region.
     */
    template <int dim>
    void
    warn_if_search_edge_reached(IO::Console                     &console,
                                const ContactNewtonProblem<dim> &problem);

    /**
     * @brief The load of a point force on one DoF: @p force (N, signed
     * along the DoF's component) times the load factor, added by the rank
     * that owns @p dof; its magnitude is |force| times the load factor.
     */
    template <int dim>
    ExternalLoad
    point_load(const dealii::DoFHandler<dim>        &dof_handler,
               const dealii::types::global_dof_index dof,
               const double                          force);

    /** Called after a step is accepted and committed. */
    using StepReport = std::function<void(const Solvers::StepInfo &,
                                          const Solvers::NewtonStatistics &)>;

    /**
     * @brief Run the load program on @p problem with cutback
     * (Solvers::run_load_program()). After each accepted step: commit,
     * @p report, and, if @p output asks for graphical output, write
     * "solution" (displacement, the solid's output fields, and the contact
     * pressure, status, tangential traction and slip). Adds to @p timings
     * the keys contact_setup_s, contact_solve_s, contact_cpu_s,
     * load_stepping_s, assembly_s, linear_solve_s, residual_s,
     * active_set_update_s and factorisation_s (seconds), and the linear
     * solver's counts n_factorisations, n_reuse_solves,
     * n_reuse_gmres_iterations and n_failed_reuse.
     */
    template <int dim>
    Solvers::LoadSteppingStatistics
    run_load_steps(ContactNewtonProblem<dim>            &problem,
                   const ExternalLoad                   &load,
                   const Solvers::LoadProgramParameters &program,
                   const IO::OutputParameters           &output,
                   const dealii::DoFHandler<dim>        &dof_handler,
                   const dealii::Mapping<dim>           &mapping,
                   IO::Console                          &console,
                   const StepReport                     &report,
                   IO::JsonObject                       &timings);

    /**
     * @brief If the run asks for it, measure the cost of contact: the
     * processor time of the contact solve over that of one assembly and
     * solve with the final active set held fixed (median of three), and
     * add contact_cpu_s, fixed_active_set_solve_s and contact_cost_ratio
     * to @p timings. Prints the ratio (a timing: not for test output).
     */
    template <int dim>
    void
    measure_contact_cost(ContactNewtonProblem<dim>  &problem,
                         const ExternalLoad         &load,
                         const Solvers::LoadState   &state,
                         const ContactRunParameters &parameters,
                         IO::Console                &console,
                         IO::JsonObject             &timings);
  } // namespace Problems
} // namespace Common

#endif
