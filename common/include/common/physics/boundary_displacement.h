/**
 * @file boundary_displacement.h
 * The displacement field along a boundary, sampled at the finite element's
 * support points: the surface profiles that benchmark reports compare
 * with reference curves (u_r and u_z of a foundation top, for example);
 * and the displacement of one material point.
 */
#ifndef common_physics_boundary_displacement_h
#define common_physics_boundary_displacement_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /** One sample of a boundary displacement profile. */
    template <int dim>
    struct BoundaryDisplacementPoint
    {
      /** Position in the reference configuration (mm). */
      dealii::Point<dim> position;
      /** Displacement (mm). */
      dealii::Tensor<1, dim> displacement;

      /** Serialisation for the exchange between processes. */
      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int /*version*/)
      {
        archive &position &displacement;
      }
    };

    /**
     * @brief The displacement @p u at every support point of the faces on
     * boundary @p boundary_id, positions mapped by @p mapping, each point
     * once, sorted by coordinate @p sort_coordinate (then by the others).
     *
     * @p u must be readable at the DoFs of the locally owned cells (a
     * ghosted or fully replicated vector); each process samples its own
     * cells and the result, identical on every process of the DoF
     * handler's communicator, is the union. The first dim components of
     * the finite element are the displacement, and the element must have
     * support points (Lagrange elements).
     */
    template <int dim>
    std::vector<BoundaryDisplacementPoint<dim>>
    boundary_displacements(const dealii::Mapping<dim>    &mapping,
                           const dealii::DoFHandler<dim> &dof_handler,
                           const dealii::TrilinosWrappers::MPI::Vector &u,
                           const dealii::types::boundary_id boundary_id,
                           const unsigned int sort_coordinate = 0);

    /**
     * @brief The displacement @p u of the material point at @p point of the
     * reference configuration (mm), evaluated with the finite element on
     * the cell that holds it (its reference shape given by @p mapping).
     * Every process finds the same cell (shared triangulations hold every
     * cell); its owner evaluates, and the result is the same on every
     * process. @p u must be readable at the DoFs of the locally owned
     * cells. Throws "No cell holds <what>." if the point lies outside
     * the mesh.
     */
    template <int dim>
    dealii::Tensor<1, dim>
    displacement_at(const dealii::Mapping<dim>                  &mapping,
                    const dealii::DoFHandler<dim>               &dof_handler,
                    const dealii::TrilinosWrappers::MPI::Vector &u,
                    const dealii::Point<dim>                    &point,
                    const std::string                           &what);
  } // namespace Physics
} // namespace Common

#endif
