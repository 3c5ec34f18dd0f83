/**
 * @file boundary_loads.h
 * Consistent nodal forces of distributed boundary loads, for plane,
 * axisymmetric (ring-weighted) and 3D models.
 */
#ifndef common_physics_boundary_loads_h
#define common_physics_boundary_loads_h

#include <common/physics/small_strain_elasticity.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

namespace Common
{
  namespace Physics
  {
    /**
     * @brief Add the consistent nodal forces (N, or N/mm in plane strain)
     * of a uniform pressure on the faces with boundary id @p boundary_id:
     * the traction \f$-p\,n\f$ with the outward unit normal n (reference
     * configuration), integrated with the measure of @p kinematics, over
     * the locally owned cells, distributed through @p constraints. Not
     * compressed here.
     * @param[in] pressure Pressure p (MPa), positive pushing into the body.
     */
    template <int dim>
    void
    add_boundary_pressure(const dealii::Mapping<dim>              &mapping,
                          const dealii::DoFHandler<dim>           &dof_handler,
                          const dealii::types::boundary_id         boundary_id,
                          const double                             pressure,
                          const Kinematics                         kinematics,
                          const dealii::AffineConstraints<double> &constraints,
                          dealii::TrilinosWrappers::MPI::Vector   &rhs);
  } // namespace Physics
} // namespace Common

#endif
