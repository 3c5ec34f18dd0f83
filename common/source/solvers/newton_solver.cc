#include <common/io/console.h>
#include <common/solvers/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace Common
{
  namespace Solvers
  {
    using namespace dealii;

    void
    NonlinearSolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      {
        prm.declare_entry("Maximum number of iterations",
                          "25",
                          Patterns::Integer(1),
                          "Semismooth Newton iterations per load step before "
                          "the step is cut back.");
        prm.declare_entry("Tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "Convergence tolerance on the equilibrium and "
                          "complementarity residuals, relative to the "
                          "external load. Dimensionless.");
        prm.declare_entry(
          "Step tolerance",
          "1e-8",
          Patterns::Double(0.),
          "An iteration that leaves the active set unchanged and meets the "
          "complementarity tolerance also converges when the Newton step is "
          "smaller than this fraction of the solution (both Euclidean "
          "norms): the equilibrium residual is then at its round-off level, "
          "which exceeds 'Tolerance' when the bodies' stiffnesses differ by "
          "orders of magnitude. 0 disables the test. Dimensionless.");
        prm.declare_entry(
          "Linear tolerance factor",
          "0",
          Patterns::Double(0., 0.5),
          "Inexact Newton: an iterative linear solve (GMRES with reused "
          "factors, or multigrid) in iteration k > 1 of a load step stops at "
          "this multiple of the Newton residual of iteration k-1 (the larger "
          "of its equilibrium and complementarity residuals) relative to the "
          "right-hand side, never below the linear solver's 'Tolerance' and "
          "never below a hundredth of 'Tolerance' times the external load. "
          "Early iterations, whose active set is still wrong, then cost a few "
          "solves with old factors instead of a new factorisation; the first "
          "iteration of a step is solved fully, and so is the rest of a step "
          "once its active set returns to an earlier one. The converged "
          "state meets 'Tolerance' as before. 0 solves every system to the "
          "linear solver's 'Tolerance'. Dimensionless, in [0, 0.5].");
        prm.declare_entry(
          "Extrapolate initial guess",
          "false",
          Patterns::Bool(),
          "Start each load step from the linear extrapolation of the last "
          "two accepted states of its stage, u_n + r (u_n - u_{n-1}) with r "
          "the ratio of the step's pseudo-time increment to the last one "
          "(at most 1), instead of from u_n. Held DoFs keep their values, "
          "and prescribed ones take their targets in the first iteration as "
          "always; the first two steps of a stage start from u_n. In a "
          "smooth loading history (forming) the first iterate then lies "
          "near the solution, and fewer contact nodes change status on the "
          "way. Affects the iteration path only.");
        prm.declare_entry(
          "Stabilization factor",
          "0",
          Patterns::Double(0.),
          "Pseudo-transient continuation of a load step whose iteration "
          "fails (an unstable sheet whose contact state has no equilibrium "
          "near the last one): the step is solved again from its start "
          "with a spring at every free DoF to the last solution, of "
          "stiffness factor x E int N_i dV / h^2 (E the reference modulus, "
          "h the cell's smallest vertex distance), anchored anew at each "
          "solution and softened by half after each solve that moves less "
          "than the one before, until a solve moves no DoF by more than "
          "1e-6 of the smallest cell (at most 100 solves); the springs are "
          "then removed and the state is solved to equilibrium without "
          "them, which alone is accepted. The path between is a "
          "dissipative one, as a snap would take; the energy the springs "
          "dissipate on it (k d^2 per solve and DoF, d its motion) is "
          "reported in summary.json. A "
          "solve that fails starts again from its anchor with springs four "
          "times as stiff; if it fails with the initial springs, the step "
          "is cut back. A step whose iteration diverges "
          "(above the 'Divergence bound', a non-finite value, a matrix that "
          "cannot be factorised) is cut back first, since a smaller "
          "increment may converge at once, and takes this path only if the "
          "retried step fails too. "
          "0: off, a failed step is cut back at once. Dimensionless.");
        prm.declare_entry(
          "Divergence bound",
          "0",
          Patterns::Double(0.),
          "An iterate whose equilibrium residual, relative to the external "
          "load, exceeds this bound fails the step at once (it is cut back; "
          "a retried step may be solved again with the stabilization "
          "springs), instead of "
          "iterating on from a state far from any equilibrium (a sheet "
          "thrown off its tools) until a value turns non-finite or the "
          "iterations run out. Set it well above the largest residual of a "
          "converging step (a few tens in forming). 0: no bound. "
          "Dimensionless.");
        prm.declare_entry(
          "Active-set solves in the first iteration",
          "1",
          Patterns::Integer(1, 100),
          "Lagrange multipliers in a nonlinear problem: the first Newton "
          "iteration of a load step carries its load increment and decides "
          "most of its active set. Above 1, that iteration solves the "
          "contact problem of its own linearisation (sequential quadratic "
          "programming): the step is solved again from the same state with "
          "the set that the pressures of the linearised residual and the "
          "gaps at the solve's end give, first by the semismooth update of "
          "every point, then one point per solve (the largest violation "
          "whose change leads to a set not yet solved on this "
          "linearisation, a pivoting method), until no point changes, no "
          "change leads to a new set, or this many solves are made; the "
          "iteration then goes on from the last solve with the semismooth "
          "update. The set is then judged on a consistent linear model "
          "instead of an iterate far from equilibrium. Each further solve "
          "costs an assembly and a linear solve, and is counted in "
          "summary.json (newton/first_iteration_extra_solves and "
          "newton/extra_solves_per_step), not as a Newton iteration. 1: one "
          "solve, the semismooth method alone. Ignored where the problem is "
          "linear or penalized. Dimensionless.");
        prm.declare_entry(
          "Active-set solves in later iterations",
          "1",
          Patterns::Integer(1, 100),
          "The same as 'Active-set solves in the first iteration' for every "
          "later Newton iteration of a solve: each linearisation then "
          "solves its own contact problem, and the Newton iterations count "
          "linearisations (a Josephy-Newton method). Where contact "
          "pressures vanish over a zone (a strip wrapped around a tool), "
          "the set that satisfies every point is found there on one "
          "linearisation instead of one change per Newton iteration. The "
          "further solves are counted in summary.json "
          "(newton/later_iterations_extra_solves and "
          "newton/extra_solves_per_step). 1: one solve per iteration. "
          "Ignored where the problem is linear or penalized. "
          "Dimensionless.");
        prm.declare_entry(
          "Step test residual bound",
          "1e-6",
          Patterns::Double(0.),
          "The step test accepts an equilibrium residual (relative to the "
          "external load) up to this bound; above it a vanishing step means "
          "that the residual and the linearisation disagree, and the "
          "iteration fails, unless the last step still halved the residual "
          "(the small steps of a stiff system, such as a stiff penalty or a "
          "bent strip), in which case it goes on. Dimensionless.");
      }
      prm.leave_subsection();
    }



    void
    NonlinearSolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      {
        max_iterations = prm.get_integer("Maximum number of iterations");
        tolerance      = prm.get_double("Tolerance");
        AssertThrow(tolerance > 0.,
                    ExcMessage("Nonlinear solver: 'Tolerance' must be "
                               "positive (a relative residual of exactly zero "
                               "is never reached), got " +
                               std::to_string(tolerance) + "."));
        step_tolerance            = prm.get_double("Step tolerance");
        step_test_residual_bound  = prm.get_double("Step test residual bound");
        linear_tolerance_factor   = prm.get_double("Linear tolerance factor");
        extrapolate_initial_guess = prm.get_bool("Extrapolate initial guess");
        stabilization_factor      = prm.get_double("Stabilization factor");
        divergence_bound          = prm.get_double("Divergence bound");
        max_first_iteration_solves =
          prm.get_integer("Active-set solves in the first iteration");
        max_later_iteration_solves =
          prm.get_integer("Active-set solves in later iterations");
      }
      prm.leave_subsection();
    }



    NewtonStatistics
    solve_newton(const NonlinearSolverParameters &parameters,
                 const NewtonCallbacks           &callbacks,
                 ConditionalOStream              &verbose)
    {
      NewtonStatistics statistics;
      const auto       finish = [&statistics]() {
        statistics.max_iterations_per_solve = statistics.n_iterations;
        return statistics;
      };
      // Inexact solves stop at the first sign of an active set that
      // returns to an earlier one: the rest of the step is solved exactly.
      bool inexact = parameters.linear_tolerance_factor > 0.;
      // After a cycle, or after n_semismooth iterations that still change
      // the set: one change per equilibrium (see NewtonCallbacks).
      constexpr unsigned int n_semismooth               = 8;
      bool                   one_change_per_equilibrium = false;
      // The iteration after which one change per equilibrium began, and
      // the iterations in which its equilibrium residual must halve.
      unsigned int           one_change_since = 0;
      constexpr unsigned int n_stagnation     = 8;
      // The iterations without an equilibrium in which one change per
      // equilibrium must halve its Newton residual.
      constexpr unsigned int n_wander = 2 * n_stagnation;
      // The last iteration whose iterate reached an equilibrium (to the
      // tolerance or at round-off): a held set's progress.
      unsigned int last_equilibrium = 0;
      bool         hold_set         = false;
      unsigned int n_held           = 0;
      // A held set changes once its equilibrium residual falls below the
      // complementarity residual, until a change leads back to a set held
      // before; from then on at equilibrium only (see NewtonCallbacks).
      bool early_changes = true;
      // The complementarity residuals of the held sets' equilibria: an
      // equilibrium that returns to the one before the last (A, B, A)
      // alternates between two sets for good, since the single change
      // from each is determined by the state.
      std::vector<double> equilibria;
      for (unsigned int it = 1; it <= parameters.max_iterations; ++it)
        {
          // Inexact Newton: the first iteration, which carries the load
          // increment and fixes the first active set, is solved fully;
          // later ones to the factor times the Newton residual they start
          // from, so that the solves tighten as the iteration converges.
          const double linear_tolerance =
            it == 1 || !inexact ?
              0. :
              parameters.linear_tolerance_factor *
                std::max(statistics.residuals.back().equilibrium,
                         statistics.residuals.back().complementarity);
          const double increment =
            callbacks.assemble_solve_and_update(linear_tolerance);
          // A solve to below the Newton tolerance is as good as exact.
          const bool inexact_solve = linear_tolerance > parameters.tolerance;
          NewtonResidual residual  = callbacks.evaluate_residual();
          residual.increment       = increment;
          // A held set has no equilibrium nearby if the residual grows
          // (a node that must change carries the body, e.g. its only
          // support): the set is then updated, one point, from here.
          // Compared from the second held iterate on: the first one
          // follows a change of the set, which raises the residual.
          const bool hold_diverges =
            hold_set && n_held > 0 &&
            residual.equilibrium > 2. * statistics.residuals.back().equilibrium;
          // A held iterate whose step vanishes has reached its
          // equilibrium at round-off level, below the tolerance or not.
          // The first iterate after a change counts too: its step carries
          // the change, and a change that moves nothing leaves the state
          // where it was (a point with neither pressure nor gap), so that
          // changes of that kind are compared as equilibria, and a
          // violation that none of them removes ends the step instead of
          // running it to its iteration limit.
          const bool hold_at_round_off =
            hold_set && !inexact_solve &&
            residual.increment < parameters.step_tolerance &&
            residual.equilibrium <= parameters.step_test_residual_bound;
          // A held iterate whose equilibrium residual is below its
          // complementarity residual decides the next change as its
          // equilibrium would: the violation outweighs the iterate's error.
          const bool hold_decides =
            hold_set && early_changes && !inexact_solve &&
            residual.equilibrium < residual.complementarity;
          n_held = hold_set ? n_held + 1 : 0;
          if (residual.equilibrium < parameters.tolerance || hold_at_round_off)
            last_equilibrium = it;
          if (hold_set &&
              (residual.equilibrium < parameters.tolerance ||
               hold_at_round_off) &&
              residual.complementarity >= parameters.tolerance)
            {
              equilibria.push_back(residual.complementarity);
              const std::size_t n    = equilibria.size();
              const auto        same = [&](const double e) {
                return std::abs(e - equilibria[n - 1]) <=
                       1e-6 * equilibria[n - 1];
              };
              std::string failure;
              if (n >= 3 && same(equilibria[n - 3]))
                failure = "the active set alternates between two equilibria "
                          "(complementarity residuals " +
                          IO::Console::format(equilibria[n - 2]) + " and " +
                          IO::Console::format(equilibria[n - 1]) +
                          "): no contact state has both the pressures and "
                          "the gaps of the right sign";
              // An equilibrium reached for the third time: the changes
              // between run in a cycle of more than two sets.
              else if (std::count_if(equilibria.begin(),
                                     equilibria.end() - 1,
                                     same) >= 2)
                failure = "the active set cycles among equilibria (one "
                          "reached three times, complementarity residual " +
                          IO::Console::format(equilibria[n - 1]) + ")";
              if (!failure.empty())
                {
                  statistics.n_iterations = it;
                  statistics.residuals.push_back(residual);
                  statistics.active_set_changes.push_back(0);
                  statistics.failure = failure;
                  return finish();
                }
            }
          if (hold_set && (residual.equilibrium < parameters.tolerance ||
                           hold_diverges || hold_at_round_off || hold_decides))
            {
              hold_set = false;
              n_held   = 0;
              callbacks.restart_cycle_detection();
            }
          const unsigned int n_changed =
            hold_set                   ? 0u :
            one_change_per_equilibrium ? callbacks.update_one_point() :
                                         callbacks.update_active_set();
          if (one_change_per_equilibrium && n_changed > 0)
            hold_set = true;
          if (one_change_per_equilibrium && n_changed > 0 &&
              callbacks.revisits_held_set && callbacks.revisits_held_set())
            early_changes = false;
          // A semismooth iteration that still changes the set after
          // n_semismooth iterations wanders among sets without repeating
          // one: from here, too, one change per equilibrium.
          if (callbacks.restart_cycle_detection &&
              !one_change_per_equilibrium && it >= n_semismooth &&
              n_changed > 0)
            {
              verbose << "    Active set still changing: from here one "
                         "change per equilibrium"
                      << std::endl;
              one_change_per_equilibrium = true;
              one_change_since           = it;
              hold_set                   = true;
            }
          statistics.n_iterations = it;
          statistics.residuals.push_back(residual);
          statistics.active_set_changes.push_back(n_changed);

          verbose << "    Newton " << std::setw(2) << it
                  << ": equilibrium residual "
                  << IO::Console::format(residual.equilibrium)
                  << ", complementarity residual "
                  << IO::Console::format(residual.complementarity)
                  << ", increment " << IO::Console::format(residual.increment)
                  << ", active set changes " << n_changed << std::endl;

          if (!std::isfinite(residual.equilibrium) ||
              !std::isfinite(residual.complementarity))
            {
              statistics.failure  = "non-finite residual";
              statistics.diverged = true;
              return finish();
            }
          if (parameters.divergence_bound > 0. &&
              residual.equilibrium > parameters.divergence_bound)
            {
              statistics.failure =
                "the iteration diverges (equilibrium residual " +
                IO::Console::format(residual.equilibrium) +
                " above the divergence bound " +
                IO::Console::format(parameters.divergence_bound) + ")";
              statistics.diverged = true;
              return finish();
            }
          // The multipliers of an augmented Lagrangian follow an iterate
          // near its equilibrium; the iteration goes on with the new ones.
          if (callbacks.update_multipliers && n_changed == 0 &&
              residual.complementarity < multiplier_update_bound &&
              residual.equilibrium < multiplier_update_bound &&
              callbacks.update_multipliers())
            {
              ++statistics.n_augmentations;
              verbose << "    Multipliers updated ("
                      << statistics.n_augmentations << ")" << std::endl;
              continue;
            }
          if (n_changed == 0 && residual.complementarity < parameters.tolerance)
            {
              if (residual.equilibrium < parameters.tolerance)
                {
                  statistics.converged = true;
                  return finish();
                }
              // The first iteration's step carries the load increment and
              // says nothing about round-off, nor does the step of an
              // inexact solve.
              if (it > 1 && !inexact_solve &&
                  residual.increment < parameters.step_tolerance)
                {
                  // A vanishing step with a large residual means that the
                  // residual and the linearisation disagree: no round-off
                  // explains it, and the state is not accepted. A residual
                  // that the last step still halved is no such
                  // disagreement: a stiff system (a stiff penalty, a bent
                  // strip) makes small steps that still remove most of the
                  // residual; the iteration goes on.
                  const std::size_t n_residuals = statistics.residuals.size();
                  const bool        still_falling =
                    n_residuals >= 2 &&
                    residual.equilibrium <
                      0.5 * statistics.residuals[n_residuals - 2].equilibrium;
                  if (residual.equilibrium >
                        parameters.step_test_residual_bound &&
                      still_falling)
                    continue;
                  if (residual.equilibrium >
                      parameters.step_test_residual_bound)
                    {
                      statistics.failure =
                        "the Newton step vanishes but the equilibrium "
                        "residual stays at " +
                        IO::Console::format(residual.equilibrium) +
                        " (residual and linearisation disagree)";
                      return finish();
                    }
                  verbose << "    Newton step below the step tolerance: the "
                             "equilibrium residual is at round-off level"
                          << std::endl;
                  statistics.converged         = true;
                  statistics.converged_on_step = true;
                  return finish();
                }
            }
          // One change per equilibrium whose set stays the same from one
          // iteration to the next for n_stagnation iterations, that reach
          // no equilibrium and do not halve the equilibrium residual, makes
          // no progress: the changes made inside the iterations (active-set
          // solves of each linearisation) trade the same sets back and
          // forth, and the iterates repeat in pairs without end.
          if (one_change_per_equilibrium &&
              it >= one_change_since + n_stagnation &&
              it >= last_equilibrium + n_stagnation)
            {
              const auto  &residuals = statistics.residuals;
              const double before =
                residuals[it - 1 - n_stagnation].equilibrium;
              double best    = std::numeric_limits<double>::infinity();
              bool   changed = false;
              for (unsigned int k = it - n_stagnation; k < it; ++k)
                {
                  best    = std::min(best, residuals[k].equilibrium);
                  changed = changed || statistics.active_set_changes[k] > 0;
                }
              if (!changed && best > 0.5 * before)
                {
                  statistics.failure =
                    "the iteration stagnates (one change per equilibrium, "
                    "no change of the set between iterations, and the "
                    "equilibrium residual stays above " +
                    IO::Console::format(0.5 * before) + " for " +
                    std::to_string(n_stagnation) + " iterations)";
                  return finish();
                }
            }
          // Iterates that repeat themselves while the set changes, both
          // residuals within 1e-3 of those p iterations before for p
          // iterations in a row (p from 2 to n_stagnation), run in a cycle
          // that the set history does not see (holds released by a growing
          // residual, changes made inside the iterations): they reach no
          // equilibrium, and the step fails instead of running to its
          // iteration limit.
          if (one_change_per_equilibrium)
            {
              const auto &residuals = statistics.residuals;
              const auto  close     = [](const double a, const double b) {
                return std::abs(a - b) <=
                       1e-3 * std::max(std::abs(a), std::abs(b));
              };
              for (unsigned int p = 2; p <= n_stagnation; ++p)
                {
                  if (it < one_change_since + 2 * p)
                    break;
                  bool repeats = true, changed = false;
                  for (unsigned int k = it - p; k < it && repeats; ++k)
                    repeats = close(residuals[k].equilibrium,
                                    residuals[k - p].equilibrium) &&
                              close(residuals[k].complementarity,
                                    residuals[k - p].complementarity);
                  for (unsigned int k = it - 2 * p; k < it; ++k)
                    changed = changed || statistics.active_set_changes[k] > 0;
                  if (repeats && changed)
                    {
                      statistics.failure =
                        "the iteration repeats itself every " +
                        std::to_string(p) +
                        " iterations while the set changes (equilibrium "
                        "residual " +
                        IO::Console::format(residuals[it - 1].equilibrium) +
                        ", complementarity residual " +
                        IO::Console::format(residuals[it - 1].complementarity) +
                        "): no equilibrium is reached";
                      return finish();
                    }
                }
            }
          // One change per equilibrium that reaches no equilibrium in
          // n_wander iterations, and whose Newton residual (the larger of
          // the two) stays above half its smallest value of the n_wander
          // iterations before, wanders among sets without approaching a
          // solution (iterates that nearly repeat, drifting by a few
          // percent per period, which the test above does not see): the
          // step fails instead of running to its iteration limit.
          if (one_change_per_equilibrium &&
              it >= one_change_since + 2 * n_wander &&
              it >= last_equilibrium + n_wander)
            {
              const auto &residuals = statistics.residuals;
              const auto  newton    = [&residuals](const unsigned int k) {
                return std::max(residuals[k].equilibrium,
                                residuals[k].complementarity);
              };
              double recent = std::numeric_limits<double>::infinity();
              double before = recent;
              for (unsigned int k = it - n_wander; k < it; ++k)
                recent = std::min(recent, newton(k));
              for (unsigned int k = it - 2 * n_wander; k < it - n_wander; ++k)
                before = std::min(before, newton(k));
              if (recent > 0.5 * before)
                {
                  statistics.failure =
                    "the iteration wanders (one change per equilibrium, no "
                    "equilibrium in " +
                    std::to_string(n_wander) +
                    " iterations, and the smallest residual in them, " +
                    IO::Console::format(recent) + ", is not half of the " +
                    IO::Console::format(before) + " of the " +
                    std::to_string(n_wander) + " before)";
                  return finish();
                }
            }
          if (!hold_set && callbacks.is_cycling())
            {
              // An inexact iterate may revisit a set; exact ones decide.
              if (inexact_solve)
                {
                  inexact = false;
                  continue;
                }
              if (callbacks.restart_cycle_detection)
                {
                  verbose << "    Active set cycles: from here one change "
                             "per equilibrium"
                          << std::endl;
                  one_change_per_equilibrium = true;
                  one_change_since           = it;
                  hold_set                   = true;
                  continue;
                }
              statistics.failure = "the active set cycles";
              return finish();
            }
        }
      statistics.failure = "no convergence in " +
                           std::to_string(parameters.max_iterations) +
                           " iterations";
      return finish();
    }
  } // namespace Solvers
} // namespace Common
