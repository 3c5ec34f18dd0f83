/*
 * Benchmark 3 of the FENET/NAFEMS advanced contact benchmarks, "sheet metal
 * forming with springback": a 1 mm aluminium strip bent by a rigid
 * cylindrical punch into a rigid die with rounded shoulders, then released
 * (plane strain half model, finite-strain J2 plasticity, Coulomb friction).
 * The model is ../shared/specs/sheet_forming.md; see README.md.
 */
#ifndef sheet_forming_forming_problem_h
#define sheet_forming_forming_problem_h

#include <common/contact/contact_postprocessor.h>
#include <common/contact/current_mortar_geometry.h>
#include <common/physics/rigid_body.h>
#include <common/problems/contact_application.h>

#include "parameters.h"

#include <array>
#include <string>
#include <vector>

namespace SheetForming
{
  using namespace dealii;

  /** Material ids: the sheet and the carrier cells of the rigid tools. */
  namespace MaterialIds
  {
    constexpr types::material_id sheet         = 1;
    constexpr types::material_id punch_carrier = 2;
    constexpr types::material_id die_carrier   = 3;
  } // namespace MaterialIds

  /** Boundary ids of the sheet. */
  namespace BoundaryIds
  {
    /** x = 0, the symmetry plane: u_x = 0. */
    constexpr types::boundary_id symmetry = 1;
    /** The top and bottom faces, the secondary contact surface. */
    constexpr types::boundary_id surface = 2;
    /** x = L/2, the free end. */
    constexpr types::boundary_id end = 3;
    /** z = 0 of the 3D strip, the symmetry plane across the width:
     * u_z = 0. */
    constexpr types::boundary_id width_symmetry = 4;
    /** z = W/2 of the 3D strip, its free edge. */
    constexpr types::boundary_id edge = 5;
  } // namespace BoundaryIds

  /** The tool loads and the punch stroke at one accepted step. */
  struct ForceRecord
  {
    /** Pseudo-time and the tools' downward displacements (mm). */
    double time, punch_displacement, die_displacement;
    /** Vertical force of the sheet on the punch and on the die, for the
     * full strip (N; upward positive). */
    double punch_force, die_force;
    /** Vertical reaction at the held node, full strip (N; zero before the
     * release). */
    double hold_force;
    /** |punch + die - hold| over the largest force so far (the largest
     * of the three magnitudes and every earlier punch force): the vertical
     * balance of the sheet. */
    double balance;
  };

  /** The angles of the flange at one state. */
  struct FlangeAngles
  {
    /** Angle of the chord P(L) - P(s_c) of the mid-surface from the
     * downward vertical (degrees): 0 for a vertical flange, 90 for a flat
     * one. */
    double chord;
    /** The same for the end piece P(L) - P(L - l). */
    double end_tangent;
  };

  /** The strip and the tools at one state, for the output files; in 3D
   * on the plane z = 0, the strip's middle. */
  struct StripShape
  {
    /** Reference arc length s of each sample (mm). */
    std::vector<double> s;
    /** Deformed top, mid-surface and bottom point at each s (mm). */
    std::vector<std::array<Point<2>, 3>> points;
    /** Downward displacements of punch and die (mm). */
    double punch_displacement = 0., die_displacement = 0.;
    /** Contact results of the top and bottom faces, by s (2D: the x and
     * y components of the 3D vectors). */
    std::vector<Common::Contact::ContactPointResult<2>> top, bottom;
  };

  /**
   * @brief The forming problem: the sheet (secondary surface: its top and
   * bottom faces) against the rigid punch and die (analytic profiles, the
   * primary side), contact in the current configuration. In plane strain
   * (dim = 2) or as a 3D strip (dim = 3: a quarter model with its edge
   * free, the tools extruded along z), whose angles are measured on the
   * symmetry plane z = 0 and at the edge.
   */
  template <int dim>
  class FormingProblem : public Common::Problems::ContactApplication<dim>
  {
  public:
    explicit FormingProblem(const Parameters &parameters);

  private:
    using Base = Common::Problems::ContactApplication<dim>;
    using Base::console;
    using Base::constraints_dirichlet_and_hanging_nodes;
    using Base::contact_geometry;
    using Base::contact_problem;
    using Base::dof_handler;
    using Base::fe;
    using Base::mapping;
    using Base::mpi_communicator;
    using Base::triangulation;
    using Base::write_plots;
    using Base::write_summary;

    std::string
    title() const override;
    void
    make_grid() override;
    void
    setup_system() override;
    Common::Problems::ExternalLoad
    external_load() const override;
    std::vector<std::string>
    result_files() const override;
    void
    postprocess_step(
      const Common::Solvers::StepInfo         &step,
      const Common::Solvers::NewtonStatistics &statistics) override;
    void
    output_results(
      const Common::Solvers::LoadSteppingStatistics &stepping) override;

    /** The punch and the die in their initial positions. */
    std::vector<Common::Contact::RigidTool<dim>>
    make_tools() const;

    /** The deformed position (x, y) of the material point at reference
     * arc length @p s, height @p y and, in 3D, @p z across the width
     * (mm). */
    Point<2>
    deformed_point(const double s, const double y, const double z = 0.) const;

    /** The flange angles now, on the plane z = @p z (3D; the middle of the
     * strip by default). */
    FlangeAngles
    flange_angles(const double z = 0.) const;

    /** The factor from the model's forces to the full strip's: 2 halves
     * times the width in plane strain (forces per mm of depth), 4 quarters
     * in 3D. */
    double
    full_strip_factor() const;

    /** The strip's outline and mid-surface, the tools' positions and the
     * contact state now. */
    StripShape
    capture_shape() const;

    /** Write @p shape as strip_<tag>.csv (outline and mid-surface),
     * tools_<tag>.csv (the tools' profiles), contact_<tag>_top.csv and
     * contact_<tag>_bottom.csv (the contact profiles of the faces), with
     * their plots. Call on rank 0. */
    void
    write_shape(const StripShape &shape, const std::string &tag);

    const Parameters                           &parameters;
    Common::Physics::PrescribedTranslation<dim> punch_carrier, die_carrier;
    /** The y DoF of the sheet's axis node held from the release stage on. */
    types::global_dof_index hold_dof;
    bool                    held = false;
    /** Forces at every accepted step. */
    std::vector<ForceRecord> forces;
    /** The angles and the shape at the end of forming, if reached. */
    bool         formed = false;
    FlangeAngles forming_angles;
    /** In 3D the same at the strip's free edge z = W/2. */
    FlangeAngles forming_angles_edge;
    StripShape   formed_shape;
    /** Punch stroke at the end of forming (mm). */
    double stroke = 0.;
  };
} // namespace SheetForming

#endif
