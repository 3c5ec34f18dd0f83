#include <common/io/parameter_values.h>
#include <common/materials/linear_elastic.h>

#include <deal.II/physics/elasticity/standard_tensors.h>

#include <sstream>

namespace Common
{
  namespace Materials
  {
    using namespace dealii;

    void
    LinearElasticParameters::declare_parameters(ParameterHandler  &prm,
                                                const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      {
        prm.declare_entry("Young's modulus",
                          "210000",
                          Patterns::Double(),
                          "Young's modulus E. Units: MPa (N/mm^2). Must be "
                          "positive and at most 1e12.");
        prm.declare_entry("Poisson's ratio",
                          "0.3",
                          Patterns::Double(),
                          "Poisson's ratio nu. Dimensionless, -1 < nu < "
                          "0.5.");
      }
      prm.leave_subsection();
    }



    void
    LinearElasticParameters::parse_parameters(ParameterHandler  &prm,
                                              const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      {
        youngs_modulus = IO::get_positive(prm,
                                          subsection,
                                          "Young's modulus",
                                          IO::max_modulus,
                                          "MPa");
        poisson_ratio  = prm.get_double("Poisson's ratio");
      }
      prm.leave_subsection();
      AssertThrow(poisson_ratio > -1. && poisson_ratio < 0.5,
                  ExcMessage(subsection +
                             ": Poisson's ratio must lie in "
                             "(-1, 0.5), got " +
                             std::to_string(poisson_ratio) + "."));
    }



    template <int dim>
    LinearElastic<dim>::LinearElastic(const LinearElasticParameters &parameters)
      : parameters(parameters)
    {
      const double E  = parameters.youngs_modulus;
      const double nu = parameters.poisson_ratio;
      AssertThrow(E > 0. && nu > -1. && nu < 0.5,
                  ExcMessage("Linear elastic: invalid E or nu."));
      lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
      mu     = E / (2. * (1. + nu));
      stiffness =
        lambda * outer_product(Physics::Elasticity::StandardTensors<dim>::I,
                               Physics::Elasticity::StandardTensors<dim>::I) +
        2. * mu * Physics::Elasticity::StandardTensors<dim>::S;
    }



    template <int dim>
    SymmetricTensor<2, dim>
    LinearElastic<dim>::stress(const SymmetricTensor<2, dim> &strain) const
    {
      return lambda * trace(strain) * unit_symmetric_tensor<dim>() +
             2. * mu * strain;
    }



    template <int dim>
    const SymmetricTensor<4, dim> &
    LinearElastic<dim>::tangent() const
    {
      return stiffness;
    }



    template <int dim>
    double
    LinearElastic<dim>::youngs_modulus() const
    {
      return parameters.youngs_modulus;
    }



    template <int dim>
    double
    LinearElastic<dim>::poisson_ratio() const
    {
      return parameters.poisson_ratio;
    }



    template <int dim>
    double
    LinearElastic<dim>::lame_lambda() const
    {
      return lambda;
    }



    template <int dim>
    double
    LinearElastic<dim>::lame_mu() const
    {
      return mu;
    }

    template <int dim>
    std::map<types::material_id, LinearElastic<dim>>
    linear_elastic_materials(
      const std::vector<std::pair<types::material_id, LinearElasticParameters>>
        &bodies)
    {
      std::map<types::material_id, LinearElastic<dim>> materials;
      for (const auto &[id, parameters] : bodies)
        materials.emplace(id, LinearElastic<dim>(parameters));
      return materials;
    }

    template std::map<types::material_id, LinearElastic<2>>
    linear_elastic_materials(
      const std::vector<std::pair<types::material_id, LinearElasticParameters>>
        &);
    template std::map<types::material_id, LinearElastic<3>>
    linear_elastic_materials(
      const std::vector<std::pair<types::material_id, LinearElasticParameters>>
        &);
    template class LinearElastic<2>;
    template class LinearElastic<3>;
  } // namespace Materials
} // namespace Common
