/**
 * @file linear_elastic.h
 * Small-strain isotropic Hooke law, evaluable at a point without a mesh.
 * In 2D the law is the plane-strain one (the 2D strain tensor with
 * epsilon_zz = 0). No history, no contact.
 */
#ifndef common_materials_linear_elastic_h
#define common_materials_linear_elastic_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace Materials
  {
    /**
     * @brief Parameters of one linear elastic body, read from a named
     * subsection (e.g. "Roller material").
     */
    struct LinearElasticParameters
    {
      /** @brief Declare "Young's modulus" and "Poisson's ratio" in the
       * subsection @p subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &subsection);

      /** @brief Read and check (E > 0, -1 < nu < 0.5). */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &subsection);

      /** Young's modulus E (MPa). */
      double youngs_modulus;
      /** Poisson's ratio nu (dimensionless). */
      double poisson_ratio;
    };

    /**
     * @brief Isotropic linear elasticity,
     * \f$\sigma = \lambda\,\mathrm{tr}(\varepsilon) I + 2\mu\varepsilon\f$.
     */
    template <int dim>
    class LinearElastic
    {
    public:
      /** @brief Law with the given parameters (checked on construction). */
      explicit LinearElastic(const LinearElasticParameters &parameters);

      /** @brief Stress (MPa) for the small strain @p strain. */
      dealii::SymmetricTensor<2, dim>
      stress(const dealii::SymmetricTensor<2, dim> &strain) const;

      /** @brief Constant tangent \f$\partial\sigma/\partial\varepsilon\f$
       * (MPa). */
      const dealii::SymmetricTensor<4, dim> &
      tangent() const;

      /** @brief Young's modulus (MPa). */
      double
      youngs_modulus() const;

      /** @brief Poisson's ratio. */
      double
      poisson_ratio() const;

      /** @brief First Lame parameter lambda (MPa). */
      double
      lame_lambda() const;

      /** @brief Shear modulus mu (MPa). */
      double
      lame_mu() const;

    private:
      LinearElasticParameters         parameters;
      double                          lambda;
      double                          mu;
      dealii::SymmetricTensor<4, dim> stiffness;
    };

    /**
     * @brief The law of each body, by material id: the map a solid
     * operator takes, from (material id, parameters) pairs.
     */
    template <int dim>
    std::map<dealii::types::material_id, LinearElastic<dim>>
    linear_elastic_materials(
      const std::vector<std::pair<dealii::types::material_id,
                                  LinearElasticParameters>> &bodies);
  } // namespace Materials
} // namespace Common

#endif
