/*
 * The convergence-rate check of the Newton tests (tests/common): the
 * residual ratios log(r_k+1)/log(r_k) of the iterations after the active
 * set has settled, with r = max(equilibrium, complementarity) residual.
 */
#ifndef tests_newton_rates_h
#define tests_newton_rates_h

#include <common/solvers/newton_solver.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace NewtonRates
{
  /** The ratios and whether they show quadratic convergence. */
  struct Rates
  {
    std::vector<double> ratios;
    bool                quadratic = false;

    /** The ratios with two digits, separated by spaces. */
    std::string
    to_string() const
    {
      std::ostringstream s;
      for (const double ratio : ratios)
        s << " " << std::showpoint << std::setprecision(2) << ratio;
      return s.str();
    }
  };

  /**
   * The ratios of the iterations k with an unchanged active set, a
   * residual r_k above @p round_off and r_(k-1) below 0.1 (in the range of
   * the quadratic rate); quadratic if there are at least @p least_count
   * and each exceeds @p least_ratio.
   */
  inline Rates
  residual_ratios(const Common::Solvers::NewtonStatistics &statistics,
                  const double                             round_off   = 1e-10,
                  const double                             least_ratio = 1.8,
                  const unsigned int                       least_count = 2)
  {
    std::vector<double> r;
    for (const auto &residual : statistics.residuals)
      r.push_back(std::max(residual.equilibrium, residual.complementarity));
    Rates rates;
    rates.quadratic = true;
    for (unsigned int k = 1; k < r.size(); ++k)
      if (statistics.active_set_changes[k - 1] == 0 && r[k] > round_off &&
          r[k - 1] < 1e-1)
        {
          const double ratio = std::log(r[k]) / std::log(r[k - 1]);
          rates.ratios.push_back(ratio);
          rates.quadratic = rates.quadratic && ratio > least_ratio;
        }
    rates.quadratic = rates.quadratic && rates.ratios.size() >= least_count;
    return rates;
  }
} // namespace NewtonRates

#endif
