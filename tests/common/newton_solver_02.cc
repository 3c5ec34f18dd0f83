/*
 * The semismooth Newton loop (common/solvers/newton_solver.h) with the
 * multipliers of an augmented Lagrangian updated within the iteration
 * (NewtonCallbacks::update_multipliers), on scripted residual histories:
 * the update is offered only to an iterate whose active set did not change
 * and whose equilibrium and complementarity residuals are both below
 * multiplier_update_bound (1e-6); an iterate whose multipliers changed is
 * not accepted even with residuals below the tolerance, and the iteration
 * goes on; a state converges, on the residual or the step test, once the
 * multipliers need no update; the updates are counted in n_augmentations;
 * multipliers that never settle leave the step unconverged at the
 * iteration limit. Without the callback the loop converges where it did
 * before.
 */

#include <common/solvers/newton_solver.h>

#include "../scripted_newton.h"
#include "../tests.h"

#include <deal.II/base/conditional_ostream.h>

#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace Common::Solvers;

namespace
{
  using ScriptedNewton::Iteration;

  /** Run the loop on a script (the last entry repeats); the multipliers
   * change at the first @p n_updates calls of the callback, which each
   * log the iteration they are made at; no callback if @p n_updates is
   * negative. */
  NewtonStatistics
  run(const std::vector<Iteration> &script,
      const int                     n_updates,
      std::vector<std::string>     &calls,
      const double                  step_tolerance = 0.)
  {
    NonlinearSolverParameters parameters;
    parameters.max_iterations = 8;
    parameters.tolerance      = 1e-10;
    parameters.step_tolerance = step_tolerance;

    unsigned int    k = 0, n_calls = 0;
    NewtonCallbacks callbacks = ScriptedNewton::callbacks(script, k);
    if (n_updates >= 0)
      callbacks.update_multipliers = [&]() {
        const bool changed = n_calls < static_cast<unsigned int>(n_updates);
        ++n_calls;
        calls.push_back("multipliers at iteration " + std::to_string(k) +
                        (changed ? ": changed" : ": unchanged"));
        return changed;
      };
    ConditionalOStream quiet(std::cout, false);
    return solve_newton(parameters, callbacks, quiet);
  }

  void
  report(const std::string              &name,
         const NewtonStatistics         &s,
         const std::vector<std::string> &calls)
  {
    deallog << name << ": converged " << s.converged << ", on the step test "
            << s.converged_on_step << ", iterations " << s.n_iterations
            << ", multiplier updates " << s.n_augmentations
            << (s.failure.empty() ? "" : ", failure: " + s.failure)
            << std::endl;
    for (const auto &call : calls)
      deallog << "  " << call << std::endl;
  }
} // namespace

int
main()
{
  initlog();

  // Iteration 3 is near its equilibrium with the set settled: the
  // multipliers change there, and the residual of iteration 4 carries
  // the change (above the bound: no call). Iteration 5 meets the
  // tolerance, but its multipliers change again: not accepted.
  // Iteration 6 needs no update and converges.
  const std::vector<Iteration> settling = {{1., 1., 1e-1, 3},
                                           {1e-2, 1e-3, 1e-4, 1},
                                           {1e-4, 1e-7, 1e-8, 0},
                                           {1e-3, 2e-6, 1e-7, 0},
                                           {1e-6, 1e-11, 1e-12, 0},
                                           {1e-9, 1e-13, 0., 0}};
  {
    std::vector<std::string> calls;
    report("two updates within the solve", run(settling, 2, calls), calls);
  }
  // Without the callback the same script converges at iteration 5.
  {
    std::vector<std::string> calls;
    report("no callback", run(settling, -1, calls), calls);
  }
  // Residuals below the bound while the set still changes: no call until
  // the set settles (iteration 4), which converges with no update.
  {
    std::vector<std::string> calls;
    report("set still changing",
           run({{1., 1., 1e-1, 3},
                {1e-2, 1e-7, 1e-8, 1},
                {1e-3, 1e-8, 1e-9, 1},
                {1e-6, 1e-12, 0., 0}},
               0,
               calls),
           calls);
  }
  // A residual at a round-off floor above the tolerance: the step test
  // accepts the state only once the multipliers need no update.
  {
    std::vector<std::string> calls;
    report("round-off floor",
           run({{1., 1., 1e-1, 3},
                {1e-2, 1e-7, 1e-8, 0},
                {1e-3, 2e-10, 1e-9, 0},
                {1e-10, 1.6e-10, 1e-12, 0}},
               1,
               calls,
               1e-8),
           calls);
  }
  // Multipliers that change at every call: the step does not converge.
  {
    std::vector<std::string> calls;
    const auto               s = run(settling, 100, calls);
    report("multipliers never settle", s, {});
    deallog << "  calls " << calls.size() << std::endl;
  }
}
