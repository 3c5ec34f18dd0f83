/**
 * @file solid_material.h
 * The material of one body as a parameter file gives it: Young's modulus,
 * Poisson's ratio and the finite-strain law with its hardening, read from
 * one subsection (e.g. "Block material") and checked for the kinematics
 * the scene uses.
 */
#ifndef common_materials_solid_material_h
#define common_materials_solid_material_h

#include <common/materials/finite_strain_material.h>
#include <common/materials/linear_elastic.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Common
{
  namespace Materials
  {
    /**
     * @brief Parameters of one body's material under small-strain or
     * finite-strain kinematics.
     */
    struct SolidMaterialParameters
    {
      /** @brief Declare "Young's modulus", "Poisson's ratio", "Finite
       * strain model" and the hardening entries in @p subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &subsection);

      /**
       * @brief Read and check the entries for the kinematics of the scene.
       * Small strain: Hooke's law, -1 < nu < 0.5, and a finite-strain
       * model that is elastic (every elastic law is Hooke's law at small
       * strain; J2 plasticity is refused). Finite strain: the law of
       * "Finite strain model" (FiniteStrainMaterialParameters). One-line
       * messages name @p subsection and the entry.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &subsection,
                       const bool                finite_strain);

      /** The subsection the parameters were read from. */
      std::string name;
      /** Young's modulus E (MPa). */
      double youngs_modulus = 0.;
      /** Poisson's ratio nu. */
      double poisson_ratio = 0.;
      /** Hooke's law of small-strain kinematics. */
      LinearElasticParameters linear_elastic;
      /** The law of finite-strain kinematics. */
      FiniteStrainMaterialParameters finite_strain;
    };
  } // namespace Materials
} // namespace Common

#endif
