/**
 * @file solid_model.h
 * The solid of a scene as its parameter file chooses it: small-strain or
 * finite-strain kinematics (subsection "Solid"), and the solid operator
 * built from that choice and the material of each body.
 */
#ifndef common_physics_solid_model_h
#define common_physics_solid_model_h

#include <common/materials/solid_material.h>
#include <common/physics/finite_strain_solid.h>
#include <common/physics/solid_operator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <memory>
#include <utility>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /** Strain measure of a solid. */
    enum class StrainKinematics
    {
      /** Linearised strain, equilibrium in the reference configuration:
       * Hooke's law. */
      small_strain,
      /** Total Lagrangian finite strain with the finite-strain law of each
       * body. */
      finite_strain
    };

    /**
     * @brief Subsection "Solid": "Kinematics" and, for finite strain, the
     * element technology and the incompressibility entries
     * (FiniteStrainParameters).
     */
    struct SolidParameters
    {
      /** @brief Declare the entries of subsection "Solid". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read and check them. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** @brief True for finite-strain kinematics. */
      bool
      finite_strain() const;

      StrainKinematics       kinematics = StrainKinematics::small_strain;
      FiniteStrainParameters finite_strain_parameters;
    };

    /**
     * @brief The solid operator of a scene: SmallStrainElasticity with
     * Hooke's law per body, or FiniteStrainSolid with each body's
     * finite-strain law (owned by the operator).
     * @param[in] bodies Material id and material of each body, parsed for
     * the same kinematics.
     * @param[in] kinematics Plane strain/3D or axisymmetric.
     * An exactly incompressible body without the mixed element, or a
     * finite-strain element that does not fit the element degree, gets a
     * one-line error naming the body.
     */
    template <int dim>
    std::unique_ptr<SolidOperator<dim>>
    create_solid_operator(
      const SolidParameters            &parameters,
      const dealii::Mapping<dim>       &mapping,
      const dealii::FiniteElement<dim> &fe,
      const std::vector<std::pair<dealii::types::material_id,
                                  Materials::SolidMaterialParameters>> &bodies,
      const Kinematics kinematics = Kinematics::cartesian);
  } // namespace Physics
} // namespace Common

#endif
