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
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <functional>
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
        /** The two bodies at the contact, e.g. "roller" and "block", as
         * "Contact size ratio" names them. */
        std::string first_body;
        std::string second_body;
      };

      /** @brief Declare "Element degree", "Number of global refinements",
       * "Number of contact refinements", "Grading factor", "Contact size
       * ratio" and "Interior node perturbation" in the current
       * subsection. */
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
      /** Base-2 logarithm of the ratio of the first body's cell size at
       * the contact to the second's, -3 to 3: positive values refine the
       * second body that many more times near the contact, negative ones
       * the first (see refine_for_size_ratio()). */
      int size_ratio_exponent;
      /** Largest random shift of the interior vertices, as a fraction of
       * the shortest edge at each (0 to 0.3, dimensionless; see
       * perturb_interior_vertices()). */
      double interior_perturbation;

      /**
       * @brief The mesh variations of these entries, after the
       * application's own refinements: the extra refinements of one body
       * toward the contact that "Contact size ratio" asks for, then the
       * perturbation of the interior vertices.
       * @param[in] contact_distance Distance of a point to the contact
       * zone (mm), as the graded refinements use it.
       * @param[in] first_body, second_body Material ids of the two bodies
       * that Description::first_body and second_body name.
       */
      template <int dim>
      void
      apply_variations(dealii::Triangulation<dim> &tria,
                       const std::function<double(const dealii::Point<dim> &)>
                                                       &contact_distance,
                       const dealii::types::material_id first_body,
                       const dealii::types::material_id second_body) const;
    };
  } // namespace Geometry
} // namespace Common

#endif
