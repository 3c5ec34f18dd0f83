#include <common/geometry/mesh_parameters.h>
#include <common/geometry/two_body_meshes.h>

#include <cstdlib>

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
      prm.declare_entry(
        "Contact size ratio",
        "1",
        Patterns::Selection("1/8|1/4|1/2|1|2|4|8"),
        "Ratio of the " + description.first_body +
          "'s cell size at the contact to the " + description.second_body +
          "'s, for tests of non-matching meshes: 2, 4 or 8 refine the " +
          description.second_body +
          "'s cells near the contact 1, 2 or 3 more times, 1/2, 1/4 or 1/8 "
          "the " +
          description.first_body + "'s. Dimensionless.");
      prm.declare_entry(
        "Interior node perturbation",
        "0",
        Patterns::Double(0., 0.3),
        "Move every vertex on no boundary in a random direction by up to "
        "this fraction of the shortest edge at it (fixed seed: the same mesh "
        "at every run), for tests of distorted meshes; 0 for the regular "
        "mesh. Dimensionless, 0 to 0.3.");
    }



    void
    MeshParameters::parse_parameters(ParameterHandler &prm)
    {
      element_degree        = prm.get_integer("Element degree");
      n_global_refinements  = prm.get_integer("Number of global refinements");
      n_contact_refinements = prm.get_integer("Number of contact refinements");
      grading_factor        = prm.get_double("Grading factor");
      const std::string ratio = prm.get("Contact size ratio");
      size_ratio_exponent     = ratio == "1/8" ? -3 :
                                ratio == "1/4" ? -2 :
                                ratio == "1/2" ? -1 :
                                ratio == "2"   ? 1 :
                                ratio == "4"   ? 2 :
                                ratio == "8"   ? 3 :
                                                 0;
      interior_perturbation   = prm.get_double("Interior node perturbation");
    }



    template <int dim>
    void
    MeshParameters::apply_variations(
      Triangulation<dim>                              &tria,
      const std::function<double(const Point<dim> &)> &contact_distance,
      const types::material_id                         first_body,
      const types::material_id                         second_body) const
    {
      refine_toward<dim>(tria,
                         contact_distance,
                         std::abs(size_ratio_exponent),
                         grading_factor,
                         "Mesh: 'Contact size ratio' with the other "
                         "refinement entries",
                         size_ratio_exponent > 0 ? second_body : first_body);
      perturb_interior_vertices(tria,
                                interior_perturbation,
                                "Mesh: 'Interior node perturbation'");
    }



    template void
    MeshParameters::apply_variations(
      Triangulation<2> &,
      const std::function<double(const Point<2> &)> &,
      const types::material_id,
      const types::material_id) const;
    template void
    MeshParameters::apply_variations(
      Triangulation<3> &,
      const std::function<double(const Point<3> &)> &,
      const types::material_id,
      const types::material_id) const;
  } // namespace Geometry
} // namespace Common
