/**
 * @file mesh_parameters.h
 * The entries of subsection "Mesh" that every contact application has:
 * element degree, uniform refinements of the coarse mesh, and graded
 * refinements toward the contact zone. An application derives its mesh
 * parameters from this and declares its own entries (e.g. the length of
 * the refined strip) in the same subsection.
 */
#ifndef common_geometry_mesh_parameters_h
#define common_geometry_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Common
{
  namespace Geometry
  {
    /**
     * @brief Element degree and refinement entries of subsection "Mesh".
     */
    struct MeshParameters
    {
      /** @brief How an application describes its mesh to the entries. */
      struct Description
      {
        /** The coarse mesh's cell size, e.g. "about half the roller
         * radius", completing "Uniform refinements of the coarse mesh
         * (cells of ...)". */
        std::string coarse_cells;
        /** What the graded refinements approach, e.g. "the contact
         * strip". */
        std::string  contact_target;
        unsigned int default_contact_refinements;
        unsigned int max_contact_refinements;
      };

      /** @brief Declare "Element degree", "Number of global refinements",
       * "Number of contact refinements" and "Grading factor" in the
       * current subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const Description        &description);

      /** @brief Read the entries from the current subsection. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Polynomial degree of the FE_Q element and the mapping (1 or 2). */
      unsigned int element_degree;
      unsigned int n_global_refinements;
      unsigned int n_contact_refinements;
      /** Refine a cell if its centre is closer to the target than this
       * many cell diameters. */
      double grading_factor;
    };
  } // namespace Geometry
} // namespace Common

#endif
