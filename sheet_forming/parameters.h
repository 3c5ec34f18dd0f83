/*
 * Parameters of the sheet_forming benchmark: the common blocks (solid,
 * contact, solvers, load program, output, run control) composed with the
 * blocks that only this benchmark has (tool and sheet geometry, mesh,
 * release, angle measurement, sheet material).
 */
#ifndef sheet_forming_parameters_h
#define sheet_forming_parameters_h

#include <common/materials/solid_material.h>
#include <common/problems/contact_run_parameters.h>
#include <common/solvers/load_program.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace SheetForming
{
  using namespace dealii;

  /** Subsection "Geometry": tools and sheet (spec sections 0 to 3). */
  struct GeometryParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check: every length positive, the sheet fits between
     * punch and die at full stroke, and it rests on the die's flat top. */
    void
    parse_parameters(ParameterHandler &prm);

    /** Radius of the punch Rp (mm). */
    double punch_radius;
    /** Distance by which the punch starts above the sheet's top (mm;
     * negative: an overlap); 0 for the benchmark. */
    double initial_punch_gap;
    /** Radius R2 of the die's cavity (mm). */
    double die_radius;
    /** Radius R3 of the die's shoulder fillet (mm). */
    double shoulder_radius;
    /** Half the sheet's length, the modelled part x >= 0 (mm). */
    double sheet_half_length;
    /** Sheet thickness (mm). */
    double thickness;
    /** Width of the full strip, the plane-strain depth (mm). */
    double width;
    /** True for the 3D model of the strip: a quarter model, 0 <= z <= W/2
     * with the symmetry plane z = 0 and the free edge z = W/2; false for
     * plane strain. */
    bool three_d;

    /** x of the shoulder fillet's centre, R2 + R3 (mm); its y is -R3, the
     * cavity's centre is (0, -R3). */
    double
    shoulder_centre_x() const;

    /** y of the punch's centre at the start, t + Rp + the initial punch
     * gap (mm); its x is 0, and the punch displacement d lowers it. */
    double
    punch_centre_y() const;

    /** The flange angle (deg, from the downward vertical, as the spec's
     * section 6.2 measures it) of a sheet that leaves the punch and the
     * die's shoulder along their common tangent, straight in between: the
     * tangent of the two circles the mid-surface follows when it lies on
     * the punch (radius Rp + t/2 about (0, t + Rp + gap - d)) and on the
     * shoulder (radius R3 + t/2 about (R2 + R3, -R3)), at punch
     * displacement @p d (mm) with the die in place. The tools alone fix
     * it: neither the material nor friction enter. */
    double
    straight_span_angle(const double d) const;
  };

  /** Subsection "Mesh". */
  struct MeshParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check the size of the mesh (its cells across the width
     * count only if @p three_d). */
    void
    parse_parameters(ParameterHandler &prm, const bool three_d);

    /** Degree of the Lagrange element (1 or 2). */
    unsigned int element_degree;
    /** Cells through the thickness, along the half-length and, in 3D,
     * across the half-width. */
    unsigned int n_cells_thickness;
    unsigned int n_cells_length;
    unsigned int n_cells_width;
    /** Largest random shift of the sheet's interior vertices, as a
     * fraction of the shortest edge at each (0 to 0.3, dimensionless). */
    double interior_perturbation;
  };

  /** Subsection "Release" and the measurement of the angles. */
  struct ReleaseParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check against the load program (@p n_stages stages) and
     * the sheet's half-length. */
    void
    parse_parameters(ParameterHandler  &prm,
                     const unsigned int n_stages,
                     const double       sheet_half_length);

    /** First stage (from 1) of the release, 0 if the program only forms:
     * from its start the sheet's mid-thickness node on the axis is held
     * where it is. */
    unsigned int release_stage;
    /** Reference arc length s where the flange chord starts; it ends at
     * the sheet's end (mm). */
    double chord_start;
    /** Length of the end piece whose direction is the end-tangent angle
     * (mm). */
    double end_tangent_length;
  };

  /** The load channels: the downward displacements of punch and die. */
  std::vector<Common::Solvers::LoadChannel>
  load_channels();

  /**
   * All parameters of a sheet_forming run, read from one .prm file.
   */
  struct Parameters : Common::Problems::ContactRunParameters
  {
    /** Declare, parse and check every entry of @p filename. */
    explicit Parameters(const std::string &filename);

    /** Declare every entry (also used by --print-parameters). */
    static void
    declare_parameters(ParameterHandler &prm);

    GeometryParameters                         geometry;
    MeshParameters                             mesh;
    ReleaseParameters                          release;
    Common::Materials::SolidMaterialParameters sheet_material;
  };
} // namespace SheetForming

#endif
