/**
 * @file normal_contact_law.h
 * Normal contact laws as pure functions of (pressure, gap): the
 * complementarity function of the semismooth Newton method and the penalty
 * law. No mesh, no state. Sign convention: gap > 0 open, pressure >= 0.
 *
 * Reference: S. Hueeber, B. Wohlmuth, CMAME 194 (2005) 3147-3166;
 * A. Popp et al., IJNME 83 (2010) 1428-1465.
 */
#ifndef common_contact_normal_contact_law_h
#define common_contact_normal_contact_law_h

namespace Common
{
  namespace Contact
  {
    namespace NormalContactLaw
    {
      /**
       * @brief Active-set rule of the semismooth Newton method:
       * a point is active (closed) if \f$\lambda - c\,g > 0\f$.
       * @param[in] pressure Normal pressure lambda (MPa).
       * @param[in] gap Normal gap g (mm), negative when penetrating.
       * @param[in] c Complementarity constant (MPa/mm), > 0.
       */
      bool
      is_active(const double pressure, const double gap, const double c);

      /**
       * @brief Complementarity function
       * \f$C(\lambda, g) = \lambda - \max(0, \lambda - c\,g)\f$ (MPa), zero
       * exactly when \f$g \ge 0,\ \lambda \ge 0,\ \lambda g = 0\f$.
       */
      double
      complementarity(const double pressure, const double gap, const double c);

      /**
       * @brief Penalty law \f$\lambda = \epsilon \max(0, -g)\f$ (MPa).
       * @param[in] stiffness Penalty stiffness epsilon (MPa/mm).
       */
      double
      penalty_pressure(const double gap, const double stiffness);

      /**
       * @brief Derivative of the penalty pressure with respect to the gap
       * (MPa/mm): \f$-\epsilon\f$ if penetrating or touching, else 0.
       * Touching (g = 0) counts as active, so that a body that only touches
       * is held at the first iteration.
       */
      double
      penalty_derivative(const double gap, const double stiffness);
    } // namespace NormalContactLaw
  }   // namespace Contact
} // namespace Common

#endif
