/**
 * @file newton_solver.h
 * Semismooth Newton loop that sees only callbacks: it knows no matrices,
 * meshes or contact. Convergence needs an unchanged active set, a small
 * complementarity residual and either a small equilibrium residual or a
 * small Newton step (the relative step test of PETSc's SNES, which ends
 * the iteration when round-off keeps the equilibrium residual above its
 * tolerance, as it does for bodies of very different stiffness) with the
 * residual below a bound that round-off cannot exceed.
 */
#ifndef common_solvers_newton_solver_h
#define common_solvers_newton_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace Common
{
  namespace Solvers
  {
    /**
     * @brief Parameters of subsection "Nonlinear solver".
     */
    struct NonlinearSolverParameters
    {
      /** @brief Declare the entries of subsection "Nonlinear solver". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read the entries of subsection "Nonlinear solver". */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      unsigned int max_iterations = 25;
      /** Tolerance on the residuals relative to the external load. */
      double tolerance = 1e-10;
      /** Tolerance on the Newton step relative to the solution. */
      double step_tolerance = 1e-8;
      /** Largest relative equilibrium residual the step test accepts. */
      double step_test_residual_bound = 1e-6;
      /** Inexact Newton: relative residual an iterative linear solve must
       * reach, as a multiple of the previous iteration's Newton residual;
       * 0 solves every system to the linear solver's own tolerance. */
      double linear_tolerance_factor = 0.;
      /** Start a load step from the linear extrapolation of the last two
       * accepted states of its stage instead of the last one. */
      bool extrapolate_initial_guess = false;
      /** Pseudo-transient continuation of a failed step: stiffness factor
       * of the springs to the last state (dimensionless; 0: off). */
      double stabilization_factor = 0.;
      /** An iterate whose relative equilibrium residual exceeds this
       * fails the step at once (0: no bound). */
      double divergence_bound = 0.;
      /** Solves of the first Newton iteration of a solve, at most, each
       * with the active set that the previous one's linearisation gives
       * (1: one solve, the semismooth update on the nonlinear iterate). */
      unsigned int max_first_iteration_solves = 1;
      /** The same for every later Newton iteration of a solve. */
      unsigned int max_later_iteration_solves = 1;
    };

    /**
     * @brief Residuals after an iteration, relative to the external load.
     */
    struct NewtonResidual
    {
      double equilibrium     = 0.;
      double complementarity = 0.;
      /** Norm of the Newton update relative to the norm of the solution. */
      double increment = 0.;
    };

    /**
     * @brief What the Newton loop needs from a problem.
     */
    struct NewtonCallbacks
    {
      /** Assemble the linearised system with the current active set, solve
       * it to the given relative residual (0: the linear solver's own
       * tolerance; only iterative solves use it) and apply the increment;
       * returns the norm of the increment relative to the norm of the
       * updated solution. */
      std::function<double(double)> assemble_solve_and_update;
      /** Residuals of the updated state (also updates the pressures). */
      std::function<NewtonResidual()> evaluate_residual;
      /** Apply the active-set rule; returns the number of changed points. */
      std::function<unsigned int()> update_active_set;
      /** True if the active set returned to an earlier state (which then
       * leaves the set unchanged). */
      std::function<bool()> is_cycling;
      /** Optional, with update_one_point: forget the active sets seen so
       * far but the current one. If given, a cycle does not end the
       * iteration, nor do eight semismooth iterations that still change
       * the set; the rest of the step is an active-set method on
       * equilibria: the set is held, without updates, until the
       * equilibrium residual falls below the complementarity residual
       * (the set's violation then outweighs the iterate's error, and the
       * pressures and gaps that decide the next change have their signs),
       * or meets the tolerance; then the history is restarted and the one
       * point with the largest violation changes, and so on. Once a change
       * leads back to a set held before in the step
       * (revisits_held_set()), each set is held until the tolerance: the
       * equilibria are then compared to detect an alternation between
       * two, or a cycle of more (an equilibrium reached a third time),
       * either of which fails the step. An iterate whose step vanishes
       * (below the step tolerance, the residual at round-off) is an
       * equilibrium even right after a change: changes that move nothing
       * (points with neither pressure nor gap) are compared too, and a
       * violation that none of them removes fails the step. So do
       * iterates that repeat themselves while the set changes (both
       * residuals to 1e-3 of those p iterations before, for p iterations
       * in a row, p from 2 to 8): a cycle that the set history does not
       * see, held sets released by a growing residual among them. And so do
       * eight iterations of this mode that leave the set unchanged from one to
       * the next, reach no equilibrium (to the tolerance or at round-off) and
       * do not halve the equilibrium residual: the changes that a problem makes
       * inside its iterations (the active-set solves of each linearisation) may
       * then trade two sets back and forth, and the iterates repeat in
       * pairs. A nonlinear problem judges its
       * sets on states out of equilibrium, and a bending body (whose
       * contact stiffness is no M-matrix) may cycle under the semismooth
       * rule even from equilibria; one change per equilibrium does not. */
      std::function<void()> restart_cycle_detection;
      /** Apply the active-set rule to the one point with the largest
       * violation; returns the number of changed points (0 or 1). */
      std::function<unsigned int()> update_one_point;
      /** Optional, with update_one_point: true if the last change of
       * update_one_point() led back to a set held earlier in the step
       * (every other change led to a set seen before). */
      std::function<bool()> revisits_held_set;
      /** Optional: update the multipliers of the constraints that the
       * problem enforces by an augmented Lagrangian at the current iterate
       * (SolidOperator::update_multipliers()); returns true if they
       * changed. Called after an iteration that leaves the active set
       * unchanged and brings both residuals below
       * multiplier_update_bound; if the
       * multipliers change, the iteration goes on with them
       * (NewtonStatistics::n_augmentations counts the updates), and a state
       * converges only once they need no update. The multipliers follow
       * the iterate as it converges, instead of a Newton solve to the
       * tolerance after each update. */
      std::function<bool()> update_multipliers;
    };

    /** The equilibrium and complementarity residuals (relative, as
     * NonlinearSolverParameters::tolerance) below which an iterate with an
     * unchanged active set updates the multipliers of an
     * augmented Lagrangian (NewtonCallbacks::update_multipliers): close
     * enough to its equilibrium that the constraint's violation there is
     * the one the update should remove. */
    constexpr double multiplier_update_bound = 1e-6;

    /**
     * @brief Outcome of one Newton solve.
     */
    struct NewtonStatistics
    {
      unsigned int n_iterations = 0;
      bool         converged    = false;
      /** Converged on the step test with the equilibrium residual above
       * its tolerance (at round-off level). */
      bool        converged_on_step = false;
      std::string failure;
      /** Failed by divergence: an equilibrium residual above the
       * divergence bound, a non-finite value, or a matrix that could not
       * be factorised. The increment was too large for the iteration,
       * which says nothing about the equilibria near the step's start. */
      bool                        diverged = false;
      std::vector<NewtonResidual> residuals;
      std::vector<unsigned int>   active_set_changes;
      /** Updates of the solid's multipliers (augmented Lagrangian): within
       * the iteration (NewtonCallbacks::update_multipliers), or each
       * followed by another Newton solve whose iterations are counted in
       * n_iterations. */
      unsigned int n_augmentations = 0;
      /** Solves of first iterations beyond their first
       * (NonlinearSolverParameters::max_first_iteration_solves), each an
       * assembly and a linear solve at the same state; not counted in
       * n_iterations. */
      unsigned int n_extra_first_iteration_solves = 0;
      /** The same for the later iterations
       * (NonlinearSolverParameters::max_later_iteration_solves). */
      unsigned int n_extra_later_iteration_solves = 0;
      /** Solves of the step with springs to the last state (the
       * stabilized path, NonlinearSolverParameters::stabilization_factor);
       * their iterations are counted in n_iterations. */
      unsigned int n_stabilized_solves = 0;
      /** Energy dissipated by the springs of the stabilized solves: each
       * spring acts as a dashpot of a backward-Euler pseudo-time step, and
       * a solve that moves DoF i by d_i against the stiffness k_i
       * dissipates k_i d_i^2. The energy that a snap releases between the
       * last equilibrium and the next; in the model's units (N mm, per mm
       * of depth in plane strain). 0 for a step solved without springs. */
      double stabilization_energy = 0.;
      /** Most Newton iterations of one solve of the step: n_iterations for
       * a step solved once; with stabilized solves and multiplier updates,
       * the largest of them. */
      unsigned int max_iterations_per_solve = 0;
    };

    /**
     * @brief Run the semismooth Newton iteration.
     * @param[in] verbose Stream for the residual history (one line per
     * iteration).
     */
    NewtonStatistics
    solve_newton(const NonlinearSolverParameters &parameters,
                 const NewtonCallbacks           &callbacks,
                 dealii::ConditionalOStream      &verbose);
  } // namespace Solvers
} // namespace Common

#endif
