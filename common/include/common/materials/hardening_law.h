/**
 * @file hardening_law.h
 * Isotropic hardening laws of rate-independent von Mises plasticity: the
 * flow stress as a function of the equivalent plastic strain, evaluable
 * at a point without a mesh.
 */
#ifndef common_materials_hardening_law_h
#define common_materials_hardening_law_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace Materials
  {
    /** The form of the flow stress curve. */
    enum class HardeningType
    {
      /** \f$\sigma_y + H\bar\varepsilon_p\f$. */
      linear,
      /** Swift: \f$K(\varepsilon_0 + \bar\varepsilon_p)^n\f$ with
       * \f$\varepsilon_0 = (\sigma_y/K)^{1/n}\f$, so that the curve starts
       * at the yield stress. */
      swift,
      /** Hollomon in the total uniaxial strain with an explicit initial
       * yield stress: \f$\sigma = \max(\sigma_y, K(\bar\varepsilon_p +
       * \sigma/E)^n)\f$ (a plateau at \f$\sigma_y\f$ until the power curve
       * reaches it). */
      power_law_with_yield,
      /** Piecewise linear through a table of (plastic strain, stress),
       * continued with the slope of its last segment. */
      tabulated
    };

    /**
     * @brief Parameters of a hardening law, read from a material
     * subsection.
     */
    struct HardeningParameters
    {
      /** @brief Declare "Hardening law", "Yield stress", "Hardening
       * modulus", "Strength coefficient", "Hardening exponent" and
       * "Hardening table" in the current subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read and check the entries of the current subsection.
       * @param[in] youngs_modulus E (MPa), which the power law with an
       * explicit yield stress needs.
       * @param[in] subsection Name for the error messages.
       * Throws a one-line message naming the entry on a bad value. */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const double              youngs_modulus,
                       const std::string        &subsection);

      HardeningType type = HardeningType::linear;
      /** Initial yield stress (MPa). */
      double yield_stress = 0.;
      /** Linear hardening modulus H (MPa). */
      double hardening_modulus = 0.;
      /** Strength coefficient K (MPa) of the Swift and power laws. */
      double strength_coefficient = 0.;
      /** Hardening exponent n (dimensionless, >= 0). */
      double exponent = 0.;
      /** Young's modulus E (MPa), for the power law with yield. */
      double youngs_modulus = 0.;
      /** Table of (equivalent plastic strain, flow stress (MPa)). */
      std::vector<std::pair<double, double>> table;
    };

    /**
     * @brief Flow stress \f$\sigma_f(\bar\varepsilon_p)\f$ and its slope.
     */
    class HardeningLaw
    {
    public:
      /** @brief The law with the given parameters; throws a one-line
       * message when they are inconsistent (a negative exponent, a yield
       * stress below the start of the power curve, a table that does not
       * start at zero plastic strain or whose stress decreases). */
      explicit HardeningLaw(const HardeningParameters &parameters);

      /** @brief Flow stress (MPa) at the equivalent plastic strain
       * @p plastic_strain (>= 0). */
      double
      flow_stress(const double plastic_strain) const;

      /** @brief Slope \f$d\sigma_f/d\bar\varepsilon_p\f$ (MPa). */
      double
      slope(const double plastic_strain) const;

      /** @brief Flow stress and slope together. */
      std::pair<double, double>
      evaluate(const double plastic_strain) const;

      /** @brief The initial yield stress (MPa). */
      double
      initial_yield_stress() const;

      /** @brief The parameters. */
      const HardeningParameters &
      parameters() const;

    private:
      HardeningParameters data;
      /** Swift prestrain (dimensionless). */
      double swift_prestrain = 0.;
    };
  } // namespace Materials
} // namespace Common

#endif
