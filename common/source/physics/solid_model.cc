#include <common/physics/small_strain_elasticity.h>
#include <common/physics/solid_model.h>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    void
    SolidParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solid");
      {
        prm.declare_entry(
          "Kinematics",
          "small strain",
          Patterns::Selection("small strain|finite strain"),
          "small strain: linearised strain and equilibrium in the reference "
          "configuration, Hooke's law with each body's Young's modulus and "
          "Poisson's ratio; finite strain: total Lagrangian kinematics with "
          "each body's 'Finite strain model' and the element technology "
          "below. Contact stays in the reference configuration.");
      }
      prm.leave_subsection();
      FiniteStrainParameters::declare_parameters(prm);
    }



    void
    SolidParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solid");
      kinematics = prm.get("Kinematics") == "finite strain" ?
                     StrainKinematics::finite_strain :
                     StrainKinematics::small_strain;
      prm.leave_subsection();
      finite_strain_parameters.parse_parameters(prm);
    }



    bool
    SolidParameters::finite_strain() const
    {
      return kinematics == StrainKinematics::finite_strain;
    }



    template <int dim>
    std::unique_ptr<SolidOperator<dim>>
    create_solid_operator(
      const SolidParameters    &parameters,
      const Mapping<dim>       &mapping,
      const FiniteElement<dim> &fe,
      const std::vector<std::pair<types::material_id,
                                  Materials::SolidMaterialParameters>> &bodies,
      const Kinematics kinematics)
    {
      if (!parameters.finite_strain())
        {
          std::vector<
            std::pair<types::material_id, Materials::LinearElasticParameters>>
            laws;
          for (const auto &[id, body] : bodies)
            laws.emplace_back(id, body.linear_elastic);
          return std::make_unique<SmallStrainElasticity<dim>>(
            mapping,
            fe,
            Materials::linear_elastic_materials<dim>(laws),
            kinematics);
        }

      const auto technology = parameters.finite_strain_parameters.technology;
      check_element_technology(technology, fe.degree);
      std::map<types::material_id,
               std::shared_ptr<const Materials::FiniteStrainMaterial>>
        laws;
      for (const auto &[id, body] : bodies)
        {
          laws[id] =
            Materials::create_finite_strain_material(body.finite_strain);
          check_element_technology(technology, *laws[id], body.name);
        }
      return std::make_unique<FiniteStrainSolid<dim>>(
        mapping,
        fe,
        laws,
        kinematics,
        parameters.finite_strain_parameters);
    }

    template std::unique_ptr<SolidOperator<2>>
    create_solid_operator(
      const SolidParameters &,
      const Mapping<2> &,
      const FiniteElement<2> &,
      const std::vector<
        std::pair<types::material_id, Materials::SolidMaterialParameters>> &,
      const Kinematics);
    template std::unique_ptr<SolidOperator<3>>
    create_solid_operator(
      const SolidParameters &,
      const Mapping<3> &,
      const FiniteElement<3> &,
      const std::vector<
        std::pair<types::material_id, Materials::SolidMaterialParameters>> &,
      const Kinematics);
  } // namespace Physics
} // namespace Common
