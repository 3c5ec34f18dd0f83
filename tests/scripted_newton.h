/*
 * Scripted residual histories for the tests of the semismooth Newton loop
 * (tests/common/newton_solver_*): each iteration plays the next entry of a
 * script.
 */
#ifndef tests_scripted_newton_h
#define tests_scripted_newton_h

#include <common/solvers/newton_solver.h>

#include <algorithm>
#include <vector>

namespace ScriptedNewton
{
  /** One scripted iteration: the step the solve returns, the residuals of
   * the updated state and the points the active-set update changes. */
  struct Iteration
  {
    double       step;
    double       equilibrium;
    double       complementarity;
    unsigned int n_changed;
  };

  /** Callbacks that play @p script, its last entry repeating when it runs
   * out; @p k counts the active-set updates made so far (the entry played
   * is script[k]). The set never cycles. */
  inline Common::Solvers::NewtonCallbacks
  callbacks(const std::vector<Iteration> &script, unsigned int &k)
  {
    const auto entry = [&script, &k]() -> const Iteration & {
      return script[std::min<std::size_t>(k, script.size() - 1)];
    };
    Common::Solvers::NewtonCallbacks callbacks;
    callbacks.assemble_solve_and_update = [entry](const double) {
      return entry().step;
    };
    callbacks.evaluate_residual = [entry]() {
      Common::Solvers::NewtonResidual r;
      r.equilibrium     = entry().equilibrium;
      r.complementarity = entry().complementarity;
      return r;
    };
    callbacks.update_active_set = [entry, &k]() {
      const unsigned int n = entry().n_changed;
      ++k;
      return n;
    };
    callbacks.is_cycling = []() {
      return false;
    };
    return callbacks;
  }
} // namespace ScriptedNewton

#endif
