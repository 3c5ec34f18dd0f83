/*
 * Parameters of the loaded_pin benchmark: the common blocks (materials,
 * contact, solvers, output, run control) composed with the blocks that only
 * this benchmark has (geometry, mesh, loading).
 */
#ifndef loaded_pin_parameters_h
#define loaded_pin_parameters_h

#include <common/geometry/mesh_parameters.h>
#include <common/materials/solid_material.h>
#include <common/problems/contact_run_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <loaded_pin/pin_mesh.h>
#include <string>

namespace LoadedPin
{
  using namespace dealii;

  /** Subsection "Geometry": the dimensions of lug and pin. */
  struct GeometryParameters : PinGeometry
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check (PinGeometry::check()). */
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Mesh": the common entries and the cell layers through
   * the thickness. */
  struct MeshParameters : Common::Geometry::MeshParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The options of make_quarter_mesh(). */
    MeshOptions
    options() const;

    /** Coarse cell layers through the sheet's half-thickness. */
    unsigned int n_sheet_layers;
    /** Coarse cell layers through the pin's half-length. */
    unsigned int n_pin_layers;
    /** Graded refinements toward the arc end line. */
    unsigned int n_arc_end_refinements;
    /** Angle theta of that line (degrees). */
    double arc_end_angle;
  };

  /** Subsection "Loading". */
  struct LoadingParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    /** Read and check: the force must be given and positive. */
    void
    parse_parameters(ParameterHandler &prm);

    /** Total force on the pin of the full model, the sum of the two point
     * forces at the centres of its end faces, along +x (N). */
    double total_force;
  };

  /**
   * All parameters of a loaded_pin run, read from one .prm file.
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
    Common::Materials::SolidMaterialParameters pin_material;
    Common::Materials::SolidMaterialParameters sheet_material;
  };
} // namespace LoadedPin

#endif
