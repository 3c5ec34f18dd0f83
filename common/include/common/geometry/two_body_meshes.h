/**
 * @file two_body_meshes.h
 * Meshes of several bodies in one triangulation: coarse meshes are joined
 * without merging coincident vertices (bodies that touch at a point stay
 * separate), keeping material and manifold ids; graded local refinement
 * toward a region such as a contact zone.
 */
#ifndef common_geometry_two_body_meshes_h
#define common_geometry_two_body_meshes_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace Common
{
  namespace Geometry
  {
    /**
     * @brief Join coarse meshes into @p result without merging any
     * vertices. Material ids, boundary ids and the manifold ids of every
     * cell, face and (3D) line are kept, and so are the manifold objects
     * attached to the parts (cloned), except flat ones; two parts must not
     * attach manifolds to the same id. A manifold that refers to its
     * part's triangulation (TransfiniteInterpolationManifold) must be
     * attached to @p result afterwards instead.
     * @param[in] parts Coarse (unrefined) triangulations.
     */
    template <int dim>
    void
    join_bodies(const std::vector<const dealii::Triangulation<dim> *> &parts,
                dealii::Triangulation<dim>                            &result);

    /**
     * @brief Largest number of active cells a mesh of the suite may have:
     * 1 million in 2D, half a million in 3D, beyond what a workstation
     * solves with a direct solver. Refinements that would exceed it are refused
     * before they run (refine_global_checked(), refine_toward()).
     */
    template <int dim>
    constexpr std::uint64_t max_active_cells = dim == 2 ? 1'000'000 : 500'000;

    /**
     * @brief Refine @p tria globally @p n_times, refusing a mesh of more
     * than max_active_cells cells before refining.
     * @param[in] entries The parameter entries that set the refinement, as
     * the error message names them (e.g. "'Number of global refinements'
     * in subsection Mesh").
     * @throws dealii::ExcMessage naming @p entries if the mesh would be
     * too large.
     */
    template <int dim>
    void
    refine_global_checked(dealii::Triangulation<dim> &tria,
                          const unsigned int          n_times,
                          const std::string          &entries);

    /**
     * @brief Graded refinement toward a region: in each of @p n_passes
     * passes, refine every active cell whose centre lies closer to the
     * region than @p factor times its diameter. Cells shrink by half per
     * band, and each band is as thick as a few of its cells. A pass that
     * would make more than max_active_cells cells is refused before it
     * runs.
     * @param[in] distance Distance of a point to the region (mm).
     * @param[in] entries The parameter entries that set the refinement, as
     * the error message names them.
     * @throws dealii::ExcMessage naming @p entries if the mesh would be
     * too large.
     */
    template <int dim>
    void
    refine_toward(
      dealii::Triangulation<dim>                              &tria,
      const std::function<double(const dealii::Point<dim> &)> &distance,
      const unsigned int                                       n_passes,
      const double                                             factor,
      const std::string                                       &entries);

    /**
     * @brief Smallest cell diameter near a region: the minimum over cells
     * with distance(centre) < their diameter (mm).
     */
    template <int dim>
    double
    smallest_cell_near(
      const dealii::Triangulation<dim>                        &tria,
      const std::function<double(const dealii::Point<dim> &)> &distance);

    /**
     * @brief The DoF of displacement component @p component at the mesh
     * vertex within @p tolerance (mm) of @p point, on a cell of material
     * @p material_id (any cell if invalid). Every rank finds it (shared
     * triangulations hold every cell). Throws "No mesh vertex at
     * <what>." if there is none.
     */
    template <int dim>
    dealii::types::global_dof_index
    vertex_dof(const dealii::DoFHandler<dim>   &dof_handler,
               const dealii::Point<dim>        &point,
               const unsigned int               component,
               const double                     tolerance,
               const std::string               &what,
               const dealii::types::material_id material_id =
                 dealii::numbers::invalid_material_id);
  } // namespace Geometry
} // namespace Common

#endif
