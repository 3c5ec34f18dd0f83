#include <common/solvers/load_stepping.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace Common
{
  namespace Solvers
  {
    using namespace dealii;

    void
    LoadSteppingParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      {
        prm.declare_entry("Number of load steps",
                          "1",
                          Patterns::Integer(1),
                          "Equal load increments from zero to the full "
                          "load.");
        prm.declare_entry("Minimum load increment",
                          "1e-4",
                          Patterns::Double(0.),
                          "Smallest increment, as a fraction of the full "
                          "load, that cutbacks may reach before the run "
                          "stops with an error. Dimensionless.");
      }
      prm.leave_subsection();
    }



    void
    LoadSteppingParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      {
        n_steps       = prm.get_integer("Number of load steps");
        min_increment = prm.get_double("Minimum load increment");
      }
      prm.leave_subsection();
      AssertThrow(min_increment > 0. && min_increment <= 1.,
                  ExcMessage("Load stepping: 'Minimum load increment' must "
                             "lie in (0, 1]."));
    }



    LoadSteppingStatistics
    run_load_stepping(const LoadSteppingParameters &parameters,
                      const LoadStepCallbacks      &callbacks,
                      IO::Console                  &console)
    {
      LoadSteppingStatistics statistics;
      const double           nominal   = 1. / parameters.n_steps;
      double                 increment = nominal;
      double                 load      = 0.;
      unsigned int           step      = 0;
      while (load < 1. - 1e-12)
        {
          const double           target = std::min(1., load + increment);
          const NewtonStatistics newton = callbacks.solve(target);
          if (newton.converged)
            {
              ++step;
              load = target;
              statistics.load_factors.push_back(load);
              statistics.newton_iterations.push_back(newton.n_iterations);
              statistics.n_converged_on_step += newton.converged_on_step;
              callbacks.accept(step, load, newton);
              // Return to the nominal increment once a reduced one worked.
              increment = std::min(nominal, 2. * increment);
            }
          else
            {
              callbacks.reject();
              ++statistics.n_cutbacks;
              increment *= 0.5;
              AssertThrow(increment >= parameters.min_increment * (1 - 1e-12),
                          ExcMessage("Newton did not converge at load factor " +
                                     IO::Console::format(target) + " (" +
                                     newton.failure +
                                     ") and the minimum load increment was "
                                     "reached."));
              console.stream()
                << "  Newton did not converge at load factor "
                << IO::Console::format(target) << " (" << newton.failure
                << "); cutting the increment back to "
                << IO::Console::format(increment) << std::endl;
            }
        }
      return statistics;
    }
  } // namespace Solvers
} // namespace Common
