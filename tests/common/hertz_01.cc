// Checks Common::Analytic::HertzLineContact on the data of benchmark 1 of
// the FENET/NAFEMS advanced contact benchmarks (steel cylinder, E1 = 210000
// MPa, nu1 = 0.3, on an aluminium block, E2 = 70000 MPa, nu2 = 0.3,
// R = 50 mm, P = 35000 N/mm): the contact modulus E* = 57692.3 MPa, the
// half-width a = 6.21463 mm, the peak pressure p0 = 3585.36 MPa, the
// pressure at x = a/2 (p0 sqrt(3)/2) and outside the contact (zero), the
// second Dundurs parameter |beta| = 1/7 with its sign flipping when the
// bodies are swapped, and equilibrium: the integral of p(x) over (-a, a),
// computed by Gauss quadrature after the substitution x = a sin(phi) that
// removes the square-root singularity at the edges, equals P to 1e-6.

#include <common/analytic/hertz.h>

#include "../tests.h"

#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <iomanip>

using namespace dealii;

int
main()
{
  initlog();

  const double E1 = 210000., nu1 = 0.3, E2 = 70000., nu2 = 0.3;
  const double R = 50., P = 35000.;
  const Common::Analytic::HertzLineContact hertz(E1, nu1, E2, nu2, R, P);

  const double a  = hertz.half_width();
  const double p0 = hertz.peak_pressure();
  deallog << std::setprecision(1) << "E* = " << hertz.contact_modulus()
          << std::endl;
  deallog << std::setprecision(5) << "a = " << a << std::endl;
  deallog << std::setprecision(2) << "p0 = " << p0 << std::endl;
  deallog << "p(a/2) = " << hertz.pressure(0.5 * a) << std::endl;
  deallog << "p(1.5 a) = " << hertz.pressure(1.5 * a) << std::endl;
  deallog << std::setprecision(6)
          << "|dundurs_beta| = " << std::abs(hertz.dundurs_beta()) << std::endl;

  const Common::Analytic::HertzLineContact swapped(E2, nu2, E1, nu1, R, P);
  deallog << "beta(1,2) + beta(2,1) = "
          << std::abs(hertz.dundurs_beta() + swapped.dundurs_beta())
          << std::endl;

  // Closed-form checks, independent of the class.
  const double e_star = 1. / ((1. - nu1 * nu1) / E1 + (1. - nu2 * nu2) / E2);
  const double a_ref  = std::sqrt(4. * P * R / (numbers::PI * e_star));
  const bool   closed_form_ok =
    std::abs(hertz.contact_modulus() / e_star - 1.) < 1e-12 &&
    std::abs(a / a_ref - 1.) < 1e-12 &&
    std::abs(p0 / (2. * P / (numbers::PI * a_ref)) - 1.) < 1e-12 &&
    std::abs(hertz.pressure(0.5 * a) / p0 - std::sqrt(3.) / 2.) < 1e-12 &&
    std::abs(std::abs(hertz.dundurs_beta()) - 1. / 7.) < 1e-12;
  deallog << "closed-form values: " << (closed_form_ok ? "PASS" : "FAIL")
          << std::endl;

  // Equilibrium: int_{-a}^{a} p(x) dx = P, with x = a sin(phi).
  const QGauss<1> quadrature(20);
  double          force = 0.;
  for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const double phi = numbers::PI * (quadrature.point(q)[0] - 0.5);
      force += hertz.pressure(a * std::sin(phi)) * a * std::cos(phi) *
               numbers::PI * quadrature.weight(q);
    }
  const double relative_error = std::abs(force / P - 1.);
  deallog << "int p dx = " << force << std::endl;
  deallog << "equilibrium |int p dx / P - 1| < 1e-6: "
          << (relative_error < 1e-6 ? "PASS" : "FAIL") << std::endl;
}
