/*
 * The semismooth Newton loop (common/solvers/newton_solver.h) on scripted
 * residual histories: it converges on the residual tolerance; it converges
 * on the step test when the equilibrium residual stalls above its tolerance
 * at round-off while the step is negligible, and flags it, but fails when
 * the residual stays far above round-off (bound 1e-6) as the step vanishes
 * and the last step did not halve it;
 * it never takes the first iteration's step (which carries the load
 * increment) as a convergence sign; it does not converge on a small step
 * while the active set changes or the complementarity residual is large,
 * nor when the step stays above its tolerance or the test is disabled; it
 * stops on a non-finite residual, on a residual above the divergence bound
 * (and only there), and on a cycling active set, unless the
 * problem offers the one-change-per-equilibrium mode: then the cycling set
 * is held until its equilibrium residual falls below the complementarity
 * residual or the tolerance, and each later update changes one point from
 * there until none changes; a held set whose equilibrium residual stays
 * above both stays held; once a change leads back to a set held before,
 * sets are held to the tolerance, and the loop stops when an equilibrium
 * returns to the one before the last (two sets trading places) or
 * reaches an equilibrium for the third time (a cycle of more sets), or
 * when 8 iterations of one change per equilibrium keep their set, reach
 * no equilibrium and do not halve the equilibrium residual (held iterates
 * that repeat in pairs), but not while the set changes, unless the
 * iterates repeat themselves (both residuals to 1e-3 over a period of 2
 * to 8 iterations) while it does; an iterate
 * whose step vanishes is at equilibrium right after a change, too (a
 * change that moves nothing), so that such changes at a round-off floor
 * above the tolerance stop the loop as an alternation. With
 * inexact solves ('Linear tolerance factor' 0.1) the first iteration is
 * solved fully and later ones to 0.1 times the previous residual; an
 * active set that returns to an earlier one after an inexact solve
 * switches the step to full solves instead of failing; the step test
 * applies once the linear tolerance is below the Newton tolerance.
 */

#include <common/solvers/newton_solver.h>

#include "../scripted_newton.h"
#include "../tests.h"

#include <deal.II/base/conditional_ostream.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace dealii;
using namespace Common::Solvers;

namespace
{
  using ScriptedNewton::Iteration;

  /** Run the loop on a script; the last entry repeats when it runs out. */
  NewtonStatistics
  run(const std::vector<Iteration> &script,
      const double                  step_tolerance,
      const unsigned int            cycling_from      = 0,
      const double                  factor            = 0.,
      std::vector<double>          *linear_tolerances = nullptr,
      const double                  divergence_bound  = 0.)
  {
    NonlinearSolverParameters parameters;
    parameters.max_iterations          = 8;
    parameters.tolerance               = 1e-10;
    parameters.step_tolerance          = step_tolerance;
    parameters.linear_tolerance_factor = factor;
    parameters.divergence_bound        = divergence_bound;

    unsigned int    k         = 0;
    NewtonCallbacks callbacks = ScriptedNewton::callbacks(script, k);
    if (linear_tolerances)
      {
        const auto play = callbacks.assemble_solve_and_update;
        callbacks.assemble_solve_and_update =
          [play, linear_tolerances](const double tolerance) {
            linear_tolerances->push_back(tolerance);
            return play(tolerance);
          };
      }
    // After iteration k, k sets have been updated.
    callbacks.is_cycling = [&]() {
      return cycling_from > 0 && k >= cycling_from;
    };

    ConditionalOStream quiet(std::cout, false);
    return solve_newton(parameters, callbacks, quiet);
  }

  /** A problem whose active set cycles at the first iteration and that
   * offers the one-change-per-equilibrium mode: each call is logged. The
   * equilibrium residual follows @p equilibrium (the last entry repeats);
   * the one-point updates change @p one_point_changes[k] points in turn.
   * The complementarity residual is 1e-3 until the changes run out, then
   * 0; or, if @p complementarity is given, its entry for the number of
   * one-point updates made so far (the last entry repeats). If
   * @p revisits is given, the problem reports whether the k-th one-point
   * update led back to a set held before (the last entry repeats).
   * @p max_iterations bounds the loop. Every step after the first is
   * @p step, judged with the step tolerance @p step_tolerance. */
  NewtonStatistics
  run_held(const std::vector<double>       &equilibrium,
           const std::vector<unsigned int> &one_point_changes,
           std::vector<std::string>        &calls,
           const std::vector<double>       &complementarity = {},
           const std::vector<bool>         &revisits        = {},
           const unsigned int               max_iterations  = 12,
           const double                     step            = 1e-3,
           const double                     step_tolerance  = 0.)
  {
    NonlinearSolverParameters parameters;
    parameters.max_iterations = max_iterations;
    parameters.tolerance      = 1e-10;
    parameters.step_tolerance = step_tolerance;

    unsigned int    it = 0, one_point = 0;
    bool            cycling = false;
    NewtonCallbacks callbacks;
    callbacks.assemble_solve_and_update = [&](const double) {
      ++it;
      return it == 1 ? 1e-3 : step;
    };
    callbacks.evaluate_residual = [&]() {
      NewtonResidual r;
      r.equilibrium =
        equilibrium[std::min<std::size_t>(it - 1, equilibrium.size() - 1)];
      r.complementarity =
        !complementarity.empty() ?
          complementarity[std::min<std::size_t>(one_point,
                                                complementarity.size() - 1)] :
        one_point < one_point_changes.size() ? 1e-3 :
                                               0.;
      return r;
    };
    callbacks.update_active_set = [&]() {
      calls.push_back("update");
      cycling = true;
      return 0u;
    };
    callbacks.is_cycling = [&]() {
      return cycling;
    };
    callbacks.restart_cycle_detection = [&]() {
      calls.push_back("restart");
      cycling = false;
    };
    callbacks.update_one_point = [&]() {
      const unsigned int n = one_point < one_point_changes.size() ?
                               one_point_changes[one_point++] :
                               0u;
      calls.push_back("one point (" + std::to_string(n) + ")");
      return n;
    };
    if (!revisits.empty())
      callbacks.revisits_held_set = [&]() {
        const bool back =
          revisits[std::min<std::size_t>(one_point - 1, revisits.size() - 1)];
        if (back)
          calls.push_back("back to a held set");
        return back;
      };
    ConditionalOStream quiet(std::cout, false);
    return solve_newton(parameters, callbacks, quiet);
  }

  void
  report(const std::string &name, const NewtonStatistics &s)
  {
    deallog << name << ": converged " << s.converged << ", on the step test "
            << s.converged_on_step << ", iterations " << s.n_iterations
            << (s.failure.empty() ? "" : ", failure: " + s.failure)
            << std::endl;
  }
} // namespace

int
main()
{
  initlog();
  const double nan = std::numeric_limits<double>::quiet_NaN();

  // Residual below tolerance at the third iteration: converges there.
  report("residual test",
         run({{1., 1e-3, 1e-1, 4}, {1e-2, 1e-7, 1e-3, 1}, {1e-5, 1e-13, 0, 0}},
             1e-8));
  // Round-off floor 7e-10 once the active set settles (the rigid-punch
  // case): converges on the step test at iteration 3, flagged.
  report("round-off floor",
         run({{1., 1e-9, 1e-1, 10}, {5e-3, 7e-10, 0, 0}, {5e-10, 7e-10, 0, 0}},
             1e-8));
  // A tiny first step (a small load increment) is not convergence: the
  // second one is.
  report("tiny first step",
         run({{1e-12, 7e-10, 0, 0}, {1e-13, 7e-10, 0, 0}}, 1e-8));
  // Small steps while the active set still changes: no convergence.
  report("active set changes",
         run({{1., 1e-9, 1e-1, 3}, {1e-12, 7e-10, 1e-3, 2}}, 1e-8));
  // Small steps with a large complementarity residual: no convergence.
  report("complementarity open",
         run({{1., 1e-9, 1e-1, 3}, {1e-12, 7e-10, 1e-3, 0}}, 1e-8));
  // A stalled residual with steps above the step tolerance (a genuinely
  // stuck iteration): no convergence.
  report("stalled, steps large",
         run({{1., 1e-3, 1e-1, 3}, {1e-6, 1e-6, 0, 0}}, 1e-8));
  // A vanishing step with a residual far above round-off (residual and
  // linearisation disagree): no convergence, a failure that says so.
  report("residual inconsistent",
         run({{1., 1e-3, 1e-1, 3}, {1e-12, 1e-3, 0, 0}}, 1e-8));
  // Vanishing steps that still remove most of the residual (the bent
  // strip: 2.6e-3, 3.7e-4, 1.7e-5, 1.8e-6, by 0.106 at the step test's
  // first chance) are no disagreement: the iteration goes on and meets
  // the tolerance at iteration 6. A vanishing step that lowers the
  // residual by 0.6 only fails at once (iteration 3).
  report("small steps, residual halved",
         run({{1., 2.3e-2, 1e-1, 1},
              {5e-4, 2.6e-3, 0, 0},
              {4e-6, 3.7e-4, 0, 0},
              {1.4e-7, 1.7e-5, 0, 0},
              {5.7e-9, 1.8e-6, 0, 0},
              {1.2e-9, 2e-11, 0, 0}},
             1e-8));
  report("small steps, residual not halved",
         run({{1., 1e-2, 1e-1, 3}, {1e-3, 1e-3, 0, 0}, {1e-9, 6e-4, 0, 0}},
             1e-8));
  // The step test disabled: the round-off floor is not accepted.
  report("step test disabled",
         run({{1., 1e-9, 1e-1, 10}, {5e-3, 7e-10, 0, 0}, {5e-10, 7e-10, 0, 0}},
             0.));
  // A non-finite residual stops at once, even with a tiny step.
  report("non-finite", run({{1., 1e-3, 1e-1, 3}, {1e-12, nan, 0, 0}}, 1e-8));
  // A residual above the divergence bound (1e3) stops at once; up to it
  // the iteration goes on and converges; without a bound the diverging
  // history runs out of iterations.
  report("above the divergence bound",
         run({{1., 5., 1e-1, 3}, {0.5, 2e3, 1e-1, 2}, {1e-5, 1e-13, 0, 0}},
             1e-8,
             0,
             0.,
             nullptr,
             1e3));
  report("at the divergence bound",
         run({{1., 5., 1e-1, 3}, {0.5, 1e3, 1e-1, 2}, {1e-5, 1e-13, 0, 0}},
             1e-8,
             0,
             0.,
             nullptr,
             1e3));
  report("diverging, no bound",
         run({{1., 5., 1e-1, 3}, {0.5, 2e3, 1e-1, 2}, {1., 1e6, 0, 1}}, 1e-8));
  // A cycling active set stops the loop.
  report("cycling", run({{1., 1e-3, 1e-1, 3}}, 1e-8, 1));
  // With the one-change-per-equilibrium mode a cycle holds the set: no
  // update until the equilibrium residual (1e-6 at iteration 2) falls
  // below the complementarity residual (1e-3), then the history restarts
  // and one point changes; held again until the same holds (iteration 3),
  // one more change; with the changes made the complementarity residual
  // is met, and the set is held until the equilibrium residual meets the
  // tolerance (iteration 5), where no point changes.
  {
    std::vector<std::string> calls;
    report("cycling, one change per equilibrium",
           run_held({1e-3, 1e-6, 1e-12, 1e-5, 1e-12, 1e-5, 1e-12},
                    {1, 1},
                    calls));
    for (const auto &call : calls)
      deallog << "  " << call << std::endl;
  }
  // A held set whose equilibrium residual stays above its complementarity
  // residual and the tolerance (and does not grow) stays held, with no
  // update; its residual does not halve in the 8 iterations after the
  // cycle (iteration 1), and the loop stops at iteration 9 as stagnating
  // instead of running to its limit (12).
  {
    std::vector<std::string> calls;
    report("cycling, equilibrium not reached",
           run_held({1e-3, 2e-3}, {1}, calls));
    for (const auto &call : calls)
      deallog << "  " << call << std::endl;
  }
  // Held iterates that repeat in pairs (the changes made inside each
  // iteration trade two sets back and forth): the residual falls until
  // iteration 5, then alternates between 6.26e-2 and 6.27e-2. Iteration 9
  // is still below half of iteration 1's; iteration 10 is not below half
  // of iteration 2's, and the loop stops there.
  {
    std::vector<std::string> calls;
    std::vector<double> equilibrium{3.6e-1, 8.9e-2, 6.6e-2, 6.4e-2, 6.26e-2};
    for (unsigned int it = 6; it <= 30; ++it)
      equilibrium.push_back(it % 2 == 0 ? 6.27e-2 : 6.26e-2);
    report("held iterates in pairs",
           run_held(equilibrium, {1}, calls, {1e-2}, {}, 30));
  }
  // A residual that does not halve while the set changes at every
  // iteration (each held iterate's equilibrium residual, 2e-3, below the
  // complementarity residual, 1e-2 less 1 % per change, decides a change)
  // is no stagnation: it runs to the limit (20). The same with a
  // complementarity residual that every change leaves where it was: the
  // iterates repeat themselves, and the loop stops at iteration 5, where
  // iterations 4 and 5 repeat 2 and 3.
  {
    std::vector<std::string> calls;
    std::vector<double>      complementarity;
    for (unsigned int k = 0; k <= 20; ++k)
      complementarity.push_back(1e-2 * (1. - 0.01 * k));
    report("held sets changing, residual not halving",
           run_held({1e-3, 2e-3},
                    std::vector<unsigned int>(20, 1),
                    calls,
                    complementarity,
                    {},
                    20));
    calls.clear();
    report("held sets changing, iterates repeating",
           run_held({1e-3, 2e-3},
                    std::vector<unsigned int>(20, 1),
                    calls,
                    {1e-2},
                    {},
                    20));
  }
  // Sets changing at every iteration with no equilibrium, given 60
  // iterations, both residuals falling by the same rate per iteration
  // (the equilibrium residual a fifth of the complementarity residual,
  // which decides each change): at 1 % the Newton residual does not halve
  // in 16 iterations, and the loop stops at iteration 33, when the
  // smallest residual of iterations 17 to 32 is compared with that of 1 to
  // 16 (one change per equilibrium from iteration 1). At 5 % it halves in
  // 14, and the iteration runs to the limit (60).
  for (const auto &[rate, name] :
       std::vector<std::pair<double, std::string>>{{0.01, "1 %"},
                                                   {0.05, "5 %"}})
    {
      std::vector<std::string> calls;
      std::vector<double>      complementarity{1e-2}, equilibrium{1e-3};
      for (unsigned int k = 1; k <= 60; ++k)
        {
          complementarity.push_back(complementarity.back() * (1. - rate));
          equilibrium.push_back(0.2 * complementarity.back());
        }
      report("held sets changing, no equilibrium, residual falling " + name +
               " per change",
             run_held(equilibrium,
                      std::vector<unsigned int>(60, 1),
                      calls,
                      complementarity,
                      {},
                      60));
    }
  // A held set that converges slowly (its residual falls by 0.9 per
  // iteration, halving in fewer than 8) is no stagnation: it runs to the
  // limit (20). At 0.95 per iteration (0.66 in 8) it stops at iteration
  // 10, 8 iterations after the last change (iteration 2).
  for (const auto &[rate, name] :
       std::vector<std::pair<double, std::string>>{{0.9, "0.9"},
                                                   {0.95, "0.95"}})
    {
      std::vector<std::string> calls;
      std::vector<double>      equilibrium{1e-3};
      for (unsigned int it = 2; it <= 20; ++it)
        equilibrium.push_back(equilibrium.back() * rate);
      report("held set converging by " + name,
             run_held(equilibrium, {1}, calls, {1e-2}, {}, 20));
    }

  // Two sets that trade places at every equilibrium (a node tensile when
  // closed and penetrating when open): the first change (iteration 2, at
  // an equilibrium) leads to a new set, which decides at iteration 3
  // before its equilibrium; that change leads back to the first set, and
  // from then on every set is held to the tolerance. The equilibrium of
  // iteration 6 returns to the complementarity residual of the one before
  // the last (iteration 2), and the loop stops there with a failure that
  // says so.
  {
    std::vector<std::string> calls;
    report("alternating equilibria",
           run_held({1e-3, 1e-12, 1e-5, 1e-12, 1e-5, 1e-12, 1e-5, 1e-12},
                    {1, 1, 1, 1, 1, 1},
                    calls,
                    {3.848e-4, 5e-4, 3.925e-4, 3.848e-4},
                    {false, true}));
    for (const auto &call : calls)
      deallog << "  " << call << std::endl;
  }

  // Changes that move nothing (points with neither pressure nor gap) at
  // a round-off floor just above the tolerance (1.2e-10, steps of 1e-14):
  // each iterate after a change is at equilibrium, and its
  // complementarity residual (0.1, the violation that no change removes)
  // decides the next change at once. Compared as equilibria, the third
  // one returns to the one before the last, and the loop stops at
  // iteration 4 instead of running to its limit (30).
  {
    std::vector<std::string> calls;
    report("changes that move nothing, at round-off",
           run_held({1e-3, 1.2e-10},
                    std::vector<unsigned int>(30, 1),
                    calls,
                    {1e-1},
                    {},
                    30,
                    1e-14,
                    1e-8));
    for (const auto &call : calls)
      deallog << "  " << call << std::endl;
  }

  // Three sets in a cycle (the one-change rule leads A to B, B to C and
  // C back to A, as the wrapped nodes of a bent strip can): held to the
  // tolerance from the second change on, the equilibria of iterations 2,
  // 4, 6, 8, 10 and 12 have the complementarity residuals a, b, c, a, b,
  // c. No two consecutive ones repeat the one before the last; the loop
  // stops at iteration 14, where a is reached for the third time, instead
  // of running to its limit (16).
  {
    std::vector<std::string> calls;
    std::vector<double>      equilibrium{1e-3};
    for (unsigned int it = 2; it <= 16; ++it)
      equilibrium.push_back(it % 2 == 0 ? 1e-12 : 1e-5);
    report("three equilibria in a cycle",
           run_held(equilibrium,
                    {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
                    calls,
                    {1e-4, 5e-4, 2e-4, 3e-4, 1e-4, 2e-4, 3e-4, 1e-4},
                    {false, true},
                    16));
    deallog << "  calls " << calls.size() << std::endl;
  }

  // Inexact Newton with factor 0.1: iteration 1 solved fully, later ones
  // to 0.1 times the larger residual of the previous iteration.
  std::vector<double> tolerances;
  report("inexact",
         run({{1., 1e-3, 1e-1, 4}, {1e-2, 1e-7, 1e-3, 1}, {1e-5, 1e-13, 0, 0}},
             1e-8,
             0,
             0.1,
             &tolerances));
  for (const double t : tolerances)
    deallog << "  linear tolerance " << t << std::endl;
  // A set that returns to an earlier one after an inexact solve is not
  // cycling: the step goes on with full solves, and fails only when a
  // fully solved iterate cycles.
  tolerances.clear();
  report("inexact, cycling",
         run({{1., 1e-3, 1e-1, 4}}, 1e-8, 2, 0.1, &tolerances));
  for (const double t : tolerances)
    deallog << "  linear tolerance " << t << std::endl;
  // The round-off floor with inexact solves: once the linear tolerance
  // falls below the Newton tolerance the step test applies again.
  report("round-off floor, inexact",
         run({{1., 1e-9, 1e-1, 10}, {5e-3, 7e-10, 0, 0}, {5e-10, 7e-10, 0, 0}},
             1e-8,
             0,
             0.1));
}
