#include "parameters.h"

#include <common/geometry/two_body_meshes.h>
#include <common/io/parameter_values.h>

#include <cmath>
#include <sstream>

namespace ReynoldsRoller
{
  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Roller radius",
                        "30",
                        Patterns::Double(),
                        "Radius R of the rigid roller; its centre is at "
                        "(0, H/2 + R), its lowest point touches the strip's "
                        "top at the start. Units: mm.");
      prm.declare_entry("Strip length behind the roller",
                        "60",
                        Patterns::Double(),
                        "Length L1 of the strip behind the roller's axis, "
                        "x from -L1 to 0; point A is the strip's top-left "
                        "corner (-L1, H/2). Units: mm, larger than R.");
      prm.declare_entry("Strip length ahead of the roller",
                        "240",
                        Patterns::Double(),
                        "Length L2 of the strip ahead of the roller's axis, "
                        "x from 0 to L2: the strip moves by about -175 mm "
                        "in a full turn, and the roller must stay on it. "
                        "Units: mm, larger than R.");
      prm.declare_entry("Strip thickness",
                        "20",
                        Patterns::Double(),
                        "Thickness H of the rubber strip, y from -H/2 to "
                        "H/2. Units: mm.");
      prm.declare_entry(
        "Dimension",
        "plane strain",
        Patterns::Selection("plane strain|3d extrusion"),
        "The model: 'plane strain' (the x-y section, forces per mm of "
        "depth) or '3d extrusion' (strip and roller extruded along z by "
        "'Width', u_z = 0 on the strip's faces z = 0 and z = W: the "
        "plane-strain problem solved in 3D; forces are reported per mm of "
        "depth as well).");
      prm.declare_entry("Width",
                        "10",
                        Patterns::Double(),
                        "Width W of the 3D extrusion, z from 0 to W; "
                        "ignored in plane strain. Units: mm.");
      prm.declare_entry(
        "Roller",
        "rigid",
        Patterns::Selection("rigid|elastic"),
        "The steel roller: 'rigid' (an analytic circle turned about its "
        "axis, the spec's allowed replacement: E_steel / E_rubber = 21000) "
        "or 'elastic' (a meshed ring of 'Roller material', outer radius R, "
        "whose hub of radius 'Roller hub radius' is turned rigidly about "
        "the axis; plane strain only).");
      prm.declare_entry("Roller hub radius",
                        "15",
                        Patterns::Double(),
                        "Radius of the elastic roller's hub, the inner "
                        "boundary of the ring, whose nodes are turned "
                        "rigidly by the channel 'Roller angle'; below the "
                        "roller radius. Units: mm.");
      prm.declare_entry("Initial gap",
                        "0",
                        Patterns::Double(),
                        "Distance by which the roller starts above the "
                        "strip's top (negative: an overlap, the roller "
                        "starts pressed into it), for tests of initial gaps; "
                        "0 for the benchmark. The roller's axis is at "
                        "(0, H/2 + R + gap); 'Indentation' moves the strip "
                        "toward it from there. At most 1 % of the roller "
                        "radius either way. Units: mm.");
    }
    prm.leave_subsection();
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    const std::string s = "Geometry";
    prm.enter_subsection(s);
    {
      roller_radius = Common::IO::get_positive_length(prm, s, "Roller radius");
      length_behind =
        Common::IO::get_positive_length(prm,
                                        s,
                                        "Strip length behind the roller");
      length_ahead =
        Common::IO::get_positive_length(prm,
                                        s,
                                        "Strip length ahead of the roller");
      thickness = Common::IO::get_positive_length(prm, s, "Strip thickness");
      three_d   = (prm.get("Dimension") == "3d extrusion");
      width     = Common::IO::get_positive_length(prm, s, "Width");
      elastic_roller = (prm.get("Roller") == "elastic");
      hub_radius = Common::IO::get_positive_length(prm, s, "Roller hub radius");
      initial_gap = prm.get_double("Initial gap");
    }
    prm.leave_subsection();
    AssertThrow(std::abs(initial_gap) <= 0.01 * roller_radius,
                ExcMessage("Geometry: 'Initial gap' must be at most 1 % of "
                           "the roller radius either way."));
    AssertThrow(!elastic_roller || hub_radius < roller_radius,
                ExcMessage("Geometry: 'Roller hub radius' must be below "
                           "'Roller radius'."));
    AssertThrow(!elastic_roller || !three_d,
                ExcMessage("Geometry: 'Roller = elastic' is a plane-strain "
                           "model; the 3D extrusion has the rigid roller."));
    AssertThrow(length_behind > roller_radius && length_ahead > roller_radius,
                ExcMessage("Geometry: 'Strip length behind the roller' and "
                           "'Strip length ahead of the roller' must exceed "
                           "'Roller radius', so that the contact zone lies "
                           "on the strip."));
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      prm.declare_entry("Element degree",
                        "2",
                        Patterns::Integer(1, 2),
                        "Degree of the Lagrange element of the "
                        "displacement: 1 or 2 (with 'Element technology = "
                        "mixed': Q1-P0 or Q2-P1).");
      prm.declare_entry("Number of cells along the length",
                        "75",
                        Patterns::Integer(4, 4000),
                        "Cells along the strip, L1 + L2 (uniform); with "
                        "those through the thickness at most 100000 "
                        "cells.");
      prm.declare_entry("Number of cells through the thickness",
                        "5",
                        Patterns::Integer(1, 200),
                        "Cells through the strip's thickness (uniform).");
      prm.declare_entry("Number of cells across the width",
                        "1",
                        Patterns::Integer(1, 200),
                        "Cells across the width W of the 3D extrusion "
                        "(uniform); ignored in plane strain.");
      prm.declare_entry("Number of cells around the roller",
                        "48",
                        Patterns::Integer(8, 2000),
                        "Cells around the elastic roller's ring (uniform; "
                        "48 makes faces of 3.9 mm on R = 30, as long as the "
                        "strip's cells of the production mesh); ignored for "
                        "the rigid roller.");
      prm.declare_entry("Number of cells across the ring",
                        "2",
                        Patterns::Integer(1, 100),
                        "Cells across the elastic roller's ring, from the "
                        "hub to the rim (uniform); ignored for the rigid "
                        "roller.");
      prm.declare_entry(
        "Interior node perturbation",
        "0",
        Patterns::Double(0., 0.3),
        "Move every vertex inside the strip in a random direction by up to "
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
      n_cells_length = prm.get_integer("Number of cells along the length");
      n_cells_thickness =
        prm.get_integer("Number of cells through the thickness");
      n_cells_around_roller =
        prm.get_integer("Number of cells around the roller");
      n_cells_across_ring = prm.get_integer("Number of cells across the ring");
      interior_perturbation = prm.get_double("Interior node perturbation");
      n_cells_width =
        three_d ? prm.get_integer("Number of cells across the width") : 1;
    }
    prm.leave_subsection();
    // Refused before the mesh is built: 1e5 Q2-P1 cells are some 8e5
    // DoFs in 2D, what a direct solver handles on a workstation; a 3D
    // cell has about three times the DoFs of a 2D one.
    const std::uint64_t max_cells = three_d ? 30000 : 100000;
    const std::uint64_t n_cells   = static_cast<std::uint64_t>(n_cells_length) *
                                  n_cells_thickness * n_cells_width;
    Common::Geometry::check_cell_count(
      n_cells,
      max_cells,
      "'Number of cells along the length' times 'Number of cells through "
      "the thickness' (and across the width in 3D)");
  }



  void
  SupportParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Supports");
    {
      prm.declare_entry("Bottom free in x from stage",
                        "2",
                        Patterns::Integer(0, 6),
                        "The strip's bottom is pushed up by the channel "
                        "'Indentation' throughout; it is held at u_x = 0 "
                        "before this stage of the load program (from 1) "
                        "and free in x from its start (the benchmark: held "
                        "while pressing, free while rolling). 1: free "
                        "throughout, the strip held in x by friction "
                        "alone; 0: held throughout (without friction "
                        "nothing else holds it).");
    }
    prm.leave_subsection();
  }



  void
  SupportParameters::parse_parameters(ParameterHandler  &prm,
                                      const unsigned int n_stages)
  {
    prm.enter_subsection("Supports");
    bottom_free_stage = prm.get_integer("Bottom free in x from stage");
    prm.leave_subsection();
    AssertThrow(bottom_free_stage <= n_stages,
                ExcMessage("Supports: 'Bottom free in x from stage' must be "
                           "a stage of the load program's " +
                           std::to_string(n_stages) + "."));
  }



  std::vector<Common::Solvers::LoadChannel>
  load_channels()
  {
    return {{"Indentation",
             "Upward displacement of the strip's bottom at the end of the "
             "stage, which presses the strip onto the roller (the "
             "benchmark: 3, then held). Units: mm, from 0 to less than "
             "half the strip's thickness."},
            {"Roller angle",
             "Clockwise rotation of the roller about its fixed axis at the "
             "end of the stage, seen from +z with x to the right and y up "
             "(the benchmark: 0 while pressing, then 360); the strip "
             "travels about R theta, which must leave the roller on it. "
             "Units: degrees."},
            {"Bottom x release",
             "Fraction of the horizontal reaction of the bottom's support "
             "that is released at the end of the stage. When the support is "
             "freed ('Supports/Bottom free in x from stage'), its reaction "
             "is applied to the bottom's nodes as a force times one less "
             "this fraction: 1 releases it at once; 0 at the end of the "
             "last held stage and 1 at the end of the next releases it "
             "gradually over that stage. No effect while the support holds "
             "or if it never held. Dimensionless, from 0 to 1."}};
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    SupportParameters::declare_parameters(prm);
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Rubber material");
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Roller material");
    Common::Problems::ContactRunParameters::declare_parameters(
      prm,
      load_channels(),
      {{"Indentation", 3.}, {"Roller angle", 0.}, {"Bottom x release", 1.}});
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
    supports.parse_parameters(prm, load_program.stages.size());
    for (unsigned int s = 0; s < load_program.stages.size(); ++s)
      {
        const double d = load_program.stages[s].end_values.at("Indentation");
        std::ostringstream text;
        text << "Load program/Stage " << s + 1
             << ": 'Indentation' must lie in [0, H/2) = [0, "
             << 0.5 * geometry.thickness
             << ") mm (the bottom pushes the strip onto the roller, by less "
                "than half its thickness), got "
             << d << ".";
        AssertThrow(d >= 0. && d < 0.5 * geometry.thickness,
                    ExcMessage(text.str()));
        // The strip travels about R theta against the turn: the roller
        // must stay on it, a radius from its end.
        const double angle =
          load_program.stages[s].end_values.at("Roller angle");
        const double travel =
          geometry.roller_radius * std::abs(angle) * numbers::PI / 180.;
        const double room =
          (angle >= 0. ? geometry.length_ahead : geometry.length_behind) -
          geometry.roller_radius;
        std::ostringstream turn;
        turn << "Load program/Stage " << s + 1
             << ": 'Roller angle' turns the strip by about R theta = " << travel
             << " mm, more than the " << room
             << " mm of strip beyond the roller's contact zone, got " << angle
             << ".";
        AssertThrow(travel <= room, ExcMessage(turn.str()));
        const double fraction =
          load_program.stages[s].end_values.at("Bottom x release");
        std::ostringstream release;
        release << "Load program/Stage " << s + 1
                << ": 'Bottom x release' must lie in [0, 1], got " << fraction
                << ".";
        AssertThrow(fraction >= 0. && fraction <= 1.,
                    ExcMessage(release.str()));
      }
    rubber_material.parse_parameters(prm,
                                     "Rubber material",
                                     solid.finite_strain());
    roller_material.parse_parameters(prm,
                                     "Roller material",
                                     solid.finite_strain());
  }
} // namespace ReynoldsRoller
