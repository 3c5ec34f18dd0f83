/**
 * @file spence.h
 * Spence's partial-slip solution of a Hertz line contact between dissimilar
 * elastic half-spaces under monotonically increasing normal load, in the
 * Goodman approximation (the shear traction does not change the pressure).
 * Reference values only: stick-zone size, tangential traction and the
 * frictionless slip; no mesh, no solver. The Hertz data (a, p0, R) come
 * from HertzLineContact or from the caller.
 *
 * References: D.A. Spence, Proc. Camb. Phil. Soc. 73 (1973) 249-268 and
 * J. Elasticity 5 (1975) 297-319; K.L. Johnson, Contact Mechanics, CUP 1985,
 * sec. 5.4; derivation and reference table in doc/references.md, sec. 1.3.
 */
#ifndef common_analytic_spence_h
#define common_analytic_spence_h

#include <utility>
#include <vector>

namespace Common
{
  namespace Analytic
  {
    /**
     * @brief Complete elliptic integral of the first kind,
     * \f$K(k) = \int_0^{\pi/2} (1 - k^2\sin^2\theta)^{-1/2}\,d\theta\f$,
     * as a function of the modulus @p k (not of the parameter \f$m = k^2\f$;
     * the same convention as std::comp_ellint_1). Computed with the
     * arithmetic-geometric mean, \f$K = \pi / (2\,\mathrm{AGM}(1, k'))\f$,
     * \f$k' = \sqrt{1-k^2}\f$, to full double precision.
     *
     * @param[in] k Modulus, \f$|k| \le 1\f$; throws for \f$|k| > 1\f$.
     * @return K(k), dimensionless; +infinity for \f$|k| = 1\f$.
     */
    double
    complete_elliptic_k(const double k);

    /**
     * @brief Stick-zone ratio \f$k = c/a\f$ of Spence's problem: the root of
     * \f$|\beta|/\mu = K'(k)/K(k)\f$, \f$K'(k) = K(\sqrt{1-k^2})\f$.
     *
     * The equation is solved in closed form: \f$K'/K = |\beta|/\mu\f$ fixes
     * the nome \f$q = e^{-\pi|\beta|/\mu}\f$, and
     * \f$k = \vartheta_2^2(q)/\vartheta_3^2(q)\f$ (Jacobi theta functions);
     * for \f$|\beta|/\mu < 1\f$ the complementary nome
     * \f$e^{-\pi\mu/|\beta|}\f$ and \f$k = \vartheta_4^2/\vartheta_3^2\f$ are
     * used, so that the series always converge fast. Only \f$|\beta|\f$
     * enters: the sign of beta follows the order of the bodies.
     *
     * @param[in] beta Second Dundurs parameter (plane strain), any sign.
     * @param[in] mu Coulomb friction coefficient, \f$\mu \ge 0\f$; throws
     * for \f$\mu < 0\f$.
     * @return c/a in [0, 1], dimensionless. Special cases: 1 (full stick)
     * if beta = 0, whatever mu (nothing drives slip); 0 (full slip) if
     * mu = 0 and beta != 0. Underflows to 0 for \f$|\beta|/\mu > 450\f$ and
     * rounds to 1 for \f$|\beta|/\mu < 0.082\f$.
     */
    double
    spence_stick_ratio(const double beta, const double mu);

    /**
     * @brief Slip accumulated in contact under increasing load for
     * \f$|\beta| = 1/7\f$ and \f$\mu = 0.1\f$, tabulated in doc/references.md
     * 1.3 from a quadrature of Spence's solution (+-5 %) for a = 6.21463 mm,
     * R = 50 mm, and scaled to other loads and radii by
     * \f$S \propto a^2/R\f$ (the solution is self-similar).
     * @param[in] a Contact half-width (mm).
     * @param[in] radius Cylinder radius R (mm).
     * @return Pairs (x, S) for x/a = 0, 0.1, ..., 1 (mm, mm).
     */
    std::vector<std::pair<double, double>>
    spence_slip_table_mu01(const double a, const double radius);

    /**
     * @brief Partial slip of a Hertz line contact between dissimilar
     * elastic bodies under monotonically increasing normal load (Spence
     * 1973/1975), Goodman approximation, half-space theory.
     *
     * Coordinates: x (mm) from the centre of the contact, \f$\xi = x/a\f$,
     * \f$k = c/a\f$. Pressure \f$p = p_0\sqrt{1-\xi^2}\f$. The stick zone
     * \f$|x| < c\f$ is self-similar (it grows in proportion to a), with
     * \f$|\beta|/\mu = K'(k)/K(k)\f$. Tangential traction at the final load,
     * for \f$x \ge 0\f$:
     * \f[
     *   q/p_0 = \mu\sqrt{1-\xi^2} \quad (k \le \xi \le 1),\qquad
     *   q/p_0 = \mu\sqrt{1-\xi^2} + \xi\int_\xi^k X(u)\,u^{-2}\,du
     *   \quad (0 \le \xi < k),
     * \f]
     * where X is the bounded solution on (-k, k) of
     * \f$\frac{1}{\pi}\,\mathrm{PV}\!\int_{-k}^{k} X(u)/(\xi-u)\,du =
     * f(\xi)\f$, \f$f = -|\beta|/\sqrt{1-\xi^2} - \mu H_S(\xi)\f$,
     * \f$H_S = -\frac{2}{\pi b}\ln\frac{1+b}{|\xi|}\f$,
     * \f$b = \sqrt{1-\xi^2}\f$ (doc/references.md sec. 1.3, read with these
     * signs; they reproduce its table). X is odd and jumps at the origin:
     * the part \f$-\frac{2\mu}{\pi}\ln|t|\f$ of f gives exactly
     * \f$X = -\frac{2\mu}{\pi}\arccos(\xi/k)\f$ for \f$\xi > 0\f$
     * (\f$X(0^+) = -\mu\f$, which cancels the jump of
     * \f$\mu\,\mathrm{sgn}(x)\dot p\f$, so q is continuous and q(0) = 0),
     * and its contribution to q is integrated in closed form. The
     * remainder of X, continuous and O(u) at the origin, is computed by
     * adaptive Gauss-Kronrod quadrature after the substitution
     * \f$t = k\cos\theta\f$ and the subtraction of the singularity, and
     * its \f$\int X/u^2\f$ is tabulated in the constructor. Relative
     * accuracy of q: about 1e-13 for \f$|\beta|/\mu \ge 0.3\f$
     * (checked against a 20-digit mpmath evaluation of the formula above),
     * 1e-10 at \f$|\beta|/\mu = 0.2\f$ (c/a = 0.999999), a few 1e-9 at
     * 0.12.
     *
     * Signs: all results are given for \f$x > 0\f$ as magnitudes computed
     * with \f$|\beta|\f$ and are odd in x. The direction follows
     * doc/references.md sec. 1.2: without friction the softer surface slips
     * toward the centre relative to the stiffer one; with friction the
     * traction on the softer body points away from the centre.
     *
     * Limitations: Goodman approximation (the fully coupled solution
     * differs by O(beta mu)); half-spaces; loading from zero in many small
     * increments (the one-increment answer differs, doc/references.md
     * sec. 1.4).
     */
    class SpencePartialSlip
    {
    public:
      /**
       * @brief Set up the solution, tabulate the stick-zone integral and
       * locate the peak of q (5 to 40 ms).
       *
       * @param[in] half_width Hertz half-width a (mm), > 0.
       * @param[in] peak_pressure Hertz peak pressure p0 (MPa), >= 0.
       * @param[in] radius Relative radius of curvature R (mm), > 0; then
       * \f$E^* = 2Rp_0/a\f$.
       * @param[in] beta Second Dundurs parameter (plane strain); only its
       * magnitude is used.
       * @param[in] mu Coulomb friction coefficient, >= 0.
       *
       * Throws if an argument is out of range. If \f$\beta \ne 0\f$,
       * \f$\mu > 0\f$ and c/a rounds to 1 (\f$|\beta|/\mu < 0.082\f$),
       * the stick zone fills the contact in double precision and the
       * traction is not available (has_traction() is false). With beta = 0
       * or mu = 0 the tangential traction is identically zero.
       */
      SpencePartialSlip(const double half_width,
                        const double peak_pressure,
                        const double radius,
                        const double beta,
                        const double mu);

      /**
       * @brief Whether tangential_traction() and
       * peak_tangential_traction() are available: false only if c/a rounds
       * to 1 with beta != 0 and mu > 0 (the stick zone fills the contact in
       * double precision, and the stick-zone integral degenerates).
       */
      bool
      has_traction() const;

      /** @brief Stick-zone ratio c/a, dimensionless (see
       * spence_stick_ratio()). */
      double
      stick_ratio() const;

      /** @brief Half-width c of the stick zone (mm). */
      double
      stick_half_width() const;

      /** @brief Hertz pressure \f$p(x) = p_0\sqrt{1-x^2/a^2}\f$ (MPa); zero
       * for \f$|x| \ge a\f$. */
      double
      pressure(const double x) const;

      /**
       * @brief Tangential traction q(x) at the final load (MPa), magnitude
       * profile: odd in x, \f$q \ge 0\f$ for \f$x \ge 0\f$, q(0) = 0,
       * \f$q = \mu p\f$ in the slip zones \f$c \le |x| \le a\f$, zero for
       * \f$|x| \ge a\f$, and \f$q < \mu p\f$ in the stick zone. Continuous,
       * including at x = c. About 0.1 ms per call in the stick zone, 1 us
       * outside it. Throws if has_traction() is false.
       *
       * @param[in] x Distance from the centre of the contact (mm).
       */
      double
      tangential_traction(const double x) const;

      /**
       * @brief Maximum of q over the contact (MPa), found numerically. It
       * lies inside the stick zone, not at x = c: q/(mu p) approaches 1 at c
       * with zero slope while mu p decreases (for beta = 1/7, mu = 0.1:
       * 328.31 MPa at x = 0.394 a, whereas q(c) = mu p(c) = 327.69 MPa, at
       * c = 0.406 a). For a small stick zone the peak is practically at c;
       * for c/a close to 1 it moves inward (x = 0.70 a for
       * |beta|/mu = 0.5). mu p0 for full slip (c = 0); zero if the traction
       * vanishes identically. Throws if has_traction() is false.
       */
      double
      peak_tangential_traction() const;

      /** @brief Position x >= 0 of peak_tangential_traction() (mm). */
      double
      peak_tangential_traction_position() const;

      /**
       * @brief Frictionless (mu = 0) slip accumulated while in contact
       * (mm):
       * \f$S_0(x) = \frac{|\beta|}{2R}\left[a^2\arcsin\frac{x}{a} +
       * x\sqrt{a^2-x^2} - \frac{\pi x^2}{2}\right]\f$ for \f$|x| \le a\f$.
       * Odd in x, zero at 0 and at \f$\pm a\f$; defined only in contact, so
       * 0 is returned for \f$|x| > a\f$. Independent of mu and of the load
       * path.
       *
       * @param[in] x Distance from the centre of the contact (mm).
       */
      double
      frictionless_slip(const double x) const;

      /**
       * @brief Frictionless (mu = 0) total relative tangential displacement
       * of the two surfaces (mm):
       * \f$g_0(x) = \frac{2|\beta|}{E^*}p_0\left[\frac{x}{2}
       * \sqrt{1-x^2/a^2} + \frac{a}{2}\arcsin\frac{x}{a}\right]\f$ for
       * \f$|x| \le a\f$, with \f$g_0(a) = |\beta|P/E^*\f$,
       * \f$P = \pi a p_0/2\f$. Odd in x; \f$g_0(a)\,\mathrm{sgn}(x)\f$ is
       * returned for \f$|x| > a\f$ (the in-plane surface displacement
       * outside a line contact is not bounded in a half-space; the
       * constant is the value where the two surfaces separate).
       *
       * @param[in] x Distance from the centre of the contact (mm).
       */
      double
      frictionless_relative_displacement(const double x) const;

    private:
      /**
       * The even function \f$g = f + \frac{2\mu}{\pi}\ln|t|\f$ (f of the
       * class documentation), continuous at t = 0, in units of
       * \f$E^{*}/(2R)\f$, and its derivative.
       */
      double
      regular_load(const double t) const;
      double
      regular_load_derivative(const double t) const;

      /**
       * The part of X(u) produced by regular_load(), for 0 < u < k: the
       * finite Hilbert inversion evaluated by adaptive quadrature.
       */
      double
      regular_stick_density(const double u) const;

      /** Integrand of \f$\int X_g(u)/u^2 du\f$ after \f$u = k\sin w\f$. */
      double
      stick_integrand(const double w) const;

      /** \f$\int_{\xi}^{k} X_g(u)/u^2\,du\f$ for \f$0 < \xi < k\f$. */
      double
      regular_stick_integral(const double xi) const;

      /** q/p0 at \f$\xi = x/a \ge 0\f$. */
      double
      normalized_traction(const double xi) const;

      double a;
      double p0;
      double radius;
      double beta;
      double mu;
      double k;
      /** False if the stick zone fills the contact (has_traction()). */
      bool traction_available;

      /**
       * Nodes \f$w_j\f$ (increasing) of the variable \f$u = k\sin w\f$ and
       * \f$\int_{w_j}^{\pi/2}\f$ of stick_integrand() at them.
       */
      std::vector<double> nodes;
      std::vector<double> integral_at_nodes;

      double peak_traction;
      double peak_position;
    };
  } // namespace Analytic
} // namespace Common

#endif
