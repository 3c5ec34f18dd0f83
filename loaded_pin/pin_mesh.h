/**
 * @file pin_mesh.h
 * The mesh of FENET/NAFEMS benchmark 4, "3D loaded pin": the quarter
 * model y >= 0, z >= 0 of the lug (sheet) and the pin, two bodies that
 * touch without clearance along the cylinder r = 50 mm about the z axis.
 * Origin on the hole axis at the sheet's mid-plane, x toward the rounded
 * lug end, z along the pin axis.
 */
#ifndef loaded_pin_pin_mesh_h
#define loaded_pin_pin_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

namespace LoadedPin
{
  /**
   * @brief Dimensions of the bodies (mm); the defaults are those of the
   * benchmark. The quarter model spans y >= 0 and z >= 0.
   */
  struct PinGeometry
  {
    /** Radius of the hole. */
    double hole_radius = 50.;
    /** Radial clearance between hole and pin: the pin's radius is
     * hole_radius - clearance; negative for an interference fit (at most
     * 1 % of the hole radius). */
    double clearance = 0.;
    /** Radius of the lug's outer arc (x >= 0), also half the sheet's
     * width: the quarter model spans 0 <= y <= outer_radius. */
    double outer_radius = 100.;
    /** Distance from the clamped face x = -sheet_length to the hole
     * axis. */
    double sheet_length = 200.;
    /** Thickness of the sheet: the quarter model spans
     * 0 <= z <= sheet_thickness / 2. */
    double sheet_thickness = 10.;
    /** Length of the pin: the quarter model spans
     * 0 <= z <= pin_length / 2. */
    double pin_length = 20.;

    /** @brief Radius of the pin (mm). */
    double
    pin_radius() const
    {
      return hole_radius - clearance;
    }

    /**
     * @brief Throw with a one-line message naming the entry if the
     * dimensions do not make the lug and pin of the mesh: positive sizes,
     * -hole_radius / 100 <= clearance < hole_radius / 2,
     * hole_radius < outer_radius <
     * sheet_length, pin_length >= sheet_thickness.
     */
    void
    check() const;
  };

  /** Material ids: one per body. */
  namespace MaterialIds
  {
    constexpr dealii::types::material_id pin   = 1;
    constexpr dealii::types::material_id sheet = 2;
  } // namespace MaterialIds

  /** Boundary ids of both bodies (with the benchmark's dimensions). */
  namespace BoundaryIds
  {
    /** Traction-free faces: the sheet's face z = 5, its edge y = 100 and
     * its outer arc r = 100; the pin's cylinder beyond the sheet. */
    constexpr dealii::types::boundary_id free = 0;
    /** The sheet's clamped face x = -200. */
    constexpr dealii::types::boundary_id clamped = 1;
    /** The symmetry plane y = 0 (both bodies). */
    constexpr dealii::types::boundary_id symmetry_y0 = 2;
    /** The symmetry plane z = 0 (both bodies). */
    constexpr dealii::types::boundary_id symmetry_z0 = 3;
    /** The pin's cylinder r = 50, 0 <= z <= 10 (the part beyond the sheet
     * too: under load the sheet's edge may move along it). */
    constexpr dealii::types::boundary_id pin_contact = 4;
    /** The sheet's hole r = 50, 0 <= z <= 5. */
    constexpr dealii::types::boundary_id hole = 5;
    /** The pin's end face z = 10; the load acts at its centre (0, 0, 10),
     * a mesh vertex. */
    constexpr dealii::types::boundary_id pin_end = 6;
  } // namespace BoundaryIds

  /** Manifold ids that make_quarter_mesh() sets and attaches. */
  namespace ManifoldIds
  {
    /** Cylinders about the z axis (r = 50 and r = 100): faces and lines. */
    constexpr dealii::types::manifold_id cylinder = 0;
    /** Transfinite interpolation on the sheet's cells next to a cylinder. */
    constexpr dealii::types::manifold_id sheet_cells = 1;
    /** Transfinite interpolation on the pin's cells next to its cylinder. */
    constexpr dealii::types::manifold_id pin_cells = 2;
  } // namespace ManifoldIds

  /** @brief Refinement and layers of the quarter mesh. */
  struct MeshOptions
  {
    /** Uniform refinements of the coarse mesh. */
    unsigned int n_global_refinements = 0;
    /** Graded refinement passes toward the contact surface r = 50,
     * 0 <= z <= 5; each halves the cell size there. */
    unsigned int n_contact_refinements = 0;
    /** Refine a cell if its centre is closer to the contact surface than
     * this many cell diameters. Dimensionless. */
    double grading_factor = 2.;
    /** Coarse cell layers through the sheet's half-thickness 0 <= z <= 5. */
    unsigned int n_sheet_layers = 1;
    /** Coarse cell layers through the pin's half-length 0 <= z <= 10;
     * twice n_sheet_layers puts a plane of pin vertices at z = 5. */
    unsigned int n_pin_layers = 2;
    /** Further graded refinement passes toward the line of the contact
     * surface at theta = arc_end_angle, where the contact arc ends; each
     * halves the cell size there. */
    unsigned int n_arc_end_refinements = 0;
    /** Angle theta = 180 - atan2(y, x) of that line about the hole
     * centre (degrees, 0 to 180: 0 faces the clamp, 180 the load). */
    double arc_end_angle = 90.;
    /** Base-2 logarithm of the ratio of the pin's cell size at the
     * contact to the sheet's, -3 to 3: positive values refine the sheet
     * that many more times toward the contact, negative ones the pin. */
    int size_ratio_exponent = 0;
    /** Largest random shift of the interior vertices, as a fraction of
     * the shortest edge at each (0 to 0.3, dimensionless). */
    double interior_perturbation = 0.;
  };

  /**
   * @brief Distance (mm) of @p p from the contact surface, the hole's
   * cylinder r = hole_radius over 0 <= z <= sheet_thickness / 2: the
   * target of the graded refinement.
   */
  double
  contact_distance(const PinGeometry &geometry, const dealii::Point<3> &p);

  /**
   * @brief Distance (mm) of @p p from the line of the contact surface at
   * the angle @p theta = 180 - atan2(y, x) (degrees) over
   * 0 <= z <= sheet_thickness / 2: the target of the arc end refinement.
   */
  double
  arc_end_distance(const PinGeometry      &geometry,
                   const double            theta,
                   const dealii::Point<3> &p);

  /**
   * @brief Build the quarter model of the sheet and the pin of
   * @p geometry (checked first) in the empty @p tria (a Triangulation<3>
   * or a parallel::shared::Triangulation<3>). The sizes below are those
   * of the benchmark; other dimensions scale the same layout.
   *
   * Coarse mesh: the planforms below, extruded along z. Sheet (material
   * MaterialIds::sheet, 0 <= z <= 5): two cells of the quarter annulus
   * 50 <= r <= 100, x >= 0 (0 to 45 and 45 to 90 degrees); the square
   * [-100, 0] x [0, 100] minus the hole, split along 135 degrees into two
   * cells; the strip [-200, -100] x [0, 100], one cell. Pin (material
   * MaterialIds::pin, 0 <= z <= 10): four cells along the half circle
   * (45 degrees each) around two cells about the axis. The vertices of
   * hole and pin coincide along r = 50 (0, 45, ..., 180 degrees) but are
   * not shared: the bodies are joined by Common::Geometry::join_bodies.
   *
   * Then @p options.n_global_refinements uniform refinements and
   * @p options.n_contact_refinements graded ones toward contact_distance()
   * (Common::Geometry::refine_toward). Faces on r = 50 and r = 100 and
   * their lines follow a CylindricalManifold about the z axis, the cells
   * next to them a TransfiniteInterpolationManifold, so refined vertices
   * and the support points of a MappingQ lie on the cylinders. Boundary
   * ids: see BoundaryIds; the vertices (0, 0, 0) and (0, 0, 10) of the
   * pin's axis exist at every refinement.
   */
  void
  make_quarter_mesh(const PinGeometry        &geometry,
                    const MeshOptions        &options,
                    dealii::Triangulation<3> &tria);
} // namespace LoadedPin

#endif
