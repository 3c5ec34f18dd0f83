#include <common/analytic/rounded_punch.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Common
{
  namespace Analytic
  {
    using namespace dealii;

    RoundedPunchHalfSpace::RoundedPunchHalfSpace(const double youngs_modulus_1,
                                                 const double poisson_ratio_1,
                                                 const double youngs_modulus_2,
                                                 const double poisson_ratio_2,
                                                 const double flat_radius,
                                                 const double edge_radius,
                                                 const double force)
      : e_star(1. /
               ((1. - poisson_ratio_1 * poisson_ratio_1) / youngs_modulus_1 +
                (1. - poisson_ratio_2 * poisson_ratio_2) / youngs_modulus_2))
      , b(flat_radius)
      , R(edge_radius)
      , P(force)
      , a(flat_radius)
    {
      AssertThrow(youngs_modulus_1 > 0. && youngs_modulus_2 > 0.,
                  ExcMessage("RoundedPunchHalfSpace: moduli must be "
                             "positive."));
      AssertThrow(flat_radius >= 0. && edge_radius > 0. && force > 0.,
                  ExcMessage("RoundedPunchHalfSpace: need b >= 0, R > 0 and "
                             "P > 0."));
      // F(a) grows monotonically from F(b) = 0: bracket, then bisect.
      double low = b, high = b + R;
      while (force_at(high) < P)
        {
          low  = high;
          high = b + 2. * (high - b);
        }
      for (unsigned int i = 0; i < 200 && high - low > 1e-14 * high; ++i)
        {
          const double mid                 = 0.5 * (low + high);
          (force_at(mid) < P ? low : high) = mid;
        }
      a = 0.5 * (low + high);
    }



    double
    RoundedPunchHalfSpace::contact_modulus() const
    {
      return e_star;
    }



    double
    RoundedPunchHalfSpace::contact_radius() const
    {
      return a;
    }



    double
    RoundedPunchHalfSpace::approach() const
    {
      return a / R * (std::sqrt(a * a - b * b) - b * std::acos(b / a));
    }



    double
    RoundedPunchHalfSpace::force_at(const double x) const
    {
      if (x <= b)
        return 0.;
      const double s     = std::sqrt((x - b) * (x + b));
      const double angle = (b > 0. ? std::acos(b / x) : 0.);
      return e_star / (3. * R) *
             ((4. * x * x - b * b) * s - 3. * x * x * b * angle);
    }



    double
    RoundedPunchHalfSpace::mean_pressure() const
    {
      return P / (numbers::PI * a * a);
    }



    double
    RoundedPunchHalfSpace::edge_profile(const double x) const
    {
      if (x <= b)
        return 0.;
      return 2. * std::sqrt((x - b) * (x + b)) -
             (b > 0. ? b * std::acos(b / x) : 0.);
    }



    double
    RoundedPunchHalfSpace::pressure(const double r) const
    {
      if (r >= a)
        return 0.;
      // Substitutions x = x0 + (a - x0) s^2 on s in [0, 1] remove the
      // square-root behaviour at the lower limit x0 = max(r, b): of
      // 1/sqrt(x - r) if r >= b, of g(x) ~ sqrt(x - b) if r < b.
      const QGauss<1>    gauss(12);
      const unsigned int n_intervals = 40;
      const double       x0          = std::max(r, b);
      double             integral    = 0.;
      for (unsigned int k = 0; k < n_intervals; ++k)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double s =
              (k + gauss.point(q)[0]) / static_cast<double>(n_intervals);
            const double w  = gauss.weight(q) / n_intervals;
            const double x  = x0 + (a - x0) * s * s;
            const double dx = 2. * (a - x0) * s;
            if (r >= b)
              // sqrt(x^2 - r^2) = s sqrt(a - r) sqrt(x + r).
              integral +=
                w * 2. * std::sqrt(a - r) * edge_profile(x) / std::sqrt(x + r);
            else
              integral +=
                w * edge_profile(x) * dx / std::sqrt((x - r) * (x + r));
          }
      return e_star / (numbers::PI * R) * integral;
    }


    std::vector<PunchReferencePoint>
    fenet_punch_fe_reference()
    {
      return {{0.5, 70.5, 71.2, 0.2, 0.},
              {5., 79.8, 77.9, 2.2, 2.6},
              {10., 85.9, 86.3, 4.9, 4.0},
              {20., 94.2, 91.1, 9.2, 9.2},
              {30., 104.2, 106.3, 10.3, 10.7},
              {35., 121.5, 138.9, 12.1, 13.9},
              {39., 325., 302., 32., 30.},
              {40., 386., 353., 38.9, 35.2},
              {45., 0., 0., 0., 0.}};
    }



    std::vector<PunchSurfaceReferencePoint>
    fenet_punch_marc_surface_displacements()
    {
      const double none = std::numeric_limits<double>::quiet_NaN();
      return {{0.5, -0.1310, -0.1288, 0., 0.},
              {5., -0.1306, -0.1284, -0.0010, 0.0002},
              {10., -0.1302, -0.1281, -0.0020, 0.0006},
              {20., -0.1291, -0.1274, -0.0042, 0.0003},
              {30., -0.1280, -0.1267, -0.0072, -0.0014},
              {35., -0.126, -0.126, -0.0094, -0.0033},
              {39., none, none, -0.0128, -0.0063},
              {40., -0.124, -0.124, -0.0137, -0.0074},
              {45., -0.0956, -0.0956, -0.0155, -0.0113},
              {60., -0.0660, -0.0660, -0.0099, -0.0078},
              {80., -0.0502, -0.0509, -0.0060, -0.0044}};
    }
  } // namespace Analytic
} // namespace Common
