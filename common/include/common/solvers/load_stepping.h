/**
 * @file load_stepping.h
 * Quasi-static load stepping from load factor 0 to 1 with automatic
 * cutback: a step whose Newton solve fails is rejected (the problem
 * restores its last accepted state) and retried with half the increment,
 * down to a minimum. Sees only callbacks.
 */
#ifndef common_solvers_load_stepping_h
#define common_solvers_load_stepping_h

#include <common/io/console.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <vector>

namespace Common
{
  namespace Solvers
  {
    /**
     * @brief Parameters of subsection "Load stepping".
     */
    struct LoadSteppingParameters
    {
      /** @brief Declare the entries of subsection "Load stepping". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read the entries of subsection "Load stepping". */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      unsigned int n_steps;
      /** Smallest load increment after cutbacks (fraction of the full
       * load). */
      double min_increment;
    };

    /**
     * @brief What the load stepping needs from a problem.
     */
    struct LoadStepCallbacks
    {
      /** Solve at the given load factor, starting from the last accepted
       * state. */
      std::function<NewtonStatistics(const double load_factor)> solve;
      /** Commit the state of a converged step. */
      std::function<void(const unsigned int      step,
                         const double            load_factor,
                         const NewtonStatistics &statistics)>
        accept;
      /** Restore the last accepted state. */
      std::function<void()> reject;
    };

    /**
     * @brief Record of the accepted steps.
     */
    struct LoadSteppingStatistics
    {
      std::vector<double>       load_factors;
      std::vector<unsigned int> newton_iterations;
      unsigned int              n_cutbacks = 0;
      /** Accepted steps whose Newton iteration converged on the step test
       * (equilibrium residual at round-off above its tolerance). */
      unsigned int n_converged_on_step = 0;
    };

    /**
     * @brief Step the load factor from 0 to 1. Throws with a one-line
     * message when the minimum increment fails.
     */
    LoadSteppingStatistics
    run_load_stepping(const LoadSteppingParameters &parameters,
                      const LoadStepCallbacks      &callbacks,
                      IO::Console                  &console);
  } // namespace Solvers
} // namespace Common

#endif
