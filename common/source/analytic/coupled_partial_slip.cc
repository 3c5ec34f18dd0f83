#include <common/analytic/coupled_partial_slip.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

namespace Common
{
  namespace Analytic
  {
    using namespace dealii;

    namespace
    {
      /** int_a^b ln|x - xi| dxi. */
      double
      log_integral(const double x, const double a, const double b)
      {
        const auto F = [](const double t) {
          return t == 0. ? 0. : t * std::log(std::abs(t)) - t;
        };
        return F(x - a) - F(x - b);
      }

      /** int_a^b sgn(x - xi)/2 dxi. */
      double
      sign_integral(const double x, const double a, const double b)
      {
        if (x >= b)
          return 0.5 * (b - a);
        if (x <= a)
          return -0.5 * (b - a);
        return 0.5 * ((x - a) - (b - x));
      }

      enum Status
      {
        open  = 0,
        stick = 1,
        slip  = 2
      };
    } // namespace



    CoupledPartialSlip::CoupledPartialSlip(const double       contact_modulus,
                                           const double       beta,
                                           const double       mu,
                                           const double       radius,
                                           const double       force,
                                           const unsigned int n_elements,
                                           const unsigned int n_increments,
                                           const bool         goodman)
      : all_converged(true)
    {
      AssertThrow(contact_modulus > 0. && radius > 0. && force > 0. &&
                    mu >= 0. && n_elements > 1 && n_increments > 0,
                  ExcMessage("CoupledPartialSlip: invalid arguments."));
      const unsigned int n = n_elements;
      const double       A = 2. / contact_modulus;
      const double       a_hertz =
        std::sqrt(4. * force * radius / (numbers::PI * contact_modulus));
      h = 1.25 * a_hertz / n;
      x.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = (i + 0.5) * h;

      // Influence of element j and its mirror (p even, q odd) at x_i.
      FullMatrix<double> Wp(n, n), Wq(n, n), Gq(n, n), Gp(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const double l = j * h, r = (j + 1) * h;
            const double L_plus  = log_integral(x[i], l, r);
            const double L_minus = log_integral(x[i], -r, -l);
            const double S_plus  = sign_integral(x[i], l, r);
            const double S_minus = sign_integral(x[i], -r, -l);
            Wp(i, j)             = -A / numbers::PI * (L_plus + L_minus);
            Wq(i, j) = goodman ? 0. : -A * beta * (S_plus - S_minus);
            Gq(i, j) = -A / numbers::PI * (L_plus - L_minus);
            Gp(i, j) = A * beta * (S_plus + S_minus);
          }

      p.assign(n, 0.);
      q.assign(n, 0.);
      status.assign(n, open);
      status[0] = (mu > 0. ? stick : slip);
      std::vector<double> g_old(n, 0.), sense(n, 1.);
      const unsigned int  size = 2 * n + 1;

      for (unsigned int k = 1; k <= n_increments; ++k)
        {
          const double load      = force * k / n_increments;
          bool         converged = false;
          for (unsigned int iteration = 0; iteration < 200 && !converged;
               ++iteration)
            {
              // Unknowns: p (0..n-1), q (n..2n-1), delta (2n).
              LAPACKFullMatrix<double> M(size, size);
              Vector<double>           rhs(size);
              for (unsigned int i = 0; i < n; ++i)
                {
                  if (status[i] == open)
                    M(i, i) = 1.;
                  else
                    {
                      for (unsigned int j = 0; j < n; ++j)
                        {
                          M(i, j)     = Wp(i, j);
                          M(i, n + j) = Wq(i, j);
                        }
                      M(i, 2 * n) = -1.;
                      rhs(i)      = -x[i] * x[i] / (2. * radius);
                    }
                  const unsigned int row = n + i;
                  if (status[i] == stick)
                    {
                      for (unsigned int j = 0; j < n; ++j)
                        {
                          M(row, n + j) = Gq(i, j);
                          M(row, j)     = Gp(i, j);
                        }
                      rhs(row) = g_old[i];
                    }
                  else
                    {
                      // Open: q = 0; slip: q + mu sense p = 0.
                      M(row, n + i) = 1.;
                      if (status[i] == slip)
                        M(row, i) = mu * sense[i];
                    }
                  M(2 * n, i) = 2. * h;
                }
              rhs(2 * n) = load;
              M.compute_lu_factorization();
              M.solve(rhs);
              for (unsigned int i = 0; i < n; ++i)
                {
                  p[i] = rhs(i);
                  q[i] = rhs(n + i);
                }
              const double delta = rhs(2 * n);

              // Active-set update.
              converged = true;
              for (unsigned int i = 0; i < n; ++i)
                {
                  double w = 0., g = 0.;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      w += Wp(i, j) * p[j] + Wq(i, j) * q[j];
                      g += Gq(i, j) * q[j] + Gp(i, j) * p[j];
                    }
                  const double gap  = x[i] * x[i] / (2. * radius) - delta + w;
                  int          next = status[i];
                  if (status[i] == open)
                    {
                      if (gap < 0.)
                        next = (mu > 0. ? stick : slip);
                    }
                  else if (p[i] < 0.)
                    next = open;
                  else if (mu > 0. && status[i] == stick &&
                           std::abs(q[i]) > mu * p[i])
                    {
                      next     = slip;
                      sense[i] = (q[i] > 0. ? -1. : 1.);
                    }
                  else if (mu > 0. && status[i] == slip &&
                           sense[i] * (g - g_old[i]) < 0.)
                    next = stick;
                  if (next != status[i])
                    {
                      status[i] = next;
                      converged = false;
                    }
                }
            }
          all_converged = all_converged && converged;
          for (unsigned int i = 0; i < n; ++i)
            {
              double g = 0.;
              for (unsigned int j = 0; j < n; ++j)
                g += Gq(i, j) * q[j] + Gp(i, j) * p[j];
              g_old[i] = g;
            }
        }
    }



    double
    CoupledPartialSlip::half_width() const
    {
      double a = 0.;
      for (unsigned int i = 0; i < x.size(); ++i)
        if (status[i] != open)
          a = x[i] + 0.5 * h;
      return a;
    }



    double
    CoupledPartialSlip::stick_half_width() const
    {
      unsigned int i = 0;
      while (i < x.size() && status[i] == stick)
        ++i;
      return i == 0 ? 0. : x[i - 1] + 0.5 * h;
    }



    double
    CoupledPartialSlip::centre_pressure() const
    {
      return p[0];
    }



    double
    CoupledPartialSlip::peak_tangential_traction() const
    {
      double peak = 0.;
      for (const double value : q)
        peak = std::max(peak, std::abs(value));
      return peak;
    }



    bool
    CoupledPartialSlip::converged() const
    {
      return all_converged;
    }
  } // namespace Analytic
} // namespace Common
