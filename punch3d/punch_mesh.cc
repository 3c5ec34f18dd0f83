/*
 * The meshes of benchmark 2: the meridian sections of the punch and the
 * foundation, joined (axisymmetric model) or revolved into a quarter (3D
 * model), and graded toward the contact zone and its edge.
 */
#include <common/geometry/revolution.h>
#include <common/geometry/two_body_meshes.h>

#include "punch_problem.h"

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace Punch3d
{
  namespace
  {

    // The meridian section (r, z): the foundation is [0, Rf] x [0, Hf];
    // the punch [0, a] x [Hf, Hf + Hp] with the corner at (a, Hf) rounded by
    // a fillet of radius rho centred at (a - rho, Hf + rho). The punch's
    // coarse mesh is built by hand: a strip along its flat face, two cells
    // along the fillet, and two rows above. Its fillet faces get manifold
    // id 0 (a circle about the fillet's centre, attached here) and, if
    // @p transfinite_cells, its cells manifold id 1 (for a transfinite
    // interpolation attached to the joined mesh). Boundary and material
    // ids are set on both. A punch that is an analytic rigid surface
    // (@p carrier_only) keeps one cell, the upper half of its meridian,
    // which carries the reference node and the pressure.
    void
    make_meridian_meshes(const GeometryParameters &geometry,
                         const bool                transfinite_cells,
                         const bool                carrier_only,
                         Triangulation<2>         &foundation,
                         Triangulation<2>         &punch)
    {
      const double a   = geometry.punch_radius;
      const double Hp  = geometry.punch_height;
      const double rho = geometry.fillet_radius;
      const double Rf  = geometry.foundation_radius;
      const double Hf  = geometry.foundation_height;
      const double b   = a - rho;
      // The punch's base (Hf without an initial gap).
      const double   Hb = geometry.punch_base();
      const Point<2> centre(b, Hb + rho);

      const double coarse_size = 0.5 * a;
      GridGenerator::subdivided_hyper_rectangle(
        foundation,
        {std::max(1u, static_cast<unsigned int>(std::round(Rf / coarse_size))),
         std::max(1u, static_cast<unsigned int>(std::round(Hf / coarse_size)))},
        Point<2>(0., 0.),
        Point<2>(Rf, Hf));

      const double                           s = std::sqrt(0.5);
      std::vector<Point<2>>                  vertices;
      std::vector<std::vector<unsigned int>> cell_vertices;
      if (carrier_only)
        {
          vertices      = {{0., Hb + 0.5 * Hp},
                           {a, Hb + 0.5 * Hp},
                           {0., Hb + Hp},
                           {a, Hb + Hp}};
          cell_vertices = {{0, 1, 2, 3}};
        }
      else if (geometry.hemispherical_end())
        {
          // A quarter disc of three cells about the hemisphere's centre
          // (two along the arc, one at the centre), then two columns of
          // two cells above it. Vertices 0 to 2: the arc from the axis to
          // the side; 3 to 5: the inner cell's corners; 6: the centre;
          // then the rows z_mid and the top, from the axis outward.
          const double z_mid = Hb + 0.5 * (a + Hp);
          vertices           = {{0., Hb},
                                {s * a, Hb + a - s * a},
                                {a, Hb + a},
                                {0., Hb + 0.5 * a},
                                {0.5 * a, Hb + 0.5 * a},
                                {0.5 * a, Hb + a},
                                {0., Hb + a},
                                {0., z_mid},
                                {0.5 * a, z_mid},
                                {a, z_mid},
                                {0., Hb + Hp},
                                {0.5 * a, Hb + Hp},
                                {a, Hb + Hp}};
          cell_vertices      = {{0, 1, 3, 4},
                                {1, 2, 4, 5},
                                {3, 4, 6, 5},
                                {6, 5, 7, 8},
                                {5, 2, 8, 9},
                                {7, 8, 10, 11},
                                {8, 9, 11, 12}};
        }
      else
        {
          // Vertices 0 to 3: the axis, the start, middle and end of the
          // fillet; then four rows from the axis outward.
          const double z_mid = Hb + 0.5 * (2.5 * rho + Hp);
          vertices           = {{0., Hb},
                                {b, Hb},
                                {b + s * rho, Hb + rho - s * rho},
                                {a, Hb + rho},
                                {0., Hb + 2. * rho},
                                {b - 1.5 * rho, Hb + 2. * rho},
                                {b - 0.25 * rho, Hb + 2.25 * rho},
                                {a, Hb + 2.5 * rho},
                                {0., z_mid},
                                {b - 1.5 * rho, z_mid},
                                {b - 0.25 * rho, z_mid},
                                {a, z_mid},
                                {0., Hb + Hp},
                                {b - 1.5 * rho, Hb + Hp},
                                {b - 0.25 * rho, Hb + Hp},
                                {a, Hb + Hp}};
          cell_vertices      = {{0, 1, 4, 5},
                                {1, 2, 5, 6},
                                {2, 3, 6, 7},
                                {4, 5, 8, 9},
                                {5, 6, 9, 10},
                                {6, 7, 10, 11},
                                {8, 9, 12, 13},
                                {9, 10, 13, 14},
                                {10, 11, 14, 15}};
        }
      std::vector<CellData<2>> cells(cell_vertices.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int v = 0; v < 4; ++v)
          cells[c].vertices[v] = cell_vertices[c][v];
      // Neighbours must traverse their shared lines alike (the fillet mesh
      // is numbered so already).
      if (geometry.hemispherical_end())
        GridTools::consistently_order_cells(cells);
      punch.create_triangulation(vertices, cells, SubCellData());

      const double tolerance = 1e-8 * a;
      for (const auto &cell : foundation.active_cell_iterators())
        {
          cell->set_material_id(MaterialIds::foundation);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<2> c = face->center();
                face->set_boundary_id(
                  std::abs(c[1]) < tolerance ? BoundaryIds::foundation_bottom :
                  std::abs(c[1] - Hf) < tolerance ?
                                               BoundaryIds::foundation_top :
                  std::abs(c[0]) < tolerance ? BoundaryIds::foundation_axis :
                                               BoundaryIds::foundation_side);
              }
        }
      for (const auto &cell : punch.active_cell_iterators())
        {
          cell->set_material_id(MaterialIds::punch);
          if (transfinite_cells)
            cell->set_all_manifold_ids(1);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<2> c = face->center();
                if (std::abs(c[0]) < tolerance)
                  face->set_boundary_id(BoundaryIds::punch_axis);
                else if (std::abs(c[1] - Hb - Hp) < tolerance)
                  face->set_boundary_id(BoundaryIds::punch_top);
                else if (std::abs(c[0] - a) < tolerance || carrier_only)
                  face->set_boundary_id(BoundaryIds::punch_side);
                else
                  {
                    // The flat face and the fillet: the primary surface.
                    face->set_boundary_id(BoundaryIds::punch_contact);
                    if (c[0] > b + tolerance)
                      face->set_manifold_id(0);
                  }
              }
        }
      punch.set_manifold(0, SphericalManifold<2>(centre));
    }
  } // namespace



  // The axisymmetric model joins the meridian meshes; the fillet is a
  // circle, the punch's interior a transfinite interpolation, so the arc
  // is exact under refinement and represented by the element geometry of
  // Q2. The 3D model revolves each meridian mesh into a quarter
  // (common/geometry/revolution.h) and joins them; the fillet becomes a
  // torus. Both are then graded toward the contact zone.
  template <int dim>
  void
  PunchProblem<dim>::make_grid()
  {
    const auto  &geometry = parameters.geometry;
    const double a        = geometry.punch_radius;
    const double b        = a - geometry.fillet_radius;
    const double Hf       = geometry.foundation_height;

    Triangulation<2> foundation, punch;
    make_meridian_meshes(geometry,
                         dim == 2,
                         parameters.model.rigid_surface,
                         foundation,
                         punch);
    if constexpr (dim == 2)
      {
        Common::Geometry::join_bodies<dim>({&foundation, &punch},
                                           triangulation);
        TransfiniteInterpolationManifold<dim> transfinite;
        transfinite.initialize(triangulation);
        triangulation.set_manifold(1, transfinite);
      }
    else
      {
        Triangulation<dim> foundation_3d, punch_3d;
        Common::Geometry::revolve_quarter(foundation,
                                          BoundaryIds::symmetry_z0,
                                          BoundaryIds::symmetry_x0,
                                          10,
                                          foundation_3d);
        Common::Geometry::revolve_quarter(punch,
                                          BoundaryIds::symmetry_z0,
                                          BoundaryIds::symmetry_x0,
                                          20,
                                          punch_3d);
        Common::Geometry::join_bodies<dim>({&foundation_3d, &punch_3d},
                                           triangulation);
      }

    // Graded toward the band under the punch, then toward the contact
    // edge, from the start of the fillet to half its radius beyond it.
    // The carrier cell of an analytic rigid punch is not refined.
    const bool carrier = parameters.model.rigid_surface;
    const auto band    = [Hf, carrier](const double r0, const double r1) {
      return [Hf, carrier, r0, r1](const Point<dim> &p) {
        if (carrier && p[1] > Hf)
          return std::numeric_limits<double>::infinity();
        const double r  = radius(p);
        const double dr = std::max({0., r0 - r, r - r1});
        return std::sqrt(dr * dr + (p[1] - Hf) * (p[1] - Hf));
      };
    };
    // A hemispherical end has its contact zone, and its edge, within the
    // Hertz radius: both gradings aim at r <= 1.25 a_Hertz.
    const bool   sphere     = geometry.hemispherical_end();
    const double edge_start = sphere ? 0. : b;
    const double edge_end   = sphere ?
                                1.25 * half_space_reference().contact_radius() :
                                b + 0.5 * geometry.fillet_radius;
    Common::Geometry::refine_planned<dim>(
      triangulation,
      parameters.mesh.n_global_refinements,
      "Mesh: 'Number of global refinements'",
      {{band(0., sphere ? edge_end : a),
        parameters.mesh.n_contact_refinements,
        parameters.mesh.grading_factor,
        "Mesh: 'Number of global refinements', "
        "'Number of contact refinements' "
        "and 'Grading factor'"},
       {band(edge_start, edge_end),
        parameters.mesh.n_edge_refinements,
        parameters.mesh.grading_factor,
        "Mesh: 'Number of global refinements', "
        "'Number of contact refinements', "
        "'Number of edge refinements' and "
        "'Grading factor'"}});
    parameters.mesh.apply_variations<dim>(triangulation,
                                          band(0., sphere ? edge_end : a),
                                          MaterialIds::punch,
                                          MaterialIds::foundation);
  }



  template void
  PunchProblem<2>::make_grid();
  template void
  PunchProblem<3>::make_grid();
} // namespace Punch3d
