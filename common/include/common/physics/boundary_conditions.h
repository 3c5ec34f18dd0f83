/**
 * @file boundary_conditions.h
 * Homogeneous constraints that every contact model starts from: hanging
 * nodes of a locally refined mesh, clamped boundaries and symmetry lines,
 * planes or axes (one displacement component held at zero).
 */
#ifndef common_physics_boundary_conditions_h
#define common_physics_boundary_conditions_h

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <utility>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /**
     * @brief Add to @p constraints, for each (c, ids) of
     * @p zero_components, zero displacement component c on the boundaries
     * ids (a symmetry line or plane normal to e_c, or the axis of an
     * axisymmetric model for c = 0). Not closed here.
     */
    template <int dim>
    void
    add_zero_component_constraints(
      const dealii::Mapping<dim>    &mapping,
      const dealii::DoFHandler<dim> &dof_handler,
      const std::vector<
        std::pair<unsigned int, std::vector<dealii::types::boundary_id>>>
                                        &zero_components,
      dealii::AffineConstraints<double> &constraints);

    /**
     * @brief Reset @p constraints (all DoFs stored) to the hanging-node
     * constraints of @p dof_handler, zero displacement on the boundaries
     * @p clamped, and, for each (c, ids) of @p zero_components, zero
     * displacement component c on the boundaries ids (a symmetry line or
     * plane normal to e_c, or the axis of an axisymmetric model for c = 0).
     * The constraints act on Newton increments; not closed here.
     */
    template <int dim>
    void
    make_homogeneous_constraints(
      const dealii::Mapping<dim>                    &mapping,
      const dealii::DoFHandler<dim>                 &dof_handler,
      const std::vector<dealii::types::boundary_id> &clamped,
      const std::vector<
        std::pair<unsigned int, std::vector<dealii::types::boundary_id>>>
                                        &zero_components,
      dealii::AffineConstraints<double> &constraints);
  } // namespace Physics
} // namespace Common

#endif
