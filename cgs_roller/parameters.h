/*
 * Parameters of the cgs_roller benchmark: the common blocks (materials,
 * contact, solvers, output) composed with the blocks that only this
 * benchmark has (geometry, mesh, loading, run control).
 */
#ifndef cgs_roller_parameters_h
#define cgs_roller_parameters_h

#include <common/geometry/mesh_parameters.h>
#include <common/materials/solid_material.h>
#include <common/problems/contact_run_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace CgsRoller
{
  using namespace dealii;

  /** Subsection "Geometry". */
  struct GeometryParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Roller radius (mm). */
    double roller_radius;
    /** Width of the half block modelled, from the symmetry line (mm). */
    double block_half_width;
    /** Block height (mm). */
    double block_height;
    /** Distance of the roller above the block at the start, negative
     * for an overlap (mm). */
    double initial_gap;
  };

  /** Subsection "Mesh": the common entries and the refined strip. */
  struct MeshParameters : Common::Geometry::MeshParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Length of the surface strip from the symmetry line that is refined
     * most (mm). */
    double contact_zone_length;
  };

  /** Subsection "Loading". */
  struct LoadingParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Total vertical force per unit thickness of the full model (N/mm);
     * the half model carries half of it. */
    double force_per_thickness;
  };

  /**
   * All parameters of a cgs_roller run, read from one .prm file.
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
    LoadingParameters                          loading;
    Common::Materials::SolidMaterialParameters roller_material;
    Common::Materials::SolidMaterialParameters block_material;
  };
} // namespace CgsRoller

#endif
