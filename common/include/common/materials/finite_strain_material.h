/**
 * @file finite_strain_material.h
 * Finite-strain material laws, evaluable at a point without a mesh: the
 * Kirchhoff stress \f$\tau\f$ as a function of the deformation gradient
 * \f$F\f$ (always 3x3: plane strain has \f$F_{33} = 1\f$, axisymmetry the
 * hoop stretch there) and of the state of the last accepted step, with
 * the exact derivative \f$\partial\tau/\partial F\f$ (forward automatic
 * differentiation through the whole stress update, return mapping
 * included).
 *
 * Laws: compressible neo-Hookean; neo-Hookean with a volumetric-isochoric
 * split, nearly or exactly incompressible; Saint Venant-Kirchhoff; and
 * J2 (von Mises) elastoplasticity with the multiplicative split
 * \f$F = F_e F_p\f$, Hencky (logarithmic strain) elasticity, the
 * exponential-map return and isotropic hardening (hardening_law.h).
 */
#ifndef common_materials_finite_strain_material_h
#define common_materials_finite_strain_material_h

#include <common/materials/hardening_law.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <utility>

namespace Common
{
  namespace Materials
  {
    /**
     * @brief What a finite-strain law keeps from the last accepted step at
     * a material point.
     */
    struct MaterialPointState
    {
      /** Inverse plastic right Cauchy-Green tensor
       * \f$C_p^{-1} = F_p^{-1}F_p^{-T}\f$ (reference configuration, so
       * that a rigid rotation of the body leaves it unchanged). */
      dealii::SymmetricTensor<2, 3> plastic_metric_inverse =
        dealii::unit_symmetric_tensor<3>();
      /** Equivalent plastic strain \f$\bar\varepsilon_p\f$. */
      double equivalent_plastic_strain = 0.;
    };

    /** Which part of the stress a law returns. */
    enum class StressPart
    {
      /** The whole Kirchhoff stress. */
      full,
      /** Its deviatoric part from the isochoric deformation only (for
       * elements that take the pressure from their own field); only for
       * laws with a volumetric-isochoric split. */
      isochoric
    };

    /**
     * @brief Stress and tangent at a material point.
     */
    struct FiniteStrainResponse
    {
      /** Kirchhoff stress \f$\tau = J\sigma\f$ (MPa). */
      dealii::SymmetricTensor<2, 3> kirchhoff_stress;
      /** \f$\partial\tau_{ij}/\partial F_{kl}\f$ (MPa). */
      dealii::Tensor<4, 3> tangent;
      /** True if the step was plastic at this point. */
      bool plastic = false;
    };

    /**
     * @brief Interface of a finite-strain law.
     */
    class FiniteStrainMaterial
    {
    public:
      virtual ~FiniteStrainMaterial() = default;

      /**
       * @brief Kirchhoff stress and its derivative at the deformation
       * gradient @p F.
       * @param[in] state State of the last accepted step.
       * @param[in] part Whole stress or isochoric part.
       * @param[out] response Stress and tangent.
       * @param[out] updated_state If given, the state at @p F (to keep
       * when the step is accepted).
       */
      virtual void
      evaluate(const dealii::Tensor<2, 3> &F,
               const MaterialPointState   &state,
               const StressPart            part,
               FiniteStrainResponse       &response,
               MaterialPointState         *updated_state = nullptr) const = 0;

      /**
       * @brief The Kirchhoff stress alone at @p F: response.kirchhoff_stress
       * and response.plastic as evaluate() sets them, the tangent left as
       * it is. A law that evaluates its stress in plain numbers does so
       * here, without the derivatives; the default calls evaluate().
       */
      virtual void
      evaluate_stress(const dealii::Tensor<2, 3> &F,
                      const MaterialPointState   &state,
                      const StressPart            part,
                      FiniteStrainResponse       &response,
                      MaterialPointState         *updated_state) const;

      /** @brief True if the stress is the sum of an isochoric part and
       * a pressure \f$U'(J)\f$ from a volumetric energy \f$U(J)\f$. */
      virtual bool
      has_volumetric_split() const = 0;

      /** @brief True if the law is exactly incompressible (no volumetric
       * energy: the pressure is a Lagrange multiplier). */
      virtual bool
      is_incompressible() const;

      /** @brief \f$U'(J)\f$ and \f$U''(J)\f$ (MPa) of the volumetric
       * energy; only for compressible laws with a split. */
      virtual std::pair<double, double>
      volumetric_response(const double J) const;

      /** @brief True if the law has history (plastic state). */
      virtual bool
      has_history() const;

      /** @brief Small-strain shear modulus (MPa). */
      virtual double
      shear_modulus() const = 0;

      /** @brief Small-strain bulk modulus (MPa); infinite for an
       * incompressible law. */
      virtual double
      bulk_modulus() const = 0;
    };

    /** The finite-strain laws a parameter file can choose. */
    enum class FiniteStrainModel
    {
      /** \f$\tau = \mu(b - I) + \lambda\ln J\,I\f$. */
      neo_hookean,
      /** \f$\tau = \mu\,\mathrm{dev}(J^{-2/3}b) + J U'(J) I\f$,
       * \f$U = \frac{K}{2}(J-1)^2\f$; exactly incompressible at
       * \f$\nu = 0.5\f$. */
      neo_hookean_split,
      /** \f$S = \lambda\,\mathrm{tr}(E) I + 2\mu E\f$,
       * \f$E = \frac12(F^TF - I)\f$. */
      saint_venant_kirchhoff,
      /** Von Mises plasticity, Hencky elasticity, isotropic hardening. */
      j2_plasticity
    };

    /**
     * @brief Parameters of a finite-strain law, read from a material
     * subsection that also holds "Young's modulus" and "Poisson's ratio".
     */
    struct FiniteStrainMaterialParameters
    {
      /** @brief Declare "Finite strain model" and the hardening entries in
       * @p subsection (Young's modulus and Poisson's ratio are declared by
       * LinearElasticParameters). */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &subsection);

      /** @brief Read and check: E > 0; -1 < nu < 0.5, or nu = 0.5 for
       * the split neo-Hookean law (exactly incompressible); the hardening
       * law of J2 plasticity. One-line messages name the entry. */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &subsection);

      FiniteStrainModel model = FiniteStrainModel::neo_hookean;
      /** Young's modulus E (MPa). */
      double youngs_modulus = 0.;
      /** Poisson's ratio nu. */
      double poisson_ratio = 0.;
      /** Hardening (J2 plasticity only). */
      HardeningParameters hardening;
    };

    /** @brief The law the parameters describe. */
    std::unique_ptr<FiniteStrainMaterial>
    create_finite_strain_material(
      const FiniteStrainMaterialParameters &parameters);

    /**
     * @brief A hyperelastic law without history: evaluate() differentiates
     * the law's stress<Number>(F, part, tau) (the derived class @p Law).
     */
    template <class Law>
    class HyperelasticMaterial : public FiniteStrainMaterial
    {
    public:
      void
      evaluate(const dealii::Tensor<2, 3> &F,
               const MaterialPointState   &state,
               const StressPart            part,
               FiniteStrainResponse       &response,
               MaterialPointState *updated_state = nullptr) const override;

      void
      evaluate_stress(const dealii::Tensor<2, 3> &F,
                      const MaterialPointState   &state,
                      const StressPart            part,
                      FiniteStrainResponse       &response,
                      MaterialPointState         *updated_state) const override;
    };

    /**
     * @brief A hyperelastic law without a volumetric-isochoric split,
     * given by the Lame constants of Young's modulus and Poisson's ratio.
     */
    template <class Law>
    class CompressibleHyperelasticMaterial : public HyperelasticMaterial<Law>
    {
    public:
      /** @brief From Young's modulus (MPa) and Poisson's ratio
       * (-1 < nu < 0.5); @p name names the law in the error message. */
      CompressibleHyperelasticMaterial(const double       youngs_modulus,
                                       const double       poisson_ratio,
                                       const std::string &name);

      /** @brief False. */
      bool
      has_volumetric_split() const override;

      /** @brief mu (MPa). */
      double
      shear_modulus() const override;

      /** @brief lambda + 2 mu / 3 (MPa). */
      double
      bulk_modulus() const override;

    protected:
      double mu;
      double lambda;
    };

    /**
     * @brief Compressible neo-Hookean law,
     * \f$\tau = \mu(b - I) + \lambda\ln J\,I\f$.
     */
    class NeoHookean : public CompressibleHyperelasticMaterial<NeoHookean>
    {
    public:
      /** @brief From Young's modulus (MPa) and Poisson's ratio
       * (-1 < nu < 0.5). */
      NeoHookean(const double youngs_modulus, const double poisson_ratio);

      /** @brief The stress for any number type. */
      template <typename Number>
      void
      stress(const Number *F, const StressPart part, Number *tau) const;
    };

    /**
     * @brief Neo-Hookean law with a volumetric-isochoric split,
     * \f$\tau = \mu\,\mathrm{dev}(\bar b) + J U'(J) I\f$ with
     * \f$\bar b = J^{-2/3}b\f$ and \f$U = \frac{K}{2}(J - 1)^2\f$; at
     * \f$\nu = 0.5\f$ exactly incompressible (no U).
     */
    class NeoHookeanSplit : public HyperelasticMaterial<NeoHookeanSplit>
    {
    public:
      /** @brief From Young's modulus (MPa) and Poisson's ratio
       * (-1 < nu <= 0.5). */
      NeoHookeanSplit(const double youngs_modulus, const double poisson_ratio);

      bool
      has_volumetric_split() const override;

      bool
      is_incompressible() const override;

      std::pair<double, double>
      volumetric_response(const double J) const override;

      double
      shear_modulus() const override;

      double
      bulk_modulus() const override;

      /** @brief The stress for any number type. */
      template <typename Number>
      void
      stress(const Number *F, const StressPart part, Number *tau) const;

    private:
      double mu;
      double kappa;
      bool   incompressible;
    };

    /**
     * @brief Saint Venant-Kirchhoff law: the second Piola-Kirchhoff stress
     * is Hooke's law of the Green-Lagrange strain.
     */
    class SaintVenantKirchhoff
      : public CompressibleHyperelasticMaterial<SaintVenantKirchhoff>
    {
    public:
      /** @brief From Young's modulus (MPa) and Poisson's ratio
       * (-1 < nu < 0.5). */
      SaintVenantKirchhoff(const double youngs_modulus,
                           const double poisson_ratio);

      /** @brief The stress for any number type. */
      template <typename Number>
      void
      stress(const Number *F, const StressPart part, Number *tau) const;
    };

    /**
     * @brief J2 elastoplasticity at finite strain: \f$F = F_eF_p\f$,
     * \f$\tau = K\ln J\,I + 2G\,\mathrm{dev}\,\varepsilon_e\f$ with
     * \f$\varepsilon_e = \frac12\ln b_e\f$, von Mises yield
     * \f$\sqrt{3/2}|\mathrm{dev}\,\tau| \le \sigma_f(\bar\varepsilon_p)\f$,
     * associative isochoric flow integrated by the exponential map (the
     * radial return in logarithmic strain), and its exact algorithmic
     * tangent. The volumetric energy is \f$U = \frac{K}{2}(\ln J)^2\f$.
     */
    class J2Plasticity : public FiniteStrainMaterial
    {
    public:
      /** @brief From Young's modulus (MPa), Poisson's ratio
       * (-1 < nu < 0.5) and the hardening law. */
      J2Plasticity(const double               youngs_modulus,
                   const double               poisson_ratio,
                   const HardeningParameters &hardening);

      void
      evaluate(const dealii::Tensor<2, 3> &F,
               const MaterialPointState   &state,
               const StressPart            part,
               FiniteStrainResponse       &response,
               MaterialPointState *updated_state = nullptr) const override;

      void
      evaluate_stress(const dealii::Tensor<2, 3> &F,
                      const MaterialPointState   &state,
                      const StressPart            part,
                      FiniteStrainResponse       &response,
                      MaterialPointState         *updated_state) const override;

      bool
      has_volumetric_split() const override;

      std::pair<double, double>
      volumetric_response(const double J) const override;

      bool
      has_history() const override;

      double
      shear_modulus() const override;

      double
      bulk_modulus() const override;

      /** @brief The hardening law. */
      const HardeningLaw &
      hardening() const;

      /** @brief The stress for any number type; with @p updated_state the
       * state at @p F (from the values). Sets @p plastic. */
      template <typename Number>
      void
      stress(const Number             *F,
             const MaterialPointState &state,
             const StressPart          part,
             Number                   *tau,
             MaterialPointState       *updated_state,
             bool                     &plastic) const;

    private:
      double       G;
      double       K;
      HardeningLaw hardening_law;
    };

    /**
     * @brief Von Mises equivalent of a stress tensor,
     * \f$\sqrt{3/2}\,|\mathrm{dev}\,\sigma|\f$ (MPa).
     */
    double
    von_mises(const dealii::SymmetricTensor<2, 3> &stress);

    /**
     * @brief Matrix logarithm of a symmetric positive definite 3x3 tensor
     * (series of the inverse hyperbolic tangent, exact to round-off for any
     * such tensor).
     */
    dealii::SymmetricTensor<2, 3>
    logarithm(const dealii::SymmetricTensor<2, 3> &b);
  } // namespace Materials
} // namespace Common

#endif
