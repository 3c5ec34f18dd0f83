/**
 * @file rigid_body.h
 * Rigid bodies in translation, by constraints: every DoF of a body follows
 * one master DoF per component, so that the body keeps its shape while its
 * neighbours deform. The body's cells stay in the mesh and in the
 * assembly; a rigid translation strains nothing, so they add no internal
 * force, and loads on the body sum up on the master DoFs. Rotations are not
 * represented (the axisymmetric and symmetric benchmark tools need none).
 * Also the rigid-body modes of a displacement field, for algebraic
 * multigrid.
 */
#ifndef common_physics_rigid_body_h
#define common_physics_rigid_body_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <map>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /**
     * @brief Constrain the body of material id @p body to a rigid
     * translation.
     *
     * The master DoFs are those of the body's vertex nearest to
     * @p reference_point (mm). For each displacement component c, every
     * other DoF of component c on the body's cells is constrained to equal
     * the master DoF of component c, or to zero if @p fixed_components
     * selects c (a translation that symmetry forbids, e.g. u_r of a body on
     * the axis of an axisymmetric model). DoFs that @p constraints already
     * constrains keep their constraint: hanging nodes inside the body agree
     * with a translation, and Dirichlet conditions meant for the whole
     * body belong on the master DoFs. Every cell of the body must be
     * known on this process (serial or parallel::shared triangulations),
     * and @p constraints must store all lines (complete index set); close
     * it afterwards.
     *
     * The finite element must be a vector-valued Lagrange element with
     * one DoF per component at each vertex.
     *
     * @return The master DoF of each component (the entry of a fixed
     * component is still the reference vertex's DoF, constrained to zero).
     */
    template <int dim>
    std::vector<dealii::types::global_dof_index>
    add_rigid_translation_constraints(
      const dealii::DoFHandler<dim>     &dof_handler,
      const dealii::types::material_id   body,
      const dealii::Point<dim>          &reference_point,
      const dealii::ComponentMask       &fixed_components,
      dealii::AffineConstraints<double> &constraints);

    /**
     * @brief A body whose every displacement is prescribed as one
     * translation: the carrier of a rigid tool (a RigidTool's reference
     * node), a cell apart from the scene that moves as the load program
     * says.
     */
    template <int dim>
    struct PrescribedTranslation
    {
      /** DoFs of the body's first vertex, one per component: a tool's
       * reference node. */
      std::array<dealii::types::global_dof_index, dim> reference_node_dofs;
      /** Every DoF of the body, by component. */
      std::array<std::vector<dealii::types::global_dof_index>, dim> dofs;

      /** @brief Set the displacement of every DoF of the body to
       * @p translation (mm) in @p values. */
      void
      prescribe(
        const dealii::Tensor<1, dim>                      &translation,
        std::map<dealii::types::global_dof_index, double> &values) const;
    };

    /**
     * @brief Give every DoF of the body of material id @p body a
     * homogeneous Dirichlet line in @p constraints (not closed), so that
     * the body moves only by the displacements an ExternalLoad prescribes
     * (PrescribedTranslation::prescribe()). Every cell of the body must be
     * known on this process (serial or parallel::shared triangulations);
     * lines that @p constraints cannot store are skipped. Throws if no cell
     * has the material id.
     */
    template <int dim>
    PrescribedTranslation<dim>
    add_prescribed_translation_constraints(
      const dealii::DoFHandler<dim>     &dof_handler,
      const dealii::types::material_id   body,
      dealii::AffineConstraints<double> &constraints);

    /**
     * @brief Rigid-body modes of the displacement field, the near null
     * space of elasticity that algebraic multigrid needs to build good
     * coarse spaces.
     *
     * The modes are the dim translations and, if @p include_rotations, the
     * rotations (one in 2D, three in 3D) about the centre of the mesh's
     * bounding box, evaluated at the support points of @p mapping. For an
     * axisymmetric model pass false: only the translations approximate its
     * near null space (an axial translation is one, a radial one nearly
     * so away from the axis).
     *
     * The finite element must be a vector-valued Lagrange element with
     * dim components.
     *
     * @return One vector per mode, with the mode's values at the locally
     * owned DoFs in the order of DoFHandler::locally_owned_dofs() (mm for
     * a translation, mm per radian for a rotation).
     */
    template <int dim>
    std::vector<std::vector<double>>
    rigid_body_modes(const dealii::Mapping<dim>    &mapping,
                     const dealii::DoFHandler<dim> &dof_handler,
                     const bool                     include_rotations);
  } // namespace Physics
} // namespace Common

#endif
