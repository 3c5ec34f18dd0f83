/*
 * Boundary-element half-space reference for Hertz line contact with Coulomb
 * friction under increasing load (common/analytic/coupled_partial_slip),
 * benchmark 1's data (E* = 57692 MPa, beta = 1/7, R = 50 mm,
 * P = 35 kN/mm), 100 elements on the half line, 20 increments. Checks:
 * (a) mu = 0 is Hertz: half-width and centre pressure within 0.5 %;
 * (b) mu = 0.1 in the Goodman approximation is Spence's solution: c/a
 * within 0.015 (one element is 0.0125 a) of K'/K = beta/mu (0.4058) and the
 * peak traction within 1 % of SpencePartialSlip's; (c) mu = 0.1 with the
 * exact coupling: the pressure rises and the stick zone shrinks, to the
 * values of a 400-element, 40-increment run within the discretisation
 * (p0/p0_Hertz = 1.0191 within 0.001, c/a = 0.392 within 0.015).
 */

#include <common/analytic/coupled_partial_slip.h>
#include <common/analytic/hertz.h>
#include <common/analytic/spence.h>

#include "../tests.h"

#include <deal.II/base/logstream.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace dealii;
using namespace Common::Analytic;

int
main()
{
  attach_log();

  const HertzLineContact hertz(210000., 0.3, 70000., 0.3, 50., 35000.);
  const double           e_star = hertz.contact_modulus();
  const double           beta   = std::abs(hertz.dundurs_beta());
  const double           a      = hertz.half_width();
  const double           p0     = hertz.peak_pressure();

  const auto pass_fail = [](const bool b) {
    return b ? "PASS" : "FAIL";
  };
  deallog << std::fixed;

  const CoupledPartialSlip
    frictionless(e_star, beta, 0., 50., 35000., 100, 20, false);
  deallog << "(a) mu = 0: a/a_Hertz = " << std::setprecision(3)
          << frictionless.half_width() / a
          << ", p(0)/p0_Hertz = " << frictionless.centre_pressure() / p0 << ": "
          << pass_fail(frictionless.converged() &&
                       std::abs(frictionless.half_width() / a - 1.) < 5e-3 &&
                       std::abs(frictionless.centre_pressure() / p0 - 1.) <
                         5e-3)
          << std::endl;

  const SpencePartialSlip spence(a, p0, 50., beta, 0.1);
  const CoupledPartialSlip
               goodman(e_star, beta, 0.1, 50., 35000., 100, 20, true);
  const double c_goodman = goodman.stick_half_width() / a;
  deallog << "(b) Goodman, mu = 0.1: c/a = " << std::setprecision(3)
          << c_goodman << " (Spence " << spence.stick_ratio()
          << "), q_max/q_Spence = "
          << goodman.peak_tangential_traction() /
               spence.peak_tangential_traction()
          << ": "
          << pass_fail(goodman.converged() &&
                       std::abs(c_goodman - spence.stick_ratio()) < 0.015 &&
                       std::abs(goodman.peak_tangential_traction() /
                                  spence.peak_tangential_traction() -
                                1.) < 0.01)
          << std::endl;

  const CoupledPartialSlip
               coupled(e_star, beta, 0.1, 50., 35000., 100, 20, false);
  const double c_coupled = coupled.stick_half_width() / a;
  const double p_ratio   = coupled.centre_pressure() / p0;
  deallog << "(c) exact coupling, mu = 0.1: p(0)/p0_Hertz = "
          << std::setprecision(3) << p_ratio << ", c/a = " << c_coupled << ": "
          << pass_fail(coupled.converged() &&
                       std::abs(p_ratio - 1.0191) < 1e-3 &&
                       std::abs(c_coupled - 0.392) < 0.015)
          << std::endl;
}
