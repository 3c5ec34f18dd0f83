#include "parameters.h"

#include <common/io/parameter_values.h>

#include <cmath>
#include <sstream>


namespace CgsRoller
{
  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Roller radius",
                        "50",
                        Patterns::Double(0.),
                        "Radius of the cylinder. Units: mm.");
      prm.declare_entry("Block half width",
                        "100",
                        Patterns::Double(0.),
                        "Width of the modelled half of the block, from the "
                        "symmetry line. Must exceed the roller radius. "
                        "Units: mm.");
      prm.declare_entry("Block height",
                        "200",
                        Patterns::Double(0.),
                        "Height of the block. Units: mm.");
      prm.declare_entry("Initial gap",
                        "0",
                        Patterns::Double(),
                        "Distance by which the roller starts above the "
                        "block (negative: an overlap, the roller starts "
                        "pressed into it), for tests of initial gaps; 0 "
                        "for the benchmark. At most 1 % of the roller "
                        "radius either way. Units: mm.");
    }
    prm.leave_subsection();
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      const std::string s = "Geometry";
      roller_radius = Common::IO::get_positive_length(prm, s, "Roller radius");
      block_half_width =
        Common::IO::get_positive_length(prm, s, "Block half width");
      block_height = Common::IO::get_positive_length(prm, s, "Block height");
      initial_gap  = prm.get_double("Initial gap");
    }
    prm.leave_subsection();
    AssertThrow(std::abs(initial_gap) <= 0.01 * roller_radius,
                ExcMessage("Geometry: 'Initial gap' must be at most 1 % of "
                           "the roller radius either way."));
    AssertThrow(block_half_width > roller_radius,
                ExcMessage("Geometry: 'Block half width' must exceed the "
                           "roller radius."));
  }



  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      Common::Geometry::MeshParameters::declare_parameters(
        prm,
        {"about half the roller radius",
         "the contact strip",
         6,
         14,
         "roller",
         "block"});
      prm.declare_entry("Contact zone length",
                        "8",
                        Patterns::Double(0.),
                        "Length of the block surface strip, from the "
                        "symmetry line, refined most. Should exceed the "
                        "contact half-width. Units: mm.");
    }
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      Common::Geometry::MeshParameters::parse_parameters(prm);
      contact_zone_length = prm.get_double("Contact zone length");
    }
    prm.leave_subsection();
  }



  void
  LoadingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    {
      prm.declare_entry("Force per unit thickness",
                        "35000",
                        Patterns::Double(0.),
                        "Vertical point force on the top of the roller, per "
                        "unit thickness of the full model; the half model "
                        "carries half of it. Units: N/mm.");
    }
    prm.leave_subsection();
  }



  void
  LoadingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    {
      force_per_thickness = prm.get_double("Force per unit thickness");
    }
    prm.leave_subsection();
    AssertThrow(force_per_thickness > 0.,
                ExcMessage("Loading: 'Force per unit thickness' must be "
                           "positive."));
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    LoadingParameters::declare_parameters(prm);
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Roller material");
    Common::Materials::SolidMaterialParameters::declare_parameters(
      prm,
      "Block material");
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
    roller_material.parse_parameters(prm,
                                     "Roller material",
                                     solid.finite_strain());
    block_material.parse_parameters(prm,
                                    "Block material",
                                    solid.finite_strain());
    // Every step's results are compared with Hertz's solution, which
    // presses the roller onto the block.
    const std::string channel = Common::Solvers::load_factor_channel().name;
    for (unsigned int s = 0; s < load_program.stages.size(); ++s)
      {
        const double value = load_program.stages[s].end_values.at(channel);
        std::ostringstream text;
        text << "Load program/Stage " << s + 1 << ": '" << channel
             << "' must not be negative (the roller is pressed onto the "
                "block), got "
             << value << ".";
        AssertThrow(value >= 0., ExcMessage(text.str()));
      }
  }
} // namespace CgsRoller
