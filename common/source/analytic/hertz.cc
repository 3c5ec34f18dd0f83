#include <common/analytic/hertz.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace Common
{
  namespace Analytic
  {
    HertzLineContact::HertzLineContact(const double youngs_modulus_1,
                                       const double poisson_ratio_1,
                                       const double youngs_modulus_2,
                                       const double poisson_ratio_2,
                                       const double radius,
                                       const double force_per_length)
      : youngs_modulus_1(youngs_modulus_1)
      , poisson_ratio_1(poisson_ratio_1)
      , youngs_modulus_2(youngs_modulus_2)
      , poisson_ratio_2(poisson_ratio_2)
    {
      AssertThrow(youngs_modulus_1 > 0 && youngs_modulus_2 > 0 && radius > 0 &&
                    force_per_length >= 0,
                  dealii::ExcMessage("Hertz: moduli, radius and force must "
                                     "be positive."));
      e_star =
        1. / ((1. - poisson_ratio_1 * poisson_ratio_1) / youngs_modulus_1 +
              (1. - poisson_ratio_2 * poisson_ratio_2) / youngs_modulus_2);
      a  = std::sqrt(4. * force_per_length * radius / (M_PI * e_star));
      p0 = (a > 0. ? 2. * force_per_length / (M_PI * a) : 0.);
    }



    double
    HertzLineContact::contact_modulus() const
    {
      return e_star;
    }



    double
    HertzLineContact::half_width() const
    {
      return a;
    }



    double
    HertzLineContact::peak_pressure() const
    {
      return p0;
    }



    double
    HertzLineContact::pressure(const double x) const
    {
      const double xi = x / a;
      return (std::abs(xi) < 1. ? p0 * std::sqrt(1. - xi * xi) : 0.);
    }



    double
    HertzLineContact::dundurs_beta() const
    {
      const double g1     = youngs_modulus_1 / (2. * (1. + poisson_ratio_1));
      const double g2     = youngs_modulus_2 / (2. * (1. + poisson_ratio_2));
      const double kappa1 = 3. - 4. * poisson_ratio_1;
      const double kappa2 = 3. - 4. * poisson_ratio_2;
      return (g1 * (kappa2 - 1.) - g2 * (kappa1 - 1.)) /
             (g1 * (kappa2 + 1.) + g2 * (kappa1 + 1.));
    }
  } // namespace Analytic
} // namespace Common
