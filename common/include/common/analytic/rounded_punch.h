/**
 * @file rounded_punch.h
 * Frictionless axisymmetric flat punch with a rounded edge on an elastic
 * half-space (benchmark 2's half-space reference). The punch is flat out to
 * radius b and has an edge of radius R beyond it, approximated by a
 * parabola (adequate while a - b << R). Closed-form contact radius, approach
 * and load; the pressure as a one-dimensional integral evaluated by
 * quadrature. No mesh, no solver.
 *
 * \f[
 *   d(a) = \frac{a}{R}\left[\sqrt{a^2-b^2} - b\arccos\frac{b}{a}\right],
 *   \quad
 *   F(a) = \frac{E^*}{3R}\left[(4a^2-b^2)\sqrt{a^2-b^2}
 *          - 3a^2 b\arccos\frac{b}{a}\right],
 * \f]
 * \f[
 *   p(r) = \frac{E^*}{\pi R}\int_{\max(r,b)}^{a}
 *          \frac{2\sqrt{x^2-b^2} - b\arccos(b/x)}{\sqrt{x^2-r^2}}\,dx .
 * \f]
 * With b = 0 this is Hertz's sphere on a half-space.
 *
 * References: M. Ciavarella, Int. J. Solids Struct. 36 (1999) 4149-4181; V.L.
 * Popov, M. Hess, Method of Dimensionality Reduction, Springer 2015;
 * doc/references.md section 2.1.
 */
#ifndef common_analytic_rounded_punch_h
#define common_analytic_rounded_punch_h

#include <vector>

namespace Common
{
  namespace Analytic
  {
    /**
     * @brief Rounded flat punch on an elastic half-space, frictionless,
     * axisymmetric.
     */
    class RoundedPunchHalfSpace
    {
    public:
      /**
       * @param[in] youngs_modulus_1 Young's modulus of body 1 (MPa).
       * @param[in] poisson_ratio_1 Poisson's ratio of body 1.
       * @param[in] youngs_modulus_2 Young's modulus of body 2 (MPa).
       * @param[in] poisson_ratio_2 Poisson's ratio of body 2.
       * @param[in] flat_radius Radius b of the flat part (mm), >= 0.
       * @param[in] edge_radius Radius R of the rounded edge (mm), > 0.
       * @param[in] force Total normal force P (N), > 0.
       */
      RoundedPunchHalfSpace(const double youngs_modulus_1,
                            const double poisson_ratio_1,
                            const double youngs_modulus_2,
                            const double poisson_ratio_2,
                            const double flat_radius,
                            const double edge_radius,
                            const double force);

      /** @brief Contact modulus E* (MPa). */
      double
      contact_modulus() const;

      /** @brief Contact radius a, the root of F(a) = P (mm). */
      double
      contact_radius() const;

      /** @brief Approach d(a) of distant points of the two bodies (mm). */
      double
      approach() const;

      /** @brief Load F(a) for a contact radius @p a >= b (N). */
      double
      force_at(const double a) const;

      /** @brief Contact pressure p(r) at radius @p r >= 0 (MPa); zero for
       * r >= a. Accurate to about 1e-8 relative. */
      double
      pressure(const double r) const;

      /** @brief Mean pressure P/(pi a^2) (MPa). */
      double
      mean_pressure() const;

    private:
      /** The integrand's numerator g(x) = 2 sqrt(x^2-b^2) - b acos(b/x)
       * (mm), zero for x <= b. */
      double
      edge_profile(const double x) const;

      double e_star;
      double b;
      double R;
      double P;
      double a;
    };

    /** One radius of the FE reference curves of benchmark 2. */
    struct PunchReferencePoint
    {
      /** Radius r (mm). */
      double r;
      /** Contact pressure, MSC.Marc and Abaqus, mu = 0.1 (MPa). */
      double pressure_marc, pressure_abaqus;
      /** Tangential traction, MSC.Marc and Abaqus, mu = 0.1 (MPa). */
      double traction_marc, traction_abaqus;
    };

    /**
     * @brief The MSC.Marc and Abaqus contact curves of FENET benchmark 2
     * (NAFEMS R0094, digitised in solids4foam; doc/references.md 2.2) at the
     * tabulated radii; the peak is listed at r = 40 mm.
     */
    std::vector<PunchReferencePoint>
    fenet_punch_fe_reference();

    /** One radius of the MSC.Marc foundation-top displacements of
     * benchmark 2; NaN where the curve is not tabulated. */
    struct PunchSurfaceReferencePoint
    {
      /** Radius r (mm). */
      double r;
      /** Axial displacement u_z for mu = 0 and mu = 0.1 (mm). */
      double uz_mu0, uz_mu01;
      /** Radial displacement u_r for mu = 0 and mu = 0.1 (mm, positive
       * away from the axis). */
      double ur_mu0, ur_mu01;
    };

    /**
     * @brief The MSC.Marc displacement curves of the foundation top of
     * FENET benchmark 2 (NAFEMS R0094, digitised in solids4foam;
     * doc/references.md 2.2) at the tabulated radii, from the axis (listed at
     * r = 0.5 mm) to r = 80 mm.
     */
    std::vector<PunchSurfaceReferencePoint>
    fenet_punch_marc_surface_displacements();
  } // namespace Analytic
} // namespace Common

#endif
