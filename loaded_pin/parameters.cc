#include "parameters.h"

#include <common/solvers/load_program.h>

namespace LoadedPin
{
  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Hole radius",
                        "50",
                        Patterns::Double(),
                        "Radius of the hole in the lug. Units: mm.");
      prm.declare_entry("Clearance",
                        "0",
                        Patterns::Double(),
                        "Radial clearance between hole and pin (the "
                        "benchmark: 0, the pin fits the hole), less than "
                        "half the hole radius; negative for an interference "
                        "fit of at most 1 % of the hole radius. The pin's "
                        "radius is the hole radius minus the clearance. "
                        "Units: mm.");
      prm.declare_entry("Outer radius",
                        "100",
                        Patterns::Double(),
                        "Radius of the lug's rounded end about the hole "
                        "axis, also half the lug's width; larger than the "
                        "hole radius. Units: mm.");
      prm.declare_entry("Sheet length",
                        "200",
                        Patterns::Double(),
                        "Distance from the clamped end of the lug to the "
                        "hole axis; larger than the outer radius. Units: "
                        "mm.");
      prm.declare_entry("Sheet thickness",
                        "10",
                        Patterns::Double(),
                        "Thickness of the lug. Units: mm.");
      prm.declare_entry("Pin length",
                        "20",
                        Patterns::Double(),
                        "Length of the pin, centred on the lug's "
                        "mid-plane; at least the sheet thickness. Units: "
                        "mm.");
    }
    prm.leave_subsection();
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      hole_radius     = prm.get_double("Hole radius");
      clearance       = prm.get_double("Clearance");
      outer_radius    = prm.get_double("Outer radius");
      sheet_length    = prm.get_double("Sheet length");
      sheet_thickness = prm.get_double("Sheet thickness");
      pin_length      = prm.get_double("Pin length");
    }
    prm.leave_subsection();
    check();
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      Common::Geometry::MeshParameters::declare_parameters(
        prm,
        {"of 30 to 50 mm in the plane and one sheet thickness along the "
         "pin axis",
         "the contact surface (the hole's cylinder over the sheet "
         "thickness)",
         2,
         8,
         "pin",
         "sheet"});
      prm.declare_entry("Number of sheet layers",
                        "1",
                        Patterns::Integer(1, 16),
                        "Coarse cell layers through the half-thickness of "
                        "the sheet (the quarter model), before refinement.");
      prm.declare_entry("Number of pin layers",
                        "2",
                        Patterns::Integer(1, 32),
                        "Coarse cell layers through the half-length of the "
                        "pin, before refinement; twice the sheet layers "
                        "(with the benchmark's dimensions) puts pin "
                        "vertices on the plane of the sheet's face.");
      prm.declare_entry("Number of arc end refinements",
                        "0",
                        Patterns::Integer(0, 8),
                        "Further graded refinements toward the line of the "
                        "contact surface at 'Arc end angle' (over the "
                        "sheet thickness), where the contact arc ends: "
                        "each halves the cell size there, on the hole and "
                        "on the pin.");
      prm.declare_entry("Arc end angle",
                        "90",
                        Patterns::Double(0., 180.),
                        "Angle theta of the line that 'Number of arc end "
                        "refinements' grade toward, theta = 180 - atan2(y, "
                        "x) about the hole centre (0 faces the clamp, 180 "
                        "the load): where the contact arc ends (a coarse "
                        "run gives it). Units: degrees, 0 to 180.");
    }
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      Common::Geometry::MeshParameters::parse_parameters(prm);
      n_sheet_layers        = prm.get_integer("Number of sheet layers");
      n_pin_layers          = prm.get_integer("Number of pin layers");
      n_arc_end_refinements = prm.get_integer("Number of arc end refinements");
      arc_end_angle         = prm.get_double("Arc end angle");
    }
    prm.leave_subsection();
  }



  MeshOptions
  MeshParameters::options() const
  {
    MeshOptions options;
    options.n_global_refinements  = n_global_refinements;
    options.n_contact_refinements = n_contact_refinements;
    options.grading_factor        = grading_factor;
    options.n_sheet_layers        = n_sheet_layers;
    options.n_pin_layers          = n_pin_layers;
    options.n_arc_end_refinements = n_arc_end_refinements;
    options.arc_end_angle         = arc_end_angle;
    options.size_ratio_exponent   = size_ratio_exponent;
    options.interior_perturbation = interior_perturbation;
    return options;
  }



  void
  LoadingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    {
      prm.declare_entry("Total force",
                        "",
                        Patterns::Anything(),
                        "Required. Total force on the pin of the full "
                        "model (the benchmark: 100000), the sum of two "
                        "equal point forces at the centres of the pin's end "
                        "faces, along +x (away from the clamped end); the "
                        "quarter model carries a quarter of it. From 1e-9 "
                        "to 1e9. Units: N.");
    }
    prm.leave_subsection();
  }



  void
  LoadingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    {
      const std::string value = prm.get("Total force");
      AssertThrow(!value.empty(),
                  ExcMessage("Loading: 'Total force' is missing; give the "
                             "total force on the pin in N."));
      AssertThrow(Patterns::Double().match(value),
                  ExcMessage("Loading: 'Total force' must be a number (N), "
                             "not '" +
                             value + "'."));
      total_force = prm.get_double("Total force");
    }
    prm.leave_subsection();
    AssertThrow(total_force > 0.,
                ExcMessage("Loading: 'Total force' must be positive."));
    Common::Solvers::LoadProgramParameters::check_load_magnitude(
      "Loading: 'Total force'",
      total_force,
      "N");
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    LoadingParameters::declare_parameters(prm);
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Pin material");
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Sheet material");
    Common::Problems::ContactRunParameters::declare_parameters(prm);
  }



  Parameters::Parameters(const std::string &filename)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    prm.parse_input(filename);

    geometry.parse_parameters(prm);
    mesh.parse_parameters(prm);
    loading.parse_parameters(prm);
    Common::Problems::ContactRunParameters::parse_parameters(prm);
    pin_material.parse_parameters(prm, "Pin material", solid.finite_strain());
    sheet_material.parse_parameters(prm,
                                    "Sheet material",
                                    solid.finite_strain());
  }
} // namespace LoadedPin
