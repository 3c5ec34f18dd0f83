#include "parameters.h"

#include <common/io/parameter_values.h>
#include <common/solvers/load_program.h>

#include <cmath>


namespace Punch3d
{
  void
  ModelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    {
      prm.declare_entry(
        "Dimension",
        "axisymmetric",
        Patterns::Selection("axisymmetric|3d quarter"),
        "The model of the bodies of revolution: 'axisymmetric' (the meridian "
        "section (r, z), 2D) or '3d quarter' (the same meridian meshes "
        "revolved through 90 degrees into 3D solids, with symmetry "
        "conditions on the planes x = 0 and z = 0; y is the axis). Results "
        "are reported along r on the plane z = 0, and forces for the full "
        "bodies (N).");
      prm.declare_entry(
        "Punch",
        "elastic",
        Patterns::Selection("elastic|rigid|rigid surface"),
        "How the punch responds: 'elastic' (the benchmark: a linear "
        "elastic body with the entries of 'Punch material'); 'rigid': the "
        "meshed punch translates along the axis without deforming, and the "
        "pressure on its top acts as their resultant; 'rigid surface': the "
        "same rigid punch without its mesh, its contact face an analytic "
        "surface (the flat face and the fillet, revolved in 3D) that moves "
        "with a reference node, which a single coarse cell at the top of "
        "the punch carries together with the pressure. 'rigid' measures "
        "what the punch's elasticity contributes, 'rigid surface' what "
        "meshing the rigid punch contributes; the half-space reference then "
        "takes an infinite punch modulus.");
    }
    prm.leave_subsection();
  }



  void
  ModelParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    {
      three_d       = (prm.get("Dimension") == "3d quarter");
      rigid_surface = (prm.get("Punch") == "rigid surface");
      rigid_punch   = (prm.get("Punch") == "rigid") || rigid_surface;
    }
    prm.leave_subsection();
  }



  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Punch radius",
                        "50",
                        Patterns::Double(0.),
                        "Radius of the cylindrical punch. Units: mm.");
      prm.declare_entry("Punch height",
                        "100",
                        Patterns::Double(0.),
                        "Height of the punch. Units: mm.");
      prm.declare_entry("Fillet radius",
                        "10",
                        Patterns::Double(0.),
                        "Radius of the rounded edge between the punch's "
                        "flat face and its side; less than 0.4 times the "
                        "punch radius and a third of the punch height. "
                        "Equal to the punch radius, the punch ends in a "
                        "hemisphere (Hertz point contact, a verification "
                        "case of both models; the punch height must then "
                        "exceed 1.5 punch radii). Units: mm.");
      prm.declare_entry("Foundation radius",
                        "100",
                        Patterns::Double(0.),
                        "Radius of the cylindrical foundation; larger than "
                        "the punch radius. Units: mm.");
      prm.declare_entry("Foundation height",
                        "200",
                        Patterns::Double(0.),
                        "Height of the foundation. Units: mm.");
      prm.declare_entry("Initial gap",
                        "0",
                        Patterns::Double(),
                        "Distance by which the punch starts above the "
                        "foundation (negative: an overlap, the punch starts "
                        "pressed into it), for tests of initial gaps; 0 for "
                        "the benchmark. At most 1 % of the punch radius "
                        "either way. Units: mm.");
    }
    prm.leave_subsection();
  }



  double
  GeometryParameters::punch_base() const
  {
    return foundation_height + initial_gap;
  }



  bool
  GeometryParameters::hemispherical_end() const
  {
    return std::abs(fillet_radius - punch_radius) <= 1e-12 * punch_radius;
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      const std::string s = "Geometry";
      punch_radius  = Common::IO::get_positive_length(prm, s, "Punch radius");
      punch_height  = Common::IO::get_positive_length(prm, s, "Punch height");
      fillet_radius = Common::IO::get_positive_length(prm, s, "Fillet radius");
      foundation_radius =
        Common::IO::get_positive_length(prm, s, "Foundation radius");
      foundation_height =
        Common::IO::get_positive_length(prm, s, "Foundation height");
      initial_gap = prm.get_double("Initial gap");
    }
    prm.leave_subsection();
    AssertThrow(std::abs(initial_gap) <= 0.01 * punch_radius,
                ExcMessage("Geometry: 'Initial gap' must be at most 1 % of "
                           "the punch radius either way."));
    AssertThrow((fillet_radius > 0. && fillet_radius < 0.4 * punch_radius &&
                 3. * fillet_radius < punch_height) ||
                  (hemispherical_end() && punch_height > 1.5 * punch_radius),
                ExcMessage("Geometry: 'Fillet radius' must be positive and "
                           "less than 0.4 times the punch radius and a third "
                           "of its height, or equal to the punch radius "
                           "with a height above 1.5 punch radii."));
    AssertThrow(foundation_radius > punch_radius,
                ExcMessage("Geometry: 'Foundation radius' must exceed the "
                           "punch radius."));
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      Common::Geometry::MeshParameters::declare_parameters(
        prm,
        {"about a quarter of the punch radius",
         "the contact strip (the foundation top under the punch and the "
         "punch's flat face and fillet)",
         4,
         12,
         "punch",
         "foundation"});
      prm.declare_entry("Number of edge refinements",
                        "3",
                        Patterns::Integer(0, 12),
                        "Further graded refinements toward the contact "
                        "edge, the strip from the start of the fillet to "
                        "half the fillet radius beyond it, where the "
                        "pressure peaks (with a hemispherical end: from "
                        "the axis to 1.25 times the Hertz contact "
                        "radius).");
    }
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      Common::Geometry::MeshParameters::parse_parameters(prm);
      n_edge_refinements = prm.get_integer("Number of edge refinements");
    }
    prm.leave_subsection();
  }



  void
  LoadingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    {
      prm.declare_entry("Pressure",
                        "100",
                        Patterns::Double(0.),
                        "Uniform pressure on the top face of the punch, "
                        "from 1e-9 to 1e9. Units: MPa.");
    }
    prm.leave_subsection();
  }



  void
  LoadingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    {
      pressure = prm.get_double("Pressure");
    }
    prm.leave_subsection();
    AssertThrow(pressure > 0.,
                ExcMessage("Loading: 'Pressure' must be positive."));
    Common::Solvers::LoadProgramParameters::check_load_magnitude(
      "Loading: 'Pressure'",
      pressure,
      "MPa");
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    ModelParameters::declare_parameters(prm);
    GeometryParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    LoadingParameters::declare_parameters(prm);
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Punch material");
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Foundation material");
    Common::Problems::ContactRunParameters::declare_parameters(prm);
  }



  Parameters::Parameters(const std::string &filename)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    prm.parse_input(filename);

    model.parse_parameters(prm);
    geometry.parse_parameters(prm);
    mesh.parse_parameters(prm);
    loading.parse_parameters(prm);
    Common::Problems::ContactRunParameters::parse_parameters(prm);
    punch_material.parse_parameters(prm,
                                    "Punch material",
                                    solid.finite_strain());
    foundation_material.parse_parameters(prm,
                                         "Foundation material",
                                         solid.finite_strain());
  }



  bool
  Parameters::benchmark_bodies_and_load() const
  {
    const auto equal = [](const double value, const double benchmark) {
      return std::abs(value - benchmark) <= 1e-12 * std::abs(benchmark);
    };
    return equal(geometry.punch_radius, 50.) &&
           equal(geometry.punch_height, 100.) &&
           equal(geometry.fillet_radius, 10.) &&
           equal(geometry.foundation_radius, 100.) &&
           equal(geometry.foundation_height, 200.) &&
           equal(foundation_material.youngs_modulus, 70000.) &&
           equal(foundation_material.poisson_ratio, 0.3) &&
           equal(loading.pressure, 100.);
  }
} // namespace Punch3d
