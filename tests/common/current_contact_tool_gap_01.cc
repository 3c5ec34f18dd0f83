/*
 * The gap of a secondary node against an analytic rigid tool in the
 * current configuration (Common::Contact::CurrentMortarGeometry), and the
 * states it refuses.
 *
 * A strip 20 x 1 mm (Q1, 10 x 1 cells, faces of h = 2 mm) lies under a
 * rigid cylinder of radius R = 25 mm whose lowest point touches the
 * middle of the strip's top (y = 1); the tool is carried by the fixed
 * reference node of a carrier cell. The strip is moved rigidly, and the
 * rows are integrated again (update()).
 *
 * Checks:
 * - 'Rigid tool gap = nodal': each paired row's gap, weighted_gap / D,
 *   equals the node's distance to the circle, |x - c| - R, to 1e-12 mm
 *   (the nodes within the search distance of the circle are paired),
 *   and the row's normal is the circle's inward normal at the node's
 *   closest point (to 1e-12);
 * - 'mortar': for the nodes whose faces lie under the circle within the
 *   search distance (the 5 nodes from x = 6 to 14), the gap is the
 *   dual-weighted mean of the faces' gap to 1e-10 mm, integrated here
 *   independently; it is smaller than the nodal gap by about the
 *   curvature of the tool between the nodes, h^2 / (12 R) (printed);
 * - admissible states (inadmissible_state() empty) as long as no node
 *   lies deeper inside the tool than the search distance (1 mm): the
 *   strip pushed 0.5 mm into the tool is admissible (contact still sees
 *   it); pushed 1.5 mm into it, the state is refused with a message that
 *   names the tool and the depth.
 */

#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/two_body_meshes.h>

#include "../tests.h"

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

using namespace dealii;

namespace
{
  constexpr types::boundary_id top_id     = 2;
  constexpr types::material_id strip_id   = 1;
  constexpr types::material_id carrier_id = 9;
  constexpr double             R          = 25.;
  constexpr double             h          = 2.;
  constexpr double             search     = 1.;
  const Point<2>               centre(10., 1. + R);

  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  parallel::shared::Triangulation<2> triangulation(MPI_COMM_WORLD);
  {
    Triangulation<2> strip, carrier;
    GridGenerator::subdivided_hyper_rectangle(strip,
                                              {10, 1},
                                              Point<2>(0., 0.),
                                              Point<2>(20., 1.));
    for (const auto &cell : strip.active_cell_iterators())
      {
        cell->set_material_id(strip_id);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            cell->face(f)->set_boundary_id(
              std::abs(cell->face(f)->center()[1] - 1.) < 1e-12 ? top_id : 0);
      }
    GridGenerator::hyper_rectangle(carrier,
                                   Point<2>(-20., -10.),
                                   Point<2>(-19., -9.));
    for (const auto &cell : carrier.active_cell_iterators())
      cell->set_material_id(carrier_id);
    Common::Geometry::join_bodies<2>({&strip, &carrier}, triangulation);
  }

  const FESystem<2> fe(FE_Q<2>(1), 2);
  const MappingQ<2> mapping(1);
  DoFHandler<2>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  AffineConstraints<double>              constraints;
  std::array<types::global_dof_index, 2> reference_dofs{};
  std::vector<types::global_dof_index>   strip_y_dofs;
  {
    constraints.reinit(complete_index_set(dof_handler.n_dofs()));
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(cell_dofs);
        if (cell->material_id() == carrier_id)
          {
            for (const auto dof : cell_dofs)
              constraints.add_line(dof);
            reference_dofs = {
              {cell->vertex_dof_index(0, 0), cell->vertex_dof_index(0, 1)}};
          }
        else
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == 1)
              strip_y_dofs.push_back(cell_dofs[i]);
      }
    constraints.close();
  }

  // The lower half of the circle, from angle -pi to 0.
  Common::Contact::RigidProfile circle;
  circle.add_arc(centre, R, -numbers::PI, 0.);
  Common::Contact::RigidTool<2> tool;
  tool.name    = "cylinder";
  tool.surface = std::make_shared<Common::Contact::RigidSurface<2>>(circle);
  tool.reference_node_dofs = reference_dofs;

  // The strip moved up by @p lift (mm).
  TrilinosWrappers::MPI::Vector u(complete_index_set(dof_handler.n_dofs()),
                                  MPI_COMM_WORLD);
  const auto                    lift_strip = [&](const double lift) {
    u = 0.;
    for (const auto dof : strip_y_dofs)
      u(dof) = lift;
    u.compress(VectorOperation::insert);
  };

  // The rows against the cylinder, measuring the gap as @p gap says.
  const auto make_geometry = [&](const Common::Contact::RigidToolGap gap) {
    auto geometry = std::make_unique<Common::Contact::CurrentMortarGeometry<2>>(
      dof_handler,
      mapping,
      top_id,
      std::vector<Common::Contact::RigidTool<2>>{tool},
      search,
      false);
    geometry->set_rigid_tool_gap(gap);
    geometry->reinit(constraints);
    return geometry;
  };

  // Nodal rows: the node's own distance and the circle's normal there.
  {
    auto  geometry_ptr = make_geometry(Common::Contact::RigidToolGap::nodal);
    auto &geometry     = *geometry_ptr;
    lift_strip(-0.01);
    geometry.update(u);
    const auto  &rows       = geometry.coupling();
    const auto  &surface    = rows.secondary_surface();
    double       gap_error  = 0.;
    double       normal_err = 0.;
    unsigned int n_paired   = 0;
    bool         pairing    = true;
    for (unsigned int j = 0; j < rows.n_rows(); ++j)
      {
        const Point<2> &x        = surface.node(j).position;
        const double    distance = x.distance(centre) - R;
        pairing = pairing && rows.row(j).has_partner == (distance <= search);
        if (rows.row(j).has_partner)
          {
            ++n_paired;
            const double gap = rows.weighted_gap(j, u) / rows.row(j).weight;
            const Tensor<1, 2> inward = (centre - x) / x.distance(centre);
            gap_error = std::max(gap_error, std::abs(gap - distance));
            normal_err =
              std::max(normal_err, (rows.row(j).normal - inward).norm());
          }
      }
    deallog << "nodal: " << n_paired << " paired rows of " << rows.n_rows()
            << ", those within the search distance " << pass_fail(pairing)
            << "; gap = distance to the circle " << pass_fail(gap_error < 1e-12)
            << ", normal = the circle's inward normal "
            << pass_fail(normal_err < 1e-12) << std::endl;
  }

  // Mortar rows: the dual-weighted mean of the gap along the faces'
  // (vertical) normals, g_j = n_j . e_y int psi_j t / D_j with
  // psi_j = (2 - 3 r / h) on each face, r the distance from node j, and
  // t(x) the vertical distance from the face to the circle; integrated
  // here with 20 Gauss points per face.
  {
    auto  geometry_ptr = make_geometry(Common::Contact::RigidToolGap::mortar);
    auto &geometry     = *geometry_ptr;
    lift_strip(-0.01);
    geometry.update(u);
    const auto     &rows    = geometry.coupling();
    const auto     &surface = rows.secondary_surface();
    const QGauss<1> gauss(20);
    const double    offset = h * h / (12. * R);
    double          worst = 0., smallest_offset = 1e9, largest_offset = 0.;
    unsigned int    n_inside = 0;
    for (unsigned int j = 0; j < rows.n_rows(); ++j)
      {
        const Point<2> &x = surface.node(j).position;
        if (!rows.row(j).has_partner || x[1] < 0.5)
          continue;
        ++n_inside;
        double integral = 0.;
        for (const double side : {-1., 1.})
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double r  = h * gauss.point(q)[0];
              const double xq = x[0] + side * r;
              const double t =
                (centre[1] -
                 std::sqrt(R * R - (xq - centre[0]) * (xq - centre[0]))) -
                x[1];
              integral += (2. - 3. * r / h) * t * h * gauss.weight(q);
            }
        const double expected =
          rows.row(j).normal[1] * integral / rows.row(j).weight;
        const double gap   = rows.weighted_gap(j, u) / rows.row(j).weight;
        const double nodal = x.distance(centre) - R;
        worst              = std::max(worst, std::abs(gap - expected));
        smallest_offset    = std::min(smallest_offset, (nodal - gap) / offset);
        largest_offset     = std::max(largest_offset, (nodal - gap) / offset);
      }
    deallog << "mortar: " << n_inside
            << " rows under the tool, gap = dual-weighted mean of the "
               "faces' gap "
            << pass_fail(n_inside == 5 && worst < 1e-10)
            << "; nodal gap less mortar gap: " << std::setprecision(3)
            << smallest_offset << " to " << largest_offset << " h^2/(12 R)"
            << std::endl;
  }

  // Admissible states.
  {
    auto  geometry_ptr = make_geometry(Common::Contact::RigidToolGap::mortar);
    auto &geometry     = *geometry_ptr;
    lift_strip(0.5);
    geometry.update(u);
    const std::string shallow = geometry.inadmissible_state();
    lift_strip(1.5);
    geometry.update(u);
    const std::string deep = geometry.inadmissible_state();
    deallog << "0.5 mm inside the tool: admissible "
            << pass_fail(shallow.empty()) << std::endl;
    deallog << "1.5 mm inside the tool: refused "
            << pass_fail(deep.find("1.5 mm inside the tool 'cylinder'") !=
                         std::string::npos)
            << std::endl;
    deallog << deep << std::endl;
  }
}
