#include "parameters.h"

#include <common/geometry/two_body_meshes.h>
#include <common/io/parameter_values.h>

#include <cmath>

namespace SheetForming
{
  double
  GeometryParameters::shoulder_centre_x() const
  {
    return die_radius + shoulder_radius;
  }



  double
  GeometryParameters::punch_centre_y() const
  {
    return thickness + punch_radius + initial_punch_gap;
  }



  double
  GeometryParameters::straight_span_angle(const double d) const
  {
    const double r_punch    = punch_radius + 0.5 * thickness;
    const double r_shoulder = shoulder_radius + 0.5 * thickness;
    const double dx         = shoulder_centre_x();
    const double dy         = -shoulder_radius - (punch_centre_y() - d);
    const double distance   = std::hypot(dx, dy);
    // The line crosses between the centres (the sheet lies outside the
    // punch and above the shoulder): it makes the angle
    // asin((r_punch + r_shoulder) / distance) with the line of centres.
    const double rise =
      std::atan2(dy, dx) +
      std::asin(std::min(1., (r_punch + r_shoulder) / distance));
    return 90. - rise * 180. / numbers::PI;
  }



  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Punch radius",
                        "23.5",
                        Patterns::Double(),
                        "Radius Rp of the cylindrical punch; its lowest "
                        "point touches the sheet's top at the start. "
                        "Units: mm.");
      prm.declare_entry("Initial punch gap",
                        "0",
                        Patterns::Double(),
                        "Distance by which the punch starts above the "
                        "sheet's top (negative: an overlap, the punch "
                        "starts pressed into it), for tests of initial "
                        "gaps; 0 for the benchmark. 'Punch displacement' "
                        "moves it from there. At most 10 % of the sheet "
                        "thickness either way. Units: mm.");
      prm.declare_entry("Die radius",
                        "25",
                        Patterns::Double(),
                        "Radius R2 of the die's half-cylindrical cavity, "
                        "centred on the axis at the depth of the shoulder "
                        "centres, y = -R3; at least the punch radius plus "
                        "the sheet thickness. Units: mm.");
      prm.declare_entry("Die shoulder radius",
                        "4",
                        Patterns::Double(),
                        "Radius R3 of the die's shoulder fillet, centred at "
                        "(R2 + R3, -R3), joining the cavity to the flat "
                        "top y = 0. Units: mm.");
      prm.declare_entry("Sheet half-length",
                        "60",
                        Patterns::Double(),
                        "Half the sheet's length, the modelled part "
                        "0 <= x <= L/2 (half model); larger than R2 + R3, "
                        "so that the sheet rests on the die's flat top. "
                        "Units: mm.");
      prm.declare_entry("Sheet thickness",
                        "1",
                        Patterns::Double(),
                        "Thickness of the sheet, 0 <= y <= t. Units: mm.");
      prm.declare_entry("Sheet width",
                        "30",
                        Patterns::Double(),
                        "Width of the full strip, the depth of the plane "
                        "strain model: forces are reported for the full "
                        "strip, 2 x width x the force per unit depth of the "
                        "half model; in 3D the strip's width. Units: mm.");
      prm.declare_entry(
        "Dimension",
        "plane strain",
        Patterns::Selection("plane strain|3d strip"),
        "The model: 'plane strain' (the x-y section of the half model, the "
        "benchmark's) or '3d strip' (the strip as a 3D body, a quarter "
        "model 0 <= z <= W/2 with the symmetry plane z = 0 and its edge "
        "z = W/2 free, against the tools extruded along z; they are wider "
        "than the strip). Angles are measured on the plane z = 0, forces "
        "are for the full strip.");
    }
    prm.leave_subsection();
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    const std::string s = "Geometry";
    prm.enter_subsection(s);
    {
      punch_radius = Common::IO::get_positive_length(prm, s, "Punch radius");
      die_radius   = Common::IO::get_positive_length(prm, s, "Die radius");
      shoulder_radius =
        Common::IO::get_positive_length(prm, s, "Die shoulder radius");
      sheet_half_length =
        Common::IO::get_positive_length(prm, s, "Sheet half-length");
      thickness = Common::IO::get_positive_length(prm, s, "Sheet thickness");
      width     = Common::IO::get_positive_length(prm, s, "Sheet width");
      three_d   = (prm.get("Dimension") == "3d strip");
      initial_punch_gap = prm.get_double("Initial punch gap");
    }
    prm.leave_subsection();
    AssertThrow(std::abs(initial_punch_gap) <= 0.1 * thickness,
                ExcMessage("Geometry: 'Initial punch gap' must be at most "
                           "10 % of the sheet thickness either way."));
    AssertThrow(die_radius >= punch_radius + thickness,
                ExcMessage("Geometry: the sheet does not fit between punch "
                           "and die: 'Die radius' must be at least 'Punch "
                           "radius' plus 'Sheet thickness'."));
    AssertThrow(sheet_half_length > shoulder_centre_x(),
                ExcMessage("Geometry: 'Sheet half-length' must exceed 'Die "
                           "radius' plus 'Die shoulder radius', so that "
                           "the sheet rests on the die's flat top."));
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      prm.declare_entry("Element degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Degree of the Lagrange element: 1 (with 'Element "
                        "technology = F-bar' the benchmark's 4-node "
                        "element) or 2.");
      prm.declare_entry("Number of cells through the thickness",
                        "4",
                        Patterns::Integer(1, 32),
                        "Cells through the sheet's thickness (uniform).");
      prm.declare_entry("Number of cells along the length",
                        "120",
                        Patterns::Integer(4, 4000),
                        "Cells along the sheet's half-length (uniform).");
      prm.declare_entry("Number of cells across the half-width",
                        "4",
                        Patterns::Integer(1, 200),
                        "Cells across the half-width W/2 of the 3D strip "
                        "(uniform); ignored in plane strain.");
      prm.declare_entry(
        "Interior node perturbation",
        "0",
        Patterns::Double(0., 0.3),
        "Move every vertex inside the sheet in a random direction by up to "
        "this fraction of the shortest edge at it (fixed seed: the same mesh "
        "at every run), for tests of distorted meshes; 0 for the regular "
        "mesh. Dimensionless, 0 to 0.3.");
    }
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler &prm, const bool three_d)
  {
    prm.enter_subsection("Mesh");
    {
      element_degree = prm.get_integer("Element degree");
      n_cells_thickness =
        prm.get_integer("Number of cells through the thickness");
      n_cells_length = prm.get_integer("Number of cells along the length");
      interior_perturbation = prm.get_double("Interior node perturbation");
      n_cells_width =
        three_d ? prm.get_integer("Number of cells across the half-width") : 1;
    }
    prm.leave_subsection();
    // Refused before the mesh is built: a direct solver on a workstation
    // takes some 1e5 2D or 3e4 3D Q2 cells.
    const std::uint64_t max_cells = three_d ? 30000 : 128000;
    const std::uint64_t n_cells   = static_cast<std::uint64_t>(n_cells_length) *
                                  n_cells_thickness * n_cells_width;
    Common::Geometry::check_cell_count(
      n_cells,
      max_cells,
      "'Number of cells along the length' times 'Number of cells through "
      "the thickness' (and across the half-width in 3D)");
  }



  void
  ReleaseParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Release");
    {
      prm.declare_entry("Release stage",
                        "2",
                        Patterns::Integer(0, 6),
                        "First stage of the load program (from 1) that "
                        "releases the sheet: from its start the sheet's "
                        "mid-thickness node on the axis is held where it "
                        "is (it removes the vertical rigid-body motion "
                        "once the tools let go; the released, tool-free "
                        "state carries no load there). The forming angle "
                        "is measured at the end of the stage before it, "
                        "the angle after release at the end of the "
                        "program. 0: the program only forms (the angles "
                        "are measured at its end).");
      prm.declare_entry("Flange chord start",
                        "50",
                        Patterns::Double(),
                        "Reference arc length s (the initial x) where the "
                        "chord of the mid-surface that defines the flange "
                        "angle starts; it ends at the sheet's end. Units: "
                        "mm, between 0 and the half-length.");
      prm.declare_entry("End tangent length",
                        "1",
                        Patterns::Double(),
                        "Length of the sheet's end piece of the "
                        "mid-surface whose direction gives the "
                        "end-tangent variant of the angles. Units: mm, "
                        "positive, at most the half-length.");
    }
    prm.leave_subsection();
  }



  void
  ReleaseParameters::parse_parameters(ParameterHandler  &prm,
                                      const unsigned int n_stages,
                                      const double       sheet_half_length)
  {
    prm.enter_subsection("Release");
    {
      release_stage      = prm.get_integer("Release stage");
      chord_start        = prm.get_double("Flange chord start");
      end_tangent_length = prm.get_double("End tangent length");
    }
    prm.leave_subsection();
    AssertThrow(release_stage == 0 ||
                  (release_stage >= 2 && release_stage <= n_stages),
                ExcMessage("Release: 'Release stage' must be 0 or a stage "
                           "after the first of the load program's " +
                           std::to_string(n_stages) + "."));
    AssertThrow(chord_start >= 0. && chord_start < sheet_half_length,
                ExcMessage("Release: 'Flange chord start' must lie on the "
                           "sheet, 0 <= s < half-length (mm)."));
    AssertThrow(end_tangent_length > 0. &&
                  end_tangent_length <= sheet_half_length,
                ExcMessage("Release: 'End tangent length' must be positive "
                           "and at most the half-length (mm)."));
  }



  std::vector<Common::Solvers::LoadChannel>
  load_channels()
  {
    return {{"Punch displacement",
             "Downward displacement of the punch at the end of the stage "
             "from its initial position, touching the sheet (the stroke: "
             "28.5); negative lifts it above that position. Units: mm."},
            {"Die displacement",
             "Downward displacement of the die at the end of the stage (0 "
             "while forming; a release lowers it). Units: mm."}};
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    ReleaseParameters::declare_parameters(prm);
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Sheet material");
    Common::Problems::ContactRunParameters::declare_parameters(
      prm,
      load_channels(),
      {{"Punch displacement", 28.5}, {"Die displacement", 0.}});
  }



  Parameters::Parameters(const std::string &filename)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    prm.parse_input(filename);

    geometry.parse_parameters(prm);
    mesh.parse_parameters(prm, geometry.three_d);
    Common::Problems::ContactRunParameters::parse_parameters(prm,
                                                             load_channels());
    release.parse_parameters(prm,
                             load_program.stages.size(),
                             geometry.sheet_half_length);
    AssertThrow(release.release_stage == 0 ||
                  mesh.n_cells_thickness * mesh.element_degree >= 2,
                ExcMessage("Mesh: the release holds a node inside the "
                           "sheet: 'Number of cells through the thickness' "
                           "must be at least 2 (1 with 'Element degree = "
                           "2')."));
    sheet_material.parse_parameters(prm,
                                    "Sheet material",
                                    solid.finite_strain());
  }
} // namespace SheetForming
