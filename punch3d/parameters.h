/*
 * Parameters of the punch3d benchmark: the common blocks (materials,
 * contact, solvers, output, run control) composed with the blocks that only
 * this benchmark has (geometry, mesh, loading).
 */
#ifndef punch3d_parameters_h
#define punch3d_parameters_h

#include <common/geometry/mesh_parameters.h>
#include <common/materials/solid_material.h>
#include <common/problems/contact_run_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Punch3d
{
  using namespace dealii;

  /** Subsection "Geometry". */
  struct GeometryParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Punch radius (mm). */
    double punch_radius;
    /** Punch height (mm). */
    double punch_height;
    /** Radius of the fillet at the punch's contact edge (mm). */
    double fillet_radius;
    /** Foundation radius (mm). */
    double foundation_radius;
    /** Foundation height (mm). */
    double foundation_height;
    /** Distance of the punch above the foundation at the start,
     * negative for an overlap (mm). */
    double initial_gap;

    /** @brief Height of the punch's lowest point at the start,
     * foundation_height + initial_gap (mm). */
    double
    punch_base() const;

    /** @brief Whether the fillet radius equals the punch radius: the
     * punch then ends in a hemisphere, a Hertz point contact (a
     * verification case, not the benchmark). */
    bool
    hemispherical_end() const;
  };

  /** Subsection "Mesh": the common entries and the edge refinements. */
  struct MeshParameters : Common::Geometry::MeshParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Further graded refinements toward the contact edge. */
    unsigned int n_edge_refinements;
  };

  /** Subsection "Loading". */
  struct LoadingParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Uniform pressure on the top of the punch (MPa). */
    double pressure;
  };

  /** Subsection "Model". */
  struct ModelParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The 3D quarter model instead of the axisymmetric one. */
    bool three_d;
    /** The punch translates along the axis without deforming. */
    bool rigid_punch;
    /** The rigid punch is an analytic surface carried by a reference node,
     * not a mesh. */
    bool rigid_surface;
  };

  /**
   * All parameters of a punch3d run, read from one .prm file.
   */
  struct Parameters : Common::Problems::ContactRunParameters
  {
    /** Declare, parse and check every entry of @p filename. */
    explicit Parameters(const std::string &filename);

    /** Declare every entry (also used by --print-parameters). */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Whether the bodies, the foundation's material and the load are
     * those of benchmark 2 (punch 100 x 100 mm with a 10 mm fillet,
     * foundation 200 x 200 mm, E = 70000 MPa, nu = 0.3, 100 MPa), for
     * which the MSC.Marc and Abaqus results of the benchmark report hold.
     * The punch's model and modulus are left free: comparing a rigid or
     * stiffer punch with those results is what measures the punch's
     * elasticity.
     */
    bool
    benchmark_bodies_and_load() const;

    ModelParameters                            model;
    GeometryParameters                         geometry;
    MeshParameters                             mesh;
    LoadingParameters                          loading;
    Common::Materials::SolidMaterialParameters punch_material;
    Common::Materials::SolidMaterialParameters foundation_material;
  };
} // namespace Punch3d

#endif
