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
       * @brief Newton step of a slipping point, in the form the condensed
       * enforcement imposes: the traction direction e and the turning
       * stiffness k (MPa/mm) such that the next iterate satisfies
       * \f$t^{+} \cdot e = s^{+}\f$ and
       * \f$t^{+} \cdot e_\perp = k\, v^{+} \cdot e_\perp\f$ for every
       * tangent \f$e_\perp \perp e\f$.
       */
      template <int dim>
      struct SlipLinearisation
      {
        /** Unit direction of the traction (the trial direction). */
        dealii::Tensor<1, dim> direction;
        /** Turning stiffness k (MPa/mm); 0 where the bound vanishes. */
        double turning_stiffness = 0.;
      };

      /**
       * @brief The semismooth Newton step of complementarity() at a
       * slipping point (\f$|q| > s\f$ with \f$q = t + c\,v\f$), split
       * along e = q/|q| and across it.
       *
       * Inserting complementarity_jacobian() into
       * \f$C + C_t\,dt + C_v\,dv + C_s\,ds = 0\f$ gives, along e,
       * \f$t^{+}\cdot e = s^{+}\f$, and across it, since
       * \f$t\cdot e_\perp = -c\,v\cdot e_\perp\f$ by the definition of e,
       * \f$t^{+}\cdot e_\perp = k\,v^{+}\cdot e_\perp\f$ with
       * \f$k = c\,s/(|q| - s)\f$: the traction t of the current iterate
       * enters only through e and k, so a method that recovers t from the
       * residual needs no derivative of it. At convergence
       * (\f$t = s\,v/|v|\f$) e = v/|v| and k = s/|v|. In 2D the tangent
       * line holds e alone and k plays no part.
       *
       * Reference: S. Hueeber, G. Stadler, B. Wohlmuth, SIAM J. Sci.
       * Comput. 30 (2008) 572-596, section 3.
       * @param[in] traction Tangential traction t (MPa).
       * @param[in] slip_increment Slip increment v (mm).
       * @param[in] slip_bound s = mu p (MPa), >= 0.
       * @param[in] c Complementarity constant (MPa/mm), > 0.
       */
      template <int dim>
      SlipLinearisation<dim>
      slip_linearisation(const dealii::Tensor<1, dim> &traction,
                         const dealii::Tensor<1, dim> &slip_increment,
                         const double                  slip_bound,
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
