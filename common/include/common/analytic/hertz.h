/**
 * @file hertz.h
 * Hertz line contact (two parallel cylinders or a cylinder on a half-space,
 * plane strain). Closed-form reference values only: no mesh, no solver.
 *
 * Reference: K.L. Johnson, Contact Mechanics, CUP 1985, ch. 4 and 5.
 */
#ifndef common_analytic_hertz_h
#define common_analytic_hertz_h

namespace Common
{
  namespace Analytic
  {
    /**
     * @brief Hertz solution of an elastic cylinder of radius @p R pressed
     * onto an elastic half-space by a force @p P per unit length, plane
     * strain.
     *
     * \f$1/E^* = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2\f$,
     * \f$a = \sqrt{4PR/(\pi E^*)}\f$, \f$p_0 = 2P/(\pi a)\f$,
     * \f$p(x) = p_0\sqrt{1-x^2/a^2}\f$.
     */
    class HertzLineContact
    {
    public:
      /**
       * @param[in] youngs_modulus_1 Young's modulus of body 1 (MPa).
       * @param[in] poisson_ratio_1 Poisson's ratio of body 1.
       * @param[in] youngs_modulus_2 Young's modulus of body 2 (MPa).
       * @param[in] poisson_ratio_2 Poisson's ratio of body 2.
       * @param[in] radius Relative radius of curvature R (mm).
       * @param[in] force_per_length Total normal force per unit length of
       * the full contact (N/mm), not of a symmetry half.
       */
      HertzLineContact(const double youngs_modulus_1,
                       const double poisson_ratio_1,
                       const double youngs_modulus_2,
                       const double poisson_ratio_2,
                       const double radius,
                       const double force_per_length);

      /** @brief Plane-strain contact modulus E* (MPa). */
      double
      contact_modulus() const;

      /** @brief Contact half-width a (mm). */
      double
      half_width() const;

      /** @brief Peak pressure p0 (MPa). */
      double
      peak_pressure() const;

      /** @brief Pressure p(x) at distance @p x from the centre (MPa); zero
       * outside the contact. */
      double
      pressure(const double x) const;

      /**
       * @brief Second Dundurs parameter beta (plane strain), body 1 relative
       * to body 2. Dimensionless; its sign follows the order of the bodies.
       */
      double
      dundurs_beta() const;

    private:
      double youngs_modulus_1, poisson_ratio_1;
      double youngs_modulus_2, poisson_ratio_2;
      double e_star;
      double a;
      double p0;
    };
  } // namespace Analytic
} // namespace Common

#endif
