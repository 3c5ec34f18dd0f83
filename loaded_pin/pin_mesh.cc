/*
 * The quarter mesh of benchmark 4: planforms of the sheet and the pin in
 * the xy-plane, extruded along z, joined, and graded toward the contact
 * surface r = 50.
 */
#include <common/geometry/two_body_meshes.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <loaded_pin/pin_mesh.h>
#include <vector>

namespace LoadedPin
{
  using namespace dealii;

  namespace
  {
    /** Geometric tolerance relative to the hole radius. */
    constexpr double relative_tolerance = 1e-8;

    /** A planform from its vertices and its cells, each given by its
     * vertices in deal.II's order (counterclockwise: 0, 1, 3, 2). */
    void
    create_planform(const std::vector<Point<2>>                    &vertices,
                    const std::vector<std::array<unsigned int, 4>> &cell_list,
                    Triangulation<2>                               &planform)
    {
      std::vector<CellData<2>> cells(cell_list.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int v = 0; v < 4; ++v)
          cells[c].vertices[v] = cell_list[c][v];
      GridTools::consistently_order_cells(cells);
      planform.create_triangulation(vertices, cells, SubCellData());
    }

    /** The sheet's planform: vertices 0 to 4 on the hole at 0, 45, ...,
     * 180 degrees; 5 to 7 on the outer arc at 0, 45 and 90 degrees; then
     * the corners (-100, 100), (-100, 0), (-200, 0) and (-200, 100). */
    void
    make_sheet_planform(const PinGeometry &g, Triangulation<2> &planform)
    {
      const double a = g.hole_radius;
      const double b = g.outer_radius;
      const double s = std::sqrt(0.5);
      create_planform({{a, 0.},
                       {s * a, s * a},
                       {0., a},
                       {-s * a, s * a},
                       {-a, 0.},
                       {b, 0.},
                       {s * b, s * b},
                       {0., b},
                       {-b, b},
                       {-b, 0.},
                       {-g.sheet_length, 0.},
                       {-g.sheet_length, b}},
                      {{{0, 5, 1, 6}},
                       {{1, 6, 2, 7}},
                       {{2, 7, 3, 8}},
                       {{3, 8, 4, 9}},
                       {{10, 9, 11, 8}}},
                      planform);
    }

    /** The pin's planform, a half disc of radius @p a: vertex 0 at the centre; 1 to 5
     * around it at 0, 45, ..., 180 degrees (at radius a/2 on the x and y
     * axes, at (+-0.4 a, 0.4 a) in between); 6 to 10 on the circle at the
     * same angles. Two cells about the centre, four along the circle. */
    void
    make_pin_planform(const double a, Triangulation<2> &planform)
    {
      const double s = std::sqrt(0.5);
      create_planform({{0., 0.},
                       {0.5 * a, 0.},
                       {0.4 * a, 0.4 * a},
                       {0., 0.5 * a},
                       {-0.4 * a, 0.4 * a},
                       {-0.5 * a, 0.},
                       {a, 0.},
                       {s * a, s * a},
                       {0., a},
                       {-s * a, s * a},
                       {-a, 0.}},
                      {{{0, 1, 3, 2}},
                       {{5, 0, 4, 3}},
                       {{1, 6, 2, 7}},
                       {{2, 7, 3, 8}},
                       {{3, 8, 4, 9}},
                       {{4, 9, 5, 10}}},
                      planform);
    }

    /** Whether every vertex of @p face lies on the cylinder of radius
     * @p radius (mm) about the z axis. */
    bool
    on_cylinder(const Triangulation<3>::face_iterator &face,
                const double                           radius)
    {
      for (const unsigned int v : face->vertex_indices())
        if (std::abs(std::hypot(face->vertex(v)[0], face->vertex(v)[1]) -
                     radius) > relative_tolerance * radius)
          return false;
      return true;
    }

    /** Whether @p face lies on one of the cylinders of the body: the hole
     * or the outer arc of the sheet, the pin's cylinder. */
    bool
    on_any_cylinder(const Triangulation<3>::face_iterator &face,
                    const PinGeometry                     &g,
                    const bool                             pin)
    {
      return pin ? on_cylinder(face, g.pin_radius()) :
                   on_cylinder(face, g.hole_radius) ||
                     on_cylinder(face, g.outer_radius);
    }

    /** The boundary id of the boundary face @p face of the pin (if
     * @p pin) or the sheet, whose top face is z = @p height (mm). */
    types::boundary_id
    boundary_id(const Triangulation<3>::face_iterator &face,
                const PinGeometry                     &g,
                const bool                             pin,
                const double                           height)
    {
      const double   tolerance = relative_tolerance * g.hole_radius;
      const Point<3> c         = face->center();
      if (std::abs(c[1]) < tolerance)
        return BoundaryIds::symmetry_y0;
      if (std::abs(c[2]) < tolerance)
        return BoundaryIds::symmetry_z0;
      if (std::abs(c[0] + g.sheet_length) < tolerance)
        return BoundaryIds::clamped;
      if (pin && on_cylinder(face, g.pin_radius()))
        return BoundaryIds::pin_contact;
      if (!pin && on_cylinder(face, g.hole_radius))
        return BoundaryIds::hole;
      if (pin && std::abs(c[2] - height) < tolerance)
        return BoundaryIds::pin_end;
      return BoundaryIds::free;
    }

    /** Extrude @p planform over 0 <= z <= @p height in @p n_layers cell
     * layers into @p body, and set its material, boundary and manifold
     * ids: faces on a cylinder and their lines get ManifoldIds::cylinder,
     * the other objects of cells next to a cylinder
     * @p cells_manifold_id. */
    void
    extrude_body(const Triangulation<2>  &planform,
                 const PinGeometry       &geometry,
                 const unsigned int       n_layers,
                 const double             height,
                 const types::material_id material_id,
                 const types::manifold_id cells_manifold_id,
                 Triangulation<3>        &body)
    {
      AssertThrow(n_layers > 0, ExcMessage("A body needs a cell layer."));
      GridGenerator::extrude_triangulation(planform,
                                           n_layers + 1,
                                           height,
                                           body);
      const bool pin = material_id == MaterialIds::pin;
      for (const auto &cell : body.active_cell_iterators())
        {
          cell->set_material_id(material_id);
          for (const auto &face : cell->face_iterators())
            if (on_any_cylinder(face, geometry, pin))
              cell->set_all_manifold_ids(cells_manifold_id);
        }
      for (const auto &cell : body.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              if (on_any_cylinder(face, geometry, pin))
                face->set_all_manifold_ids(ManifoldIds::cylinder);
              face->set_boundary_id(boundary_id(face, geometry, pin, height));
            }
    }
  } // namespace



  void
  PinGeometry::check() const
  {
    AssertThrow(hole_radius > 0.,
                ExcMessage("Geometry: 'Hole radius' must be positive."));
    AssertThrow(clearance >= -0.01 * hole_radius &&
                  clearance < 0.5 * hole_radius,
                ExcMessage("Geometry: 'Clearance' must be at least -1 % "
                           "and less than half of the hole radius."));
    AssertThrow(outer_radius > hole_radius,
                ExcMessage("Geometry: 'Hole radius' must be less than 'Outer "
                           "radius': the hole must lie inside the lug."));
    AssertThrow(sheet_length > outer_radius,
                ExcMessage("Geometry: 'Sheet length' must exceed "
                           "'Outer radius'."));
    AssertThrow(sheet_thickness > 0.,
                ExcMessage("Geometry: 'Sheet thickness' must be positive."));
    AssertThrow(pin_length >= sheet_thickness,
                ExcMessage("Geometry: 'Pin length' must be at least the "
                           "sheet thickness."));
  }



  double
  contact_distance(const PinGeometry &geometry, const Point<3> &p)
  {
    return std::hypot(std::hypot(p[0], p[1]) - geometry.hole_radius,
                      std::max(0., p[2] - 0.5 * geometry.sheet_thickness));
  }



  double
  arc_end_distance(const PinGeometry &geometry,
                   const double       theta,
                   const Point<3>    &p)
  {
    // theta = 180 degrees - atan2(y, x): 0 faces the clamp, 180 the load.
    const double angle = theta * numbers::PI / 180.;
    const double x     = -geometry.hole_radius * std::cos(angle);
    const double y     = geometry.hole_radius * std::sin(angle);
    return std::hypot(std::hypot(p[0] - x, p[1] - y),
                      std::max(0., p[2] - 0.5 * geometry.sheet_thickness));
  }



  void
  make_quarter_mesh(const PinGeometry &geometry,
                    const MeshOptions &options,
                    Triangulation<3>  &tria)
  {
    geometry.check();
    Triangulation<2> sheet_planform, pin_planform;
    make_sheet_planform(geometry, sheet_planform);
    make_pin_planform(geometry.pin_radius(), pin_planform);
    Triangulation<3> sheet, pin;
    extrude_body(sheet_planform,
                 geometry,
                 options.n_sheet_layers,
                 0.5 * geometry.sheet_thickness,
                 MaterialIds::sheet,
                 ManifoldIds::sheet_cells,
                 sheet);
    extrude_body(pin_planform,
                 geometry,
                 options.n_pin_layers,
                 0.5 * geometry.pin_length,
                 MaterialIds::pin,
                 ManifoldIds::pin_cells,
                 pin);
    Common::Geometry::join_bodies<3>({&sheet, &pin}, tria);

    // The cylinder first: the transfinite interpolations read it.
    tria.set_manifold(ManifoldIds::cylinder, CylindricalManifold<3>(2));
    for (const types::manifold_id id :
         {ManifoldIds::sheet_cells, ManifoldIds::pin_cells})
      {
        TransfiniteInterpolationManifold<3> transfinite;
        transfinite.initialize(tria);
        tria.set_manifold(id, transfinite);
      }

    // The last set is the variation of the common mesh entries (see
    // Common::Geometry::MeshParameters::apply_variations()).
    const auto to_contact = [&geometry](const Point<3> &p) {
      return contact_distance(geometry, p);
    };
    Common::Geometry::refine_planned<3>(
      tria,
      options.n_global_refinements,
      "Mesh: 'Number of global refinements', 'Number of sheet layers' and "
      "'Number of pin layers'",
      {{to_contact,
        options.n_contact_refinements,
        options.grading_factor,
        "Mesh: 'Number of global refinements', 'Number of sheet layers', "
        "'Number of pin layers', 'Number of contact refinements' and "
        "'Grading factor'"},
       {[&geometry, &options](const Point<3> &p) {
          return arc_end_distance(geometry, options.arc_end_angle, p);
        },
        options.n_arc_end_refinements,
        options.grading_factor,
        "Mesh: 'Number of global refinements', 'Number of sheet layers', "
        "'Number of pin layers', 'Number of contact refinements', 'Number of "
        "arc end refinements' and 'Grading factor'"},
       {to_contact,
        static_cast<unsigned int>(std::abs(options.size_ratio_exponent)),
        options.grading_factor,
        "Mesh: 'Contact size ratio' with the other refinement entries",
        options.size_ratio_exponent > 0 ? MaterialIds::sheet :
                                          MaterialIds::pin}});
    Common::Geometry::perturb_interior_vertices(
      tria,
      options.interior_perturbation,
      "Mesh: 'Interior node perturbation'");
  }
} // namespace LoadedPin
