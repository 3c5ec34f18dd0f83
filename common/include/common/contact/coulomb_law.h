/**
 * @file coulomb_law.h
 * Coulomb's friction law as pure functions of the tangential traction,
 * the slip increment and the slip bound: the complementarity function of
 * the semismooth Newton method, its generalised derivative, and the
 * stick/slip decision. No mesh, no state.
 *
 * Conventions: the traction t is the tangential traction on the secondary
 * surface (MPa); the slip increment v is the increment of the primary
 * surface's tangential displacement relative to the secondary one in the
 * current load step (mm). Friction drags the secondary surface along, so in
 * slip t points along v. Both are vectors of the tangent plane (dim
 * components, no normal part). The slip bound is mu times the normal
 * pressure (MPa).
 *
 * Reference: S. Hueeber, G. Stadler, B. Wohlmuth, SIAM J. Sci. Comput. 30
 * (2008) 572-596; A. Gitterle et al., IJNME 84 (2010) 543-571.
 */
#ifndef common_contact_coulomb_law_h
#define common_contact_coulomb_law_h

#include <deal.II/base/tensor.h>

#include <utility>

namespace Common
{
  namespace Contact
  {
    namespace CoulombLaw
    {
      /**
       * @brief Projection of @p x onto the disc (ball) of radius
       * @p radius >= 0 about the origin.
       */
      template <int dim>
      dealii::Tensor<1, dim>
      project_onto_disc(const dealii::Tensor<1, dim> &x, const double radius);

      /**
       * @brief Complementarity function
       * \f$C = t - P_{B(s)}(t + c\,v)\f$ (MPa): zero exactly when either
       * v = 0 and |t| <= s (stick), or |t| = s and t is a non-negative
       * multiple of v (slip).
       * @param[in] traction Tangential traction t (MPa).
       * @param[in] slip_increment Slip increment v (mm).
       * @param[in] slip_bound s = mu p (MPa), >= 0.
       * @param[in] c Complementarity constant (MPa/mm), > 0.
       */
      template <int dim>
      dealii::Tensor<1, dim>
      complementarity(const dealii::Tensor<1, dim> &traction,
                      const dealii::Tensor<1, dim> &slip_increment,
                      const double                  slip_bound,
                      const double                  c);

      /**
       * @brief True if the point sticks in the next semismooth Newton
       * iteration: \f$|t + c\,v| \le s\f$. A point with zero bound and zero
       * trial traction sticks.
       */
      template <int dim>
      bool
      is_sticking(const dealii::Tensor<1, dim> &traction,
                  const dealii::Tensor<1, dim> &slip_increment,
                  const double                  slip_bound,
                  const double                  c);

      /**
       * @brief Direction of the traction of a slipping point for the next
       * iteration, \f$(t + c\,v)/|t + c\,v|\f$ (unit vector; zero if the
       * trial traction vanishes).
       */
      template <int dim>
      dealii::Tensor<1, dim>
      slip_direction(const dealii::Tensor<1, dim> &traction,
                     const dealii::Tensor<1, dim> &slip_increment,
                     const double                  c);

      /**
       * @brief Slip direction e for a slipping point's traction
       * \f$\mu\lambda e\f$ in the next iteration, and the rate
       * \f$\rho\f$ of its linearisation \f$de = \rho\,(I - e e^T)\,dv\f$
       * (1/mm).
       *
       * Where the slip increment v points along the trial
       * \f$t + c\,v\f$, e = v/|v| and \f$\rho = 1/|v|\f$: the Coulomb law
       * at convergence (traction along the slip), linearised exactly, so
       * that Newton converges quadratically also in 3D, where the
       * direction turns. Otherwise (a point that has just started to slip,
       * v = 0, or one whose slip still runs against the trial) e is the
       * trial direction slip_direction() and \f$\rho = c/|t + c\,v|\f$,
       * its derivative with t held. In 2D both give the same e.
       */
      template <int dim>
      std::pair<dealii::Tensor<1, dim>, double>
      slip_direction_and_rate(const dealii::Tensor<1, dim> &traction,
                              const dealii::Tensor<1, dim> &slip_increment,
                              const double                  c);

      /**
       * @brief Generalised derivative of complementarity() at a point
       * where it is differentiable.
       */
      template <int dim>
      struct Jacobian
      {
        /** dC/dt (dimensionless). */
        dealii::Tensor<2, dim> d_traction;
        /** dC/dv (MPa/mm). */
        dealii::Tensor<2, dim> d_slip_increment;
        /** dC/ds (dimensionless). */
        dealii::Tensor<1, dim> d_slip_bound;
      };

      /**
       * @brief The derivative of complementarity(). Stick: dC/dt = 0,
       * dC/dv = -c I. Slip: dC/dt = I - (s/|q|)(I - e e^T) with q = t + c v
       * and e = q/|q|, dC/dv = -c (s/|q|)(I - e e^T), dC/ds = -e. In 2D,
       * on the tangent line, the slip case reduces to t = s e with e fixed:
       * the Newton step of the active-set form used by the enforcement.
       */
      template <int dim>
      Jacobian<dim>
      complementarity_jacobian(const dealii::Tensor<1, dim> &traction,
                               const dealii::Tensor<1, dim> &slip_increment,
                               const double                  slip_bound,
                               const double                  c);
    } // namespace CoulombLaw
  }   // namespace Contact
} // namespace Common

#endif
