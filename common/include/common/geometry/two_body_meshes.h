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
     * before they run (refine_planned(), refine_toward()).
     */
    template <int dim>
    constexpr std::uint64_t max_active_cells = dim == 2 ? 1'000'000 : 500'000;

    /**
     * @brief Refuse, before it is built, a structured mesh of @p n_cells
     * cells beyond an application's @p max_cells (what a direct solver
     * handles for its element).
     * @param[in] entries The parameter entries whose product @p n_cells is,
     * as the error message names them.
     * @throws dealii::ExcMessage "Mesh: <entries> would make a mesh of
     * <n_cells> cells, more than <max_cells>."
     */
    void
    check_cell_count(const std::uint64_t n_cells,
                     const std::uint64_t max_cells,
                     const std::string  &entries);

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
     * @param[in] material_id Refine only the cells of this body (all
     * cells if invalid). Bodies joined by join_bodies() share no vertices,
     * so refining one of them leaves the other's cells at the contact
     * unchanged: the meshes across the contact no longer match.
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
      const std::string                                       &entries,
      const dealii::types::material_id                         material_id =
        dealii::numbers::invalid_material_id);

    /**
     * @brief One set of graded passes of refine_planned(): the arguments
     * of refine_toward().
     */
    template <int dim>
    struct GradedRefinement
    {
      /** Distance of a point to the region (mm). */
      std::function<double(const dealii::Point<dim> &)> distance;
      /** Number of passes. */
      unsigned int n_passes;
      /** A cell is refined if its centre lies closer to the region than
       * factor times its diameter (dimensionless). */
      double factor;
      /** The parameter entries that set the refinement, as the error
       * message names them. */
      std::string entries;
      /** Refine only the cells of this body (all cells if invalid). */
      dealii::types::material_id material_id =
        dealii::numbers::invalid_material_id;
    };

    /**
     * @brief Refine @p tria globally @p n_global times, then by each set of
     * graded passes of @p graded in turn (refine_toward()). Before any
     * refinement runs, the mesh that the global refinements and each set
     * alone would make of the coarse mesh is predicted: the later sets
     * refine a finer mesh, so this is a lower bound of the final mesh, and
     * a plan beyond max_active_cells is refused at once, not after global
     * refinements that may take minutes.
     * @param[in] global_entries The parameter entries that set
     * @p n_global, as the error message names them.
     * @throws dealii::ExcMessage naming the entries of the first set (or
     * @p global_entries) that would make the mesh too large.
     */
    template <int dim>
    void
    refine_planned(dealii::Triangulation<dim>               &tria,
                   const unsigned int                        n_global,
                   const std::string                        &global_entries,
                   const std::vector<GradedRefinement<dim>> &graded);

    /**
     * @brief Move every vertex that lies on no boundary in a random
     * direction by up to @p fraction of the shortest active edge at it,
     * for tests of robustness to distorted cells. The random numbers come
     * from a fixed seed, so that every run and every MPI rank makes the
     * same mesh. Boundary vertices (the contact surfaces among them) stay;
     * hanging vertices are put back at the middle of their parent edge
     * (and, in 3D, of their parent face), so the mesh stays conforming.
     * The interior cells, lines and faces, and boundary objects described
     * by a transfinite interpolation, become straight-sided (flat
     * manifold id); the other boundary manifolds stay. Call after the last
     * refinement.
     * @param[in] fraction Largest shift over the shortest adjacent edge,
     * 0 to 0.3 (dimensionless); 0 leaves the mesh unchanged.
     * @param[in] entry The parameter entry that sets @p fraction, as the
     * error message names it.
     * @throws dealii::ExcMessage naming @p entry if a cell is inverted.
     */
    template <int dim>
    void
    perturb_interior_vertices(dealii::Triangulation<dim> &tria,
                              const double                fraction,
                              const std::string          &entry);

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
