/*
 * Half-space solution of the rounded flat punch (common/analytic/
 * rounded_punch): checks (a) the FENET benchmark 2 values of doc/references.md
 * 2.1 (a = 40.430 mm, approach 0.169 mm, p at r = 0 ... 39 mm as tabulated,
 * within their rounding); (b) equilibrium, 2 pi int r p dr = P to 1e-6
 * relative; (c) b = 0 reproduces Hertz's sphere (a, approach, p(r)) to 1e-8;
 * (d) the solids4foam case punchAxisymmetricModified (b = 10, R = 100,
 * E = 100 GPa on both sides, nu = 0.3, b/a = 0.7): mean pressure 696.504 MPa
 * and approach 0.32115 mm to their five or six digits.
 */

#include <common/analytic/rounded_punch.h>

#include "../tests.h"

#include <deal.II/base/logstream.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <string>
#include <vector>

using namespace dealii;
using Common::Analytic::RoundedPunchHalfSpace;

namespace
{
  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }

  // int_lo^hi f(x) dx with x = hi - (hi - lo) s^2 if at_hi (square-root
  // behaviour at hi), x = lo + (hi - lo) s^2 otherwise (at lo).
  double
  integrate(const std::function<double(double)> &f,
            const double                         lo,
            const double                         hi,
            const bool                           at_hi)
  {
    const QGauss<1>    gauss(10);
    const unsigned int n   = 200;
    double             sum = 0.;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double s  = (k + gauss.point(q)[0]) / n;
          const double w  = gauss.weight(q) / n;
          const double dx = 2. * (hi - lo) * s;
          sum +=
            w * dx * f(at_hi ? hi - (hi - lo) * s * s : lo + (hi - lo) * s * s);
        }
    return sum;
  }
} // namespace



int
main()
{
  attach_log();

  // (a) FENET benchmark 2: steel punch on aluminium, b = 40, R = 10,
  // P = 100 MPa times pi 50^2.
  const double                P = 100. * numbers::PI * 50. * 50.;
  const RoundedPunchHalfSpace punch(210000., 0.3, 70000., 0.3, 40., 10., P);
  const double                a = punch.contact_radius();
  deallog << std::fixed << std::setprecision(1)
          << "E* = " << punch.contact_modulus() << " MPa" << std::endl;
  deallog << std::setprecision(4) << "a = " << a << " mm" << std::endl;
  deallog << std::setprecision(5) << "approach = " << punch.approach() << " mm"
          << std::endl;
  bool table_ok = std::abs(a - 40.430) < 0.0005 &&
                  std::abs(punch.approach() - 0.169) < 0.0005;
  const std::vector<std::pair<double, double>> table = {{0., 77.1},
                                                        {10., 79.6},
                                                        {20., 88.9},
                                                        {30., 115.7},
                                                        {35., 156.1},
                                                        {38., 233.8},
                                                        {39., 311.9}};
  for (const auto &[r, p] : table)
    {
      const double value = punch.pressure(r);
      deallog << std::setprecision(2) << "p(" << r << ") = " << value
              << " MPa (doc/references.md " << std::setprecision(1) << p << ")"
              << std::endl;
      table_ok = table_ok && std::abs(value - p) < 0.05;
    }
  deallog << "(a) FENET values within rounding: " << pass_fail(table_ok)
          << std::endl;

  // (b) Equilibrium, the integral split at the steep rise before b and
  // graded to the square-root ends at b and a.
  const auto rp = [&punch](const double r) {
    return r * punch.pressure(r);
  };
  const double total =
    2. * numbers::PI *
    (integrate(rp, 0., 38., false) + integrate(rp, 38., 40., true) +
     integrate(rp, 40., a, true));
  const double balance = std::abs(total / P - 1.);
  deallog << std::scientific << std::setprecision(3)
          << "|2 pi int r p dr / P - 1| < 1e-6: " << pass_fail(balance < 1e-6)
          << std::endl;

  // (c) b = 0: Hertz's sphere, a^3 = 3PR/(4E*), approach a^2/R,
  // p = p0 sqrt(1 - r^2/a^2) with p0 = 3P/(2 pi a^2).
  const RoundedPunchHalfSpace sphere(210000., 0.3, 70000., 0.3, 0., 50., 1e5);
  const double                e_star = sphere.contact_modulus();
  const double a_hertz = std::cbrt(3. * 1e5 * 50. / (4. * e_star));
  const double p0      = 3. * 1e5 / (2. * numbers::PI * a_hertz * a_hertz);
  double       hertz_error =
    std::max(std::abs(sphere.contact_radius() / a_hertz - 1.),
             std::abs(sphere.approach() / (a_hertz * a_hertz / 50.) - 1.));
  for (const double xi : {0., 0.3, 0.6, 0.9, 0.99})
    hertz_error = std::max(hertz_error,
                           std::abs(sphere.pressure(xi * a_hertz) -
                                    p0 * std::sqrt(1. - xi * xi)) /
                             p0);
  deallog << "(c) b = 0 is Hertz's sphere to 1e-8: "
          << pass_fail(hertz_error < 1e-8) << std::endl;

  // (d) solids4foam punchAxisymmetricModified: b/a = 0.7.
  const RoundedPunchHalfSpace probe(100000., 0.3, 100000., 0.3, 10., 100., 1.);
  const double                F = probe.force_at(10. / 0.7);
  const RoundedPunchHalfSpace s4f(100000., 0.3, 100000., 0.3, 10., 100., F);
  deallog << std::fixed << std::setprecision(3)
          << "solids4foam case: mean pressure " << s4f.mean_pressure()
          << " MPa, approach " << std::setprecision(5) << s4f.approach()
          << " mm" << std::endl;
  deallog << "(d) solids4foam values: "
          << pass_fail(std::abs(s4f.mean_pressure() - 696.504) < 0.0005 &&
                       std::abs(s4f.approach() - 0.32115) < 0.000005)
          << std::endl;
}
