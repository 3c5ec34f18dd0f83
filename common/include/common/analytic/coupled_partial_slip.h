/**
 * @file coupled_partial_slip.h
 * Numerical half-space reference for Hertz line contact between dissimilar
 * elastic bodies with Coulomb friction under increasing load (Spence's
 * problem), with or without the Goodman approximation: a boundary-element
 * solution on the contact line.
 *
 * Plane strain, two half-spaces with contact modulus E* and second Dundurs
 * parameter beta, cylinder radius R. With A = 2/E*, piecewise-constant
 * pressure p and tangential traction q on elements of width h, collocated at
 * the element centres, the relative normal deflection w and the relative
 * tangential displacement g are
 * \f[
 *   w(x) = -\frac{A}{\pi}\int p(\xi)\ln|x-\xi|\,d\xi
 *          - A\beta\int \tfrac12\mathrm{sgn}(x-\xi)\,q(\xi)\,d\xi,
 *   \qquad
 *   g(x) = -\frac{A}{\pi}\int q(\xi)\ln|x-\xi|\,d\xi
 *          + A\beta\int \tfrac12\mathrm{sgn}(x-\xi)\,p(\xi)\,d\xi ,
 * \f]
 * a symmetric (reciprocal) pair of operators. Contact: the gap
 * \f$x^2/(2R) - \delta + w\f$ vanishes where p > 0; friction, per load
 * increment: \f$\Delta g = 0\f$ where \f$|q| < \mu p\f$, else
 * \f$q = -\mu p\,\mathrm{sgn}(\Delta g)\f$. Symmetry (p even, q odd) halves
 * the unknowns; each increment is solved by a primal-dual active-set
 * iteration with a dense direct solver. The Goodman approximation drops the
 * effect of q on w. The sign of beta only flips q.
 *
 * Reference: D.A. Spence, J. Elasticity 5 (1975) 297-319; D.A. Hills,
 * D. Nowell, A. Sackfield, Mechanics of Elastic Contacts, 1993, ch. 2 and 7.
 */
#ifndef common_analytic_coupled_partial_slip_h
#define common_analytic_coupled_partial_slip_h

#include <vector>

namespace Common
{
  namespace Analytic
  {
    /**
     * @brief Boundary-element solution of Hertz line contact with Coulomb
     * friction between dissimilar half-spaces under increasing load.
     */
    class CoupledPartialSlip
    {
    public:
      /**
       * @brief Solve the load path from 0 to the force @p force in
       * @p n_increments equal increments.
       * @param[in] contact_modulus E* (MPa).
       * @param[in] beta Second Dundurs parameter (dimensionless).
       * @param[in] mu Friction coefficient.
       * @param[in] radius Cylinder radius R (mm).
       * @param[in] force Force per unit length of the full contact (N/mm).
       * @param[in] n_elements Elements on the half line x > 0, which covers
       * 1.25 times the Hertz half-width at full load.
       * @param[in] n_increments Load increments.
       * @param[in] goodman If true, neglect the effect of q on the pressure.
       */
      CoupledPartialSlip(const double       contact_modulus,
                         const double       beta,
                         const double       mu,
                         const double       radius,
                         const double       force,
                         const unsigned int n_elements,
                         const unsigned int n_increments,
                         const bool         goodman);

      /** @brief Contact half-width at full load: the outer edge of the last
       * loaded element (mm). */
      double
      half_width() const;

      /** @brief Stick-zone half-width at full load: midway between the
       * centres of the last sticking element of the central run and the
       * next one (mm). */
      double
      stick_half_width() const;

      /** @brief Pressure of the element at the centre (MPa). */
      double
      centre_pressure() const;

      /** @brief Largest |q| at full load (MPa). */
      double
      peak_tangential_traction() const;

      /** @brief True if every increment's active set converged. */
      bool
      converged() const;

    private:
      double              h;
      std::vector<double> x;
      std::vector<double> p;
      std::vector<double> q;
      std::vector<int>    status; // 0 open, 1 stick, 2 slip
      bool                all_converged;
    };
  } // namespace Analytic
} // namespace Common

#endif
