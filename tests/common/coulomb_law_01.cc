/*
 * Coulomb's friction law (common/contact/coulomb_law.h): the
 * complementarity function C(t, v, s) = t - P_B(s)(t + c v) vanishes exactly
 * on the stick and slip states and nowhere else among the sampled points;
 * the stick/slip decision and the slip direction; and the generalised
 * derivative against central finite differences in 2D and 3D, at stick and
 * slip points away from the kink |t + c v| = s (pass: relative difference
 * below 1e-6); and the Newton step of a slipping point in the form the
 * condensed enforcement imposes (traction direction and turning stiffness)
 * against the step the generalised derivative gives (pass: 1e-12 relative
 * to the slip bound).
 */

#include <common/contact/coulomb_law.h>

#include "../tests.h"

#include <deal.II/base/tensor.h>

#include <cmath>
#include <string>
#include <vector>

using namespace dealii;
namespace Law = Common::Contact::CoulombLaw;

namespace
{
  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }

  /** A vector of the tangent plane of the normal e_last. */
  template <int dim>
  Tensor<1, dim>
  tangential(const double a, const double b)
  {
    Tensor<1, dim> x;
    x[0] = a;
    if (dim == 3)
      x[1] = b;
    return x;
  }

  /** Largest relative deviation of the analytic derivative from central
   * differences, perturbing each tangential component of t, v and s. */
  template <int dim>
  double
  derivative_error(const Tensor<1, dim> &t,
                   const Tensor<1, dim> &v,
                   const double          s,
                   const double          c)
  {
    const auto   J     = Law::complementarity_jacobian(t, v, s, c);
    const double h     = 1e-6;
    double       error = 0., scale = 1.;
    for (unsigned int k = 0; k < dim - 1; ++k)
      {
        Tensor<1, dim> e;
        e[k] = 1.;
        const Tensor<1, dim> dC_dt =
          (Law::complementarity(t + h * e, v, s, c) -
           Law::complementarity(t - h * e, v, s, c)) /
          (2. * h);
        const Tensor<1, dim> dC_dv =
          (Law::complementarity(t, v + (h / c) * e, s, c) -
           Law::complementarity(t, v - (h / c) * e, s, c)) /
          (2. * h / c);
        for (unsigned int i = 0; i < dim - 1; ++i)
          {
            error = std::max(error, std::abs(dC_dt[i] - J.d_traction[i][k]));
            error = std::max(error,
                             std::abs(dC_dv[i] - J.d_slip_increment[i][k]) / c);
          }
      }
    const Tensor<1, dim> dC_ds = (Law::complementarity(t, v, s + h, c) -
                                  Law::complementarity(t, v, s - h, c)) /
                                 (2. * h);
    for (unsigned int i = 0; i < dim - 1; ++i)
      error = std::max(error, std::abs(dC_ds[i] - J.d_slip_bound[i]));
    return error / scale;
  }

  /** Largest deviation, relative to s, of the Newton iterate
   * t+ = t + dt (dt from C + C_t dt + C_v dv + C_s ds = 0 with the
   * derivatives of complementarity_jacobian()) from the form
   * slip_linearisation() states: t+.e = s + ds and
   * t+.e_perp = k (v + dv).e_perp across e. */
  template <int dim>
  double
  slip_step_error(const Tensor<1, dim> &t,
                  const Tensor<1, dim> &v,
                  const double          s,
                  const double          c,
                  const Tensor<1, dim> &dv,
                  const double          ds)
  {
    if (Law::is_sticking(t, v, s, c))
      return 1.; // the sample must slip
    const auto            J      = Law::complementarity_jacobian(t, v, s, c);
    const auto            step   = Law::slip_linearisation(t, v, s, c);
    const Tensor<1, dim>  rhs    = -(Law::complementarity(t, v, s, c) +
                                 J.d_slip_increment * dv + J.d_slip_bound * ds);
    const Tensor<1, dim>  t_next = t + invert(J.d_traction) * rhs;
    const Tensor<1, dim>  v_next = v + dv;
    const Tensor<1, dim> &e      = step.direction;
    double                error =
      std::abs(e.norm() - 1.) + std::abs(t_next * e - (s + ds)) / s;
    if (dim == 3)
      {
        Tensor<1, dim> normal;
        normal[dim - 1] = 1.;
        Tensor<1, dim> across;
        if constexpr (dim == 3)
          across = cross_product_3d(normal, e);
        error += std::abs(t_next * across -
                          step.turning_stiffness * (v_next * across)) /
                 s;
      }
    return error;
  }

  template <int dim>
  void
  check()
  {
    deallog << "dim = " << dim << std::endl;
    const double c = 1e4; // MPa/mm
    const double s = 30.; // MPa (mu p)

    // Exact states.
    const Tensor<1, dim> t_stick = tangential<dim>(12., -5.);
    const Tensor<1, dim> zero;
    const Tensor<1, dim> v_slip = tangential<dim>(2e-3, 1e-3);
    const Tensor<1, dim> t_slip = s * v_slip / v_slip.norm();
    const bool           stick_ok =
      Law::is_sticking(t_stick, zero, s, c) &&
      Law::complementarity(t_stick, zero, s, c).norm() < 1e-12 * s;
    const bool slip_ok =
      !Law::is_sticking(t_slip, v_slip, s, c) &&
      Law::complementarity(t_slip, v_slip, s, c).norm() < 1e-12 * s &&
      (Law::slip_direction(t_slip, v_slip, c) - v_slip / v_slip.norm()).norm() <
        1e-14;
    deallog << "C = 0 in stick (|t| < mu p, v = 0): " << pass_fail(stick_ok)
            << std::endl;
    deallog << "C = 0 in slip (t = mu p v/|v|): " << pass_fail(slip_ok)
            << std::endl;

    // Violations: traction above the bound, slip against the traction,
    // slip while |t| < mu p.
    const bool violations =
      Law::complementarity(2. * t_slip, v_slip, s, c).norm() > 1e-3 * s &&
      Law::complementarity(-t_slip, v_slip, s, c).norm() > 1e-3 * s &&
      Law::complementarity(t_stick, v_slip, s, c).norm() > 1e-3 * s;
    deallog << "C != 0 for violated states: " << pass_fail(violations)
            << std::endl;

    // Derivatives away from the kink.
    const double e_stick =
      derivative_error(t_stick, tangential<dim>(1e-4, -2e-4), s, c);
    const double e_slip =
      derivative_error(t_slip, tangential<dim>(3e-3, 4e-3), s, c);
    deallog << "derivative in stick matches finite differences: "
            << pass_fail(e_stick < 1e-6) << std::endl;
    deallog << "derivative in slip matches finite differences: "
            << pass_fail(e_slip < 1e-6) << std::endl;

    // The Newton step of a slipping point in the form the enforcement
    // imposes (slip_linearisation()), against the generalised derivative:
    // a point far from convergence (v at 60 degrees to t in 3D), one whose
    // slip runs against its traction, and one that has just started to
    // slip (v = 0); at a converged slip state e = v/|v| and k = s/|v|.
    {
      const Tensor<1, dim> t     = tangential<dim>(20., 10.);
      const Tensor<1, dim> v     = tangential<dim>(-1e-3, 3e-3);
      const Tensor<1, dim> dv    = tangential<dim>(4e-4, -7e-4);
      const Tensor<1, dim> v_old = -1e-4 * t / t.norm();
      const double         e_step =
        std::max({slip_step_error(t, v, 0.2 * s, c, dv, 2.),
                  slip_step_error(t, v_old, 0.2 * s, c, dv, -1.),
                  slip_step_error(2. * t, zero, s, c, dv, 0.5)});
      const auto converged = Law::slip_linearisation(t_slip, v_slip, s, c);
      const bool at_solution =
        (converged.direction - v_slip / v_slip.norm()).norm() < 1e-14 &&
        std::abs(converged.turning_stiffness * v_slip.norm() / s - 1.) < 1e-12;
      deallog << "slip step matches the generalised Newton step: "
              << pass_fail(e_step < 1e-12) << std::endl;
      deallog << "at a slip state e = v/|v| and k = s/|v|: "
              << pass_fail(at_solution) << std::endl;
    }

    // In 2D the slip derivative is the active-set form t = s e.
    if (dim == 2)
      {
        const auto J = Law::complementarity_jacobian(t_slip,
                                                     tangential<dim>(3e-3, 0.),
                                                     s,
                                                     c);
        const bool active_set_form =
          std::abs(J.d_traction[0][0] - 1.) < 1e-14 &&
          std::abs(J.d_slip_increment[0][0]) < 1e-14;
        deallog << "2D slip derivative is dC/dt = 1, dC/dv = 0: "
                << pass_fail(active_set_form) << std::endl;
      }
  }
} // namespace



int
main()
{
  initlog();
  check<2>();
  check<3>();
}
