#include <common/analytic/spence.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace Common
{
  namespace Analytic
  {
    namespace
    {
      using dealii::numbers::PI;

      /** The exception of the traction accessors where the stick zone
       * fills the contact. */
      dealii::StandardExceptions::ExcMessage
      not_available()
      {
        return dealii::StandardExceptions::ExcMessage(
          "Spence: |beta|/mu is so small that the stick zone fills the "
          "contact in double precision; the traction is not available.");
      }

      // Gauss-Kronrod 7/15-point rule on [-1, 1] (QUADPACK qk15): Kronrod
      // abscissae, the odd ones (1, 3, 5, 7) being the Gauss points, and
      // the weights of both rules.
      constexpr double kronrod_points[8] = {0.991455371120812639206854697526329,
                                            0.949107912342758524526189684047851,
                                            0.864864423359769072789712788640926,
                                            0.741531185599394439863864773280788,
                                            0.586087235467691130294144845693013,
                                            0.405845151377397166906606412076961,
                                            0.207784955007898467600689403773245,
                                            0.};
      constexpr double kronrod_weights[8] = {
        0.022935322010529224963732008058970,
        0.063092092629978553290700663189204,
        0.104790010322250183839876322541518,
        0.140653259715525918745189590510238,
        0.169004726639267902826583426598550,
        0.190350578064785409913256402421014,
        0.204432940075298892414161999234649,
        0.209482141084727828012999174891714};
      constexpr double gauss_weights[4] = {0.129484966168869693270611432679082,
                                           0.279705391489276667901467771423780,
                                           0.381830050505118944950369775488975,
                                           0.417959183673469387755102040816327};



      /**
       * 15-point Kronrod approximation of the integral of @p f over
       * [@p lower, @p upper]. @p error receives |Kronrod - Gauss|, a
       * (pessimistic) estimate of the error of the 7-point Gauss rule, but
       * not less than the rounding error of the sum.
       */
      template <typename Function>
      double
      gauss_kronrod(const Function &f,
                    const double    lower,
                    const double    upper,
                    double         &error)
      {
        const double center      = 0.5 * (lower + upper);
        const double half_length = 0.5 * (upper - lower);
        const double f_center    = f(center);
        double       kronrod     = kronrod_weights[7] * f_center;
        double       gauss       = gauss_weights[3] * f_center;
        double       magnitude   = kronrod_weights[7] * std::abs(f_center);
        for (unsigned int j = 0; j < 7; ++j)
          {
            const double dx      = half_length * kronrod_points[j];
            const double f_left  = f(center - dx);
            const double f_right = f(center + dx);
            kronrod += kronrod_weights[j] * (f_left + f_right);
            magnitude +=
              kronrod_weights[j] * (std::abs(f_left) + std::abs(f_right));
            if (j % 2 == 1)
              gauss += gauss_weights[j / 2] * (f_left + f_right);
          }
        error = std::max(std::abs((kronrod - gauss) * half_length),
                         50. * std::numeric_limits<double>::epsilon() *
                           magnitude * std::abs(half_length));
        return kronrod * half_length;
      }



      /**
       * Globally adaptive Gauss-Kronrod quadrature (QUADPACK qag-like):
       * the piece with the largest error estimate is bisected until the
       * sum of the estimates is below @p tolerance (absolute) or
       * @p max_pieces pieces exist, which bounds the work.
       */
      template <typename Function>
      double
      adaptive_integral(const Function    &f,
                        const double       lower,
                        const double       upper,
                        const double       tolerance,
                        const unsigned int max_pieces)
      {
        struct Piece
        {
          double lower, upper, value, error;
        };
        const auto integrate = [&f](const double lo, const double hi) {
          Piece piece{lo, hi, 0., 0.};
          piece.value = gauss_kronrod(f, lo, hi, piece.error);
          return piece;
        };

        std::vector<Piece> pieces(1, integrate(lower, upper));
        double             total_error = pieces[0].error;
        while (total_error > tolerance && pieces.size() < max_pieces)
          {
            const auto worst =
              std::max_element(pieces.begin(),
                               pieces.end(),
                               [](const Piece &p1, const Piece &p2) {
                                 return p1.error < p2.error;
                               });
            const double lo = worst->lower, hi = worst->upper;
            const double middle = 0.5 * (lo + hi);
            if (!(middle > lo && middle < hi))
              break;
            *worst = integrate(lo, middle);
            pieces.push_back(integrate(middle, hi));
            total_error = 0.;
            for (const Piece &piece : pieces)
              total_error += piece.error;
          }
        double value = 0.;
        for (const Piece &piece : pieces)
          value += piece.value;
        return value;
      }



      /** The 15-point Kronrod rule alone, for integrands known to be smooth
       * on the interval. */
      template <typename Function>
      double
      kronrod_integral(const Function &f,
                       const double    lower,
                       const double    upper)
      {
        double error = 0.;
        return gauss_kronrod(f, lower, upper, error);
      }



      /**
       * Jacobi theta functions of the nome @p q, 0 <= q <= exp(-pi):
       * \f$\vartheta_2/(2q^{1/4})\f$, \f$\vartheta_3\f$ and \f$\vartheta_4\f$.
       * Eight terms give full double precision for q <= exp(-pi).
       */
      void
      theta_functions(const double q,
                      double      &theta_2_reduced,
                      double      &theta_3,
                      double      &theta_4)
      {
        theta_2_reduced = 0.;
        theta_3         = 1.;
        theta_4         = 1.;
        for (unsigned int n = 0; n < 8; ++n)
          {
            const double nn = static_cast<double>(n);
            theta_2_reduced += std::pow(q, nn * (nn + 1.));
            if (n > 0)
              {
                const double term = 2. * std::pow(q, nn * nn);
                theta_3 += term;
                theta_4 += (n % 2 == 1 ? -term : term);
              }
          }
      }
    } // namespace



    double
    complete_elliptic_k(const double k)
    {
      AssertThrow(std::abs(k) <= 1.,
                  dealii::ExcMessage("complete_elliptic_k: the modulus must "
                                     "satisfy |k| <= 1."));
      const double k_complement = std::sqrt((1. - k) * (1. + k));
      if (k_complement == 0.)
        return std::numeric_limits<double>::infinity();

      // Arithmetic-geometric mean of 1 and k'; converges quadratically.
      double arithmetic = 1., geometric = k_complement;
      for (unsigned int iteration = 0; iteration < 64; ++iteration)
        {
          const double next_arithmetic = 0.5 * (arithmetic + geometric);
          geometric                    = std::sqrt(arithmetic * geometric);
          arithmetic                   = next_arithmetic;
          if (std::abs(arithmetic - geometric) <= 1e-16 * arithmetic)
            break;
        }
      return PI / (arithmetic + geometric);
    }



    double
    spence_stick_ratio(const double beta, const double mu)
    {
      AssertThrow(mu >= 0.,
                  dealii::ExcMessage("spence_stick_ratio: the friction "
                                     "coefficient must be non-negative."));
      if (beta == 0.)
        return 1.;
      if (mu == 0.)
        return 0.;

      // K'(k)/K(k) = r is the nome q = exp(-pi r) of the modulus k, and
      // k = theta_2^2/theta_3^2. For r < 1 the complementary modulus has
      // nome exp(-pi/r) <= exp(-pi), and k = theta_4^2/theta_3^2 of it.
      const double ratio = std::abs(beta) / mu;
      double       theta_2_reduced, theta_3, theta_4;
      if (ratio >= 1.)
        {
          theta_functions(std::exp(-PI * ratio),
                          theta_2_reduced,
                          theta_3,
                          theta_4);
          const double quotient = theta_2_reduced / theta_3;
          return 4. * std::exp(-0.5 * PI * ratio) * quotient * quotient;
        }
      else
        {
          theta_functions(std::exp(-PI / ratio),
                          theta_2_reduced,
                          theta_3,
                          theta_4);
          const double quotient = theta_4 / theta_3;
          return quotient * quotient;
        }
    }



    SpencePartialSlip::SpencePartialSlip(const double half_width,
                                         const double peak_pressure,
                                         const double radius,
                                         const double beta,
                                         const double mu)
      : a(half_width)
      , p0(peak_pressure)
      , radius(radius)
      , beta(std::abs(beta))
      , mu(mu)
      , k(spence_stick_ratio(beta, mu))
      , traction_available(true)
      , peak_traction(0.)
      , peak_position(0.)
    {
      AssertThrow(half_width > 0. && peak_pressure >= 0. && radius > 0. &&
                    mu >= 0.,
                  dealii::ExcMessage("Spence: a and R must be positive, p0 "
                                     "and mu non-negative."));
      if (this->beta == 0. || mu == 0.)
        return; // q = 0 everywhere
      if (k >= 1.)
        {
          traction_available = false;
          return;
        }
      if (k == 0.)
        {
          // Full slip: q = mu p, largest at the centre.
          peak_traction = mu * p0;
          return;
        }

      // Nodes of the variable w, u = k sin(w), 0 < w <= pi/2. The
      // integrand behaves like 1/w at w = 0 (cells halve toward it), and
      // X_g has complex singularities at distance acosh(1/k) from w = pi/2
      // (the edges t = +-1 of the contact, close to +-k when k -> 1): the
      // cells also halve toward pi/2 until the last one is four times
      // smaller than that distance. The cells in between are uniform.
      const double        split         = PI / 8.;
      const double        edge_distance = std::acosh(1. / k);
      std::vector<double> lower_nodes, upper_gaps;
      for (double w = split; w > 1e-6; w *= 0.5)
        lower_nodes.push_back(w);
      for (double gap = split;
           upper_gaps.empty() || upper_gaps.back() > 0.25 * edge_distance;
           gap *= 0.5)
        upper_gaps.push_back(gap);

      nodes.assign(lower_nodes.rbegin(), lower_nodes.rend());
      const double       middle_end = 0.5 * PI - split;
      const unsigned int n_middle   = 8;
      for (unsigned int j = 1; j < n_middle; ++j)
        nodes.push_back(split + (middle_end - split) * j / n_middle);
      for (const double gap : upper_gaps)
        nodes.push_back(0.5 * PI - gap);
      nodes.push_back(0.5 * PI);

      integral_at_nodes.assign(nodes.size(), 0.);
      for (unsigned int j = nodes.size() - 1; j-- > 0;)
        integral_at_nodes[j] =
          integral_at_nodes[j + 1] +
          kronrod_integral([this](
                             const double w) { return stick_integrand(w); },
                           nodes[j],
                           nodes[j + 1]);

      // Peak of q: coarse scan of the stick zone, then golden sections.
      const unsigned int n_scan = 64;
      unsigned int       i_max  = n_scan;
      double             q_max  = 0.;
      for (unsigned int i = 1; i <= n_scan; ++i)
        {
          const double q = normalized_traction(k * i / n_scan);
          if (q > q_max)
            {
              q_max = q;
              i_max = i;
            }
        }
      double       lower  = k * (i_max - 1.) / n_scan;
      double       upper  = std::min(k * (i_max + 1.) / n_scan, k);
      const double golden = 0.5 * (std::sqrt(5.) - 1.);
      double       x1     = upper - golden * (upper - lower);
      double       x2     = lower + golden * (upper - lower);
      double       q1 = normalized_traction(x1), q2 = normalized_traction(x2);
      for (unsigned int iteration = 0; iteration < 60; ++iteration)
        if (q1 < q2)
          {
            lower = x1;
            x1    = x2;
            q1    = q2;
            x2    = lower + golden * (upper - lower);
            q2    = normalized_traction(x2);
          }
        else
          {
            upper = x2;
            x2    = x1;
            q2    = q1;
            x1    = upper - golden * (upper - lower);
            q1    = normalized_traction(x1);
          }
      const double xi_max = (q1 > q2 ? x1 : x2);
      peak_position       = a * xi_max;
      peak_traction       = p0 * std::max({q1, q2, q_max});
    }



    double
    SpencePartialSlip::stick_ratio() const
    {
      return k;
    }



    bool
    SpencePartialSlip::has_traction() const
    {
      return traction_available;
    }



    double
    SpencePartialSlip::stick_half_width() const
    {
      return k * a;
    }



    double
    SpencePartialSlip::pressure(const double x) const
    {
      const double xi = x / a;
      return (std::abs(xi) < 1. ? p0 * std::sqrt((1. - xi) * (1. + xi)) : 0.);
    }



    double
    SpencePartialSlip::tangential_traction(const double x) const
    {
      AssertThrow(traction_available, not_available());
      const double q = p0 * normalized_traction(std::abs(x) / a);
      return (x < 0. ? -q : q);
    }



    double
    SpencePartialSlip::peak_tangential_traction() const
    {
      AssertThrow(traction_available, not_available());
      return peak_traction;
    }



    double
    SpencePartialSlip::peak_tangential_traction_position() const
    {
      return peak_position;
    }



    double
    SpencePartialSlip::frictionless_slip(const double x) const
    {
      const double s = std::abs(x);
      if (s > a)
        return 0.;
      // Non-negative for 0 <= s <= a; the clamp removes the rounding
      // residue of the cancellation at s = a.
      const double slip =
        std::max(0.,
                 beta / (2. * radius) *
                   (a * a * std::asin(s / a) +
                    s * std::sqrt((a - s) * (a + s)) - 0.5 * PI * s * s));
      return (x < 0. ? -slip : slip);
    }



    double
    SpencePartialSlip::frictionless_relative_displacement(const double x) const
    {
      // (2 beta/E*) p0 [...] with E* = 2 R p0/a.
      const double s = std::min(std::abs(x), a);
      const double displacement =
        beta / (2. * radius) *
        (a * a * std::asin(s / a) + s * std::sqrt((a - s) * (a + s)));
      return (x < 0. ? -displacement : displacement);
    }



    double
    SpencePartialSlip::regular_load(const double t) const
    {
      const double s = std::abs(t);
      const double b = std::sqrt((1. - s) * (1. + s));
      // (1/b - 1) ln|t|, which is t^2 ln|t| / 2 near t = 0.
      const double log_part =
        (s > 0. ? s * s / (b * (1. + b)) * std::log(s) : 0.);
      return -beta / b + 2. * mu / PI * (std::log1p(b) / b - log_part);
    }



    double
    SpencePartialSlip::regular_load_derivative(const double t) const
    {
      const double s = std::abs(t);
      if (s == 0.)
        return 0.;
      const double b  = std::sqrt((1. - s) * (1. + s));
      const double b3 = b * b * b;
      const double derivative =
        -beta * s / b3 +
        2. * mu / PI *
          (-s / b * (1. / (b * (1. + b)) - std::log1p(b) / (b * b)) -
           s / b3 * std::log(s) - s / (b * (1. + b)));
      return (t < 0. ? -derivative : derivative);
    }



    double
    SpencePartialSlip::regular_stick_density(const double u) const
    {
      // X_g(u) = sqrt(k^2-u^2)/pi PV int_{-k}^{k} g(t)/(sqrt(k^2-t^2)(t-u)) dt.
      // With t = k cos(theta) the weight disappears, and since
      // PV int_0^pi dtheta/(k cos(theta) - u) = 0 for |u| < k, g(t) may be
      // replaced by g(t) - g(u): the integrand is then regular at t = u.
      // g is even, so the two halves theta < pi/2 and theta > pi/2 combine
      // into int_0^{pi/2} (g(t)-g(u))/(t-u) * 2u/(t+u) dtheta. The
      // difference quotient is replaced by g'(u) where it would lose more
      // than half of its digits.
      const double phi_u     = std::acos(u / k);
      const double g_u       = regular_load(u);
      const double dg_u      = regular_load_derivative(u);
      const auto   integrand = [&](const double theta) {
        const double t          = k * std::cos(theta);
        const double difference = t - u;
        const double quotient   = (std::abs(difference) <= 1e-8 * k ?
                                       dg_u :
                                       (regular_load(t) - g_u) / difference);
        return quotient * 2. * u / (t + u);
      };
      // The integral is O((beta + mu) u) at the origin: a tolerance
      // proportional to u keeps X_g/u^2 accurate. Its floor is the level of
      // the rounding errors of the difference quotients, about
      // eps (beta + mu)/k, which matters only for a small stick zone.
      const double tolerance = (beta + mu) * std::max(1e-9 * u, 1e-13 / k);
      const double integral =
        adaptive_integral(integrand, 0., phi_u, tolerance, 100) +
        adaptive_integral(integrand, phi_u, 0.5 * PI, tolerance, 100);
      return std::sqrt((k - u) * (k + u)) / PI * integral;
    }



    double
    SpencePartialSlip::stick_integrand(const double w) const
    {
      // X_g(u)/u^2 du with u = k sin(w), du = k cos(w) dw.
      const double u = k * std::sin(w);
      return regular_stick_density(u) * std::cos(w) /
             (k * std::sin(w) * std::sin(w));
    }



    double
    SpencePartialSlip::regular_stick_integral(const double xi) const
    {
      const double w = std::asin(std::min(xi / k, 1.));
      if (w >= nodes.back())
        return 0.;
      if (w < nodes.front())
        {
          // Below the first node the integrand is c/w, c = X_g'(0)/k.
          const double c = stick_integrand(nodes.front()) * nodes.front();
          return integral_at_nodes.front() + c * std::log(nodes.front() / w);
        }
      const unsigned int j =
        std::upper_bound(nodes.begin(), nodes.end(), w) - nodes.begin();
      return integral_at_nodes[j] +
             kronrod_integral([this](
                                const double v) { return stick_integrand(v); },
                              w,
                              nodes[j]);
    }



    double
    SpencePartialSlip::normalized_traction(const double xi) const
    {
      if (mu == 0. || beta == 0. || xi >= 1.)
        return 0.;
      const double slip_value = mu * std::sqrt((1. - xi) * (1. + xi));
      if (xi >= k)
        return slip_value;
      if (xi == 0.)
        return 0.;
      // Contribution of X_s = -(2 mu/pi) acos(u/k), in closed form:
      // xi int_xi^k X_s/u^2 du = -(2 mu/pi) [acos(r) - r ln((1+s)/r)],
      // r = xi/k, s = sqrt(1-r^2).
      const double r = xi / k;
      const double s = std::sqrt((1. - r) * (1. + r));
      const double singular_part =
        -2. * mu / PI * (std::acos(r) - r * std::log((1. + s) / r));
      return slip_value + singular_part + xi * regular_stick_integral(xi);
    }


    std::vector<std::pair<double, double>>
    spence_slip_table_mu01(const double a, const double radius)
    {
      // doc/references.md 1.3: S [mm] at x/a = 0, 0.1, ..., 1 for a = 6.21463
      // mm and R = 50 mm.
      const double tabulated[] = {0.,
                                  0.00024,
                                  0.00097,
                                  0.0022,
                                  0.0039,
                                  0.0058,
                                  0.0075,
                                  0.0081,
                                  0.0076,
                                  0.0049,
                                  0.};
      const double a_table = 6.21463, radius_table = 50.;
      const double scale =
        (a * a / radius) / (a_table * a_table / radius_table);
      std::vector<std::pair<double, double>> table;
      for (unsigned int i = 0; i < 11; ++i)
        table.emplace_back(0.1 * i * a, scale * tabulated[i]);
      return table;
    }
  } // namespace Analytic
} // namespace Common
