#include <common/geometry/mesh_parameters.h>

namespace Common
{
  namespace Geometry
  {
    using namespace dealii;

    void
    MeshParameters::declare_parameters(ParameterHandler  &prm,
                                       const Description &description)
    {
      prm.declare_entry("Element degree",
                        "2",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of the FE_Q displacement element "
                        "and of the geometry mapping (1: Q1, 2: Q2).");
      prm.declare_entry("Number of global refinements",
                        "0",
                        Patterns::Integer(0, 6),
                        "Uniform refinements of the coarse mesh (cells of " +
                          description.coarse_cells + ").");
      prm.declare_entry("Number of contact refinements",
                        std::to_string(description.default_contact_refinements),
                        Patterns::Integer(0,
                                          description.max_contact_refinements),
                        "Graded refinements toward " +
                          description.contact_target +
                          "; each halves the cell size there.");
      prm.declare_entry("Grading factor",
                        "2.0",
                        Patterns::Double(0.5),
                        "A cell is refined if its centre lies closer to the "
                        "target than this many cell diameters. "
                        "Dimensionless.");
    }



    void
    MeshParameters::parse_parameters(ParameterHandler &prm)
    {
      element_degree        = prm.get_integer("Element degree");
      n_global_refinements  = prm.get_integer("Number of global refinements");
      n_contact_refinements = prm.get_integer("Number of contact refinements");
      grading_factor        = prm.get_double("Grading factor");
    }
  } // namespace Geometry
} // namespace Common
