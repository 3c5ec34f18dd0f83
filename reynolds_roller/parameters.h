/*
 * Parameters of the reynolds_roller benchmark: the common blocks (solid,
 * contact, solvers, load program, output, run control) composed with the
 * blocks that only this benchmark has (roller and strip geometry, mesh,
 * supports, rubber material).
 */
#ifndef reynolds_roller_parameters_h
#define reynolds_roller_parameters_h

#include <common/materials/solid_material.h>
#include <common/problems/contact_run_parameters.h>
#include <common/solvers/load_program.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace ReynoldsRoller
{
  using namespace dealii;

  /** Subsection "Geometry" (../shared/specs/reynolds_roller.md section
   * 2): the strip x in [-L1, L2], y in [-H/2, H/2]; the roller's centre
   * (0, H/2 + R), so that it touches the strip's top at (0, H/2), raised
   * by the initial gap of the robustness tests. */
  struct GeometryParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check: every length positive, the roller's contact zone
     * (about R on either side of x = 0) on the strip. */
    void
    parse_parameters(ParameterHandler &prm);

    /** Roller radius R (mm). */
    double roller_radius;
    /** Strip length L1 behind the roller (x < 0) and L2 ahead (mm). */
    double length_behind, length_ahead;
    /** Strip thickness H (mm). */
    double thickness;
    /** True for the 3D extrusion (section 2, item 4 of the spec): both
     * bodies extruded by the width W along z, u_z = 0 on the strip's z
     * faces; false for plane strain. */
    bool three_d;
    /** Width W of the 3D extrusion, z from 0 to W (mm); forces are still
     * reported per mm of depth. */
    double width;
    /** True for the elastic steel roller (a meshed ring turned by its
     * hub), false for the rigid one (an analytic circle). */
    bool elastic_roller;
    /** Distance by which the roller starts above the strip's top (mm;
     * negative: an overlap); 0 for the benchmark. */
    double initial_gap;
    /** Radius of the elastic roller's hub, the inner boundary of the ring
     * that turns rigidly (mm). */
    double hub_radius;
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
    /** Cells along the strip, through its thickness and, in 3D, across
     * its width (uniform). */
    unsigned int n_cells_length, n_cells_thickness, n_cells_width;
    /** Cells of the elastic roller's ring around it and across it. */
    unsigned int n_cells_around_roller, n_cells_across_ring;
    /** Largest random move of the strip's interior vertices, as a fraction
     * of the shortest edge at each (Common::Geometry::
     * perturb_interior_vertices()); 0 for the regular mesh. */
    double interior_perturbation = 0.;
  };

  /** Subsection "Supports": the strip's bottom. */
  struct SupportParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check against the load program's @p n_stages stages. */
    void
    parse_parameters(ParameterHandler &prm, const unsigned int n_stages);

    /** First stage (from 1) in which the bottom is free in x; before it
     * every bottom node is held at u_x = 0. 1: free throughout; 0: held
     * throughout. */
    unsigned int bottom_free_stage;
  };

  /** The load channels: the indentation (the bottom's upward
   * displacement) and the roller's clockwise angle. */
  std::vector<Common::Solvers::LoadChannel>
  load_channels();

  /**
   * All parameters of a reynolds_roller run, read from one .prm file.
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
    SupportParameters                          supports;
    Common::Materials::SolidMaterialParameters rubber_material;
    /** The elastic roller's steel (read, and used only with 'Roller =
     * elastic'). */
    Common::Materials::SolidMaterialParameters roller_material;
  };
} // namespace ReynoldsRoller

#endif
