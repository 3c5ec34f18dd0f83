// Checks the pure functions of Common::Contact::NormalContactLaw. The
// complementarity function C(lambda, g, c) = lambda - max(0, lambda - c g)
// must vanish exactly on the complementarity set {lambda >= 0, g >= 0,
// lambda g = 0} (checked at (lambda > 0, g = 0), (0, g > 0), (0, 0)) and be
// nonzero off it (lambda < 0; g < 0 with lambda = 0; lambda > 0 with
// g > 0), for several c > 0; on a grid of (lambda, g) it must equal
// min(lambda, c g) and be zero exactly on the set. is_active must agree
// with the rule lambda - c g > 0, and C must reduce to c g on active and to
// lambda on inactive points. The penalty pressure eps max(0, -g) and its
// derivative are compared with central finite differences away from the
// kink at g = 0, and the derivative at g = 0 must be -eps (touching counts
// as active).

#include <common/contact/normal_contact_law.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace dealii;
namespace Law = Common::Contact::NormalContactLaw;

namespace
{
  bool
  in_complementarity_set(const double lambda, const double g)
  {
    return lambda >= 0. && g >= 0. && lambda * g == 0.;
  }
} // namespace

int
main()
{
  initlog();

  // Named check points, c = 100 MPa/mm.
  {
    const double c = 100.;
    struct Case
    {
      const char *name;
      double      lambda, g;
    };
    const std::vector<Case> cases = {{"lambda>0, g=0 ", 5., 0.},
                                     {"lambda=0, g>0 ", 0., 0.1},
                                     {"lambda=0, g=0 ", 0., 0.},
                                     {"lambda<0, g=0 ", -2., 0.},
                                     {"lambda<0, g>0 ", -2., 0.1},
                                     {"lambda=0, g<0 ", 0., -0.1},
                                     {"lambda>0, g>0 ", 5., 0.1},
                                     {"lambda>0, g<0 ", 5., -0.1}};
    for (const Case &k : cases)
      {
        const double C = Law::complementarity(k.lambda, k.g, c);
        deallog << k.name << ": C = " << C
                << ", in set = " << in_complementarity_set(k.lambda, k.g)
                << ", active = " << Law::is_active(k.lambda, k.g, c)
                << std::endl;
      }
  }

  // Grid of (lambda, g) and several c: C == 0 exactly on the set,
  // C == min(lambda, c g), is_active == (lambda - c g > 0), and C == c g on
  // active points, C == lambda on inactive points.
  {
    const std::vector<double> lambdas = {-3., -1., -0.25, 0., 0.5, 2., 7.};
    const std::vector<double> gaps = {-0.3, -0.01, -1e-6, 0., 1e-6, 0.02, 1.};
    const std::vector<double> cs   = {1., 100., 1e4};
    unsigned int              n_points = 0, zero_set_errors = 0, min_errors = 0,
                 active_errors = 0, reduction_errors = 0;
    for (const double c : cs)
      for (const double lambda : lambdas)
        for (const double g : gaps)
          {
            ++n_points;
            const double C = Law::complementarity(lambda, g, c);
            if ((C == 0.) != in_complementarity_set(lambda, g))
              ++zero_set_errors;
            if (std::abs(C - std::min(lambda, c * g)) >
                1e-14 * (std::abs(lambda) + std::abs(c * g)))
              ++min_errors;
            const bool active = Law::is_active(lambda, g, c);
            if (active != (lambda - c * g > 0.))
              ++active_errors;
            const double expected = (active ? c * g : lambda);
            if (std::abs(C - expected) >
                1e-14 * (std::abs(lambda) + std::abs(c * g)))
              ++reduction_errors;
          }
    deallog << "grid points: " << n_points << std::endl;
    deallog << "C == 0 exactly on the complementarity set, mismatches: "
            << zero_set_errors << std::endl;
    deallog << "C == min(lambda, c g), mismatches: " << min_errors << std::endl;
    deallog << "is_active == (lambda - c g > 0), mismatches: " << active_errors
            << std::endl;
    deallog << "C == c g if active, lambda if not, mismatches: "
            << reduction_errors << std::endl;
  }

  // Penalty law against central finite differences, away from g = 0.
  {
    const double eps                = 1000.;
    const double h                  = 1e-6;
    double       max_pressure_error = 0., max_derivative_error = 0.;
    for (const double g : {-0.3, -0.01, -1e-4, 1e-4, 0.05, 0.2})
      {
        const double p  = Law::penalty_pressure(g, eps);
        const double dp = Law::penalty_derivative(g, eps);
        const double fd = (Law::penalty_pressure(g + h, eps) -
                           Law::penalty_pressure(g - h, eps)) /
                          (2. * h);
        deallog << "g = " << g << ": p = " << p << ", dp/dg = " << dp
                << std::endl;
        max_pressure_error =
          std::max(max_pressure_error, std::abs(p - eps * std::max(0., -g)));
        max_derivative_error =
          std::max(max_derivative_error, std::abs(dp - fd) / eps);
      }
    deallog << "penalty pressure == eps max(0, -g): "
            << (max_pressure_error == 0. ? "yes" : "no") << std::endl;
    deallog << "max |dp/dg - finite difference| / eps < 1e-6: "
            << (max_derivative_error < 1e-6 ? "yes" : "no") << std::endl;
    deallog << "at g = 0: p = " << Law::penalty_pressure(0., eps)
            << ", dp/dg = " << Law::penalty_derivative(0., eps) << std::endl;
  }
}
