/*
 * The setting of the tests of a rigid tool on a strip in the current
 * configuration (tests/common/current_contact_rolling_01,
 * current_contact_penalty_01): a plane strip on a rigid frictionless
 * backing, and a carrier cell far from it whose first vertex is the tool's
 * reference node and which moves rigidly with the tool.
 */
#ifndef tests_tool_on_strip_h
#define tests_tool_on_strip_h

#include <common/geometry/two_body_meshes.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <cmath>
#include <vector>

namespace ToolOnStrip
{
  using namespace dealii;

  constexpr types::boundary_id bottom_id  = 1;
  constexpr types::boundary_id top_id     = 2;
  constexpr types::material_id strip_id   = 1;
  constexpr types::material_id carrier_id = 9;

  /** The strip [x0, x1] x [0, thickness] (mm) of nx x ny cells, its
   * bottom bottom_id and its top top_id, joined with the carrier cell
   * [-40, -39] x [20, 21]. */
  inline void
  make_mesh(parallel::shared::Triangulation<2> &triangulation,
            const double                        x0,
            const double                        x1,
            const unsigned int                  nx,
            const unsigned int                  ny,
            const double                        thickness)
  {
    Triangulation<2> strip, carrier;
    GridGenerator::subdivided_hyper_rectangle(strip,
                                              {nx, ny},
                                              Point<2>(x0, 0.),
                                              Point<2>(x1, thickness));
    for (const auto &cell : strip.active_cell_iterators())
      {
        cell->set_material_id(strip_id);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            cell->face(f)->set_boundary_id(
              std::abs(cell->face(f)->center()[1]) < 1e-12 ? bottom_id :
              std::abs(cell->face(f)->center()[1] - thickness) < 1e-12 ?
                                                             top_id :
                                                             0);
      }
    GridGenerator::hyper_rectangle(carrier,
                                   Point<2>(-40., 20.),
                                   Point<2>(-39., 21.));
    for (const auto &cell : carrier.active_cell_iterators())
      cell->set_material_id(carrier_id);
    Common::Geometry::join_bodies<2>({&strip, &carrier}, triangulation);
  }

  /** The carrier's DoFs: the reference node's, and the vertical ones. */
  struct Carrier
  {
    std::array<types::global_dof_index, 2> reference_dofs{};
    std::vector<types::global_dof_index>   vertical_dofs;
  };

  /** Reinitialise @p constraints with a line for every DoF of the carrier
   * and for the vertical DoFs of the strip's bottom (the backing); not
   * closed, so that a test can add its own lines. */
  inline Carrier
  constrain(const DoFHandler<2>       &dof_handler,
            AffineConstraints<double> &constraints)
  {
    const auto &fe = dof_handler.get_fe();
    Carrier     result;
    constraints.reinit(complete_index_set(dof_handler.n_dofs()));
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == carrier_id)
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == 1)
              result.vertical_dofs.push_back(cell_dofs[i]);
          for (const auto dof : cell_dofs)
            constraints.add_line(dof);
          result.reference_dofs = {
            {cell->vertex_dof_index(0, 0), cell->vertex_dof_index(0, 1)}};
        }
    const FEValuesExtractors::Scalar y(1);
    for (const auto dof : DoFTools::extract_boundary_dofs(dof_handler,
                                                          fe.component_mask(y),
                                                          {bottom_id}))
      constraints.add_line(dof);
    return result;
  }
} // namespace ToolOnStrip

#endif
