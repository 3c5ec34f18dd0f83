/*
 * Benchmark 5 of the FENET/NAFEMS advanced contact benchmarks, "steel
 * roller on rubber": a rigid roller of radius 30 mm is pressed 3 mm into a
 * 20 mm rubber strip (exactly incompressible neo-Hookean) and turned a
 * full revolution about its fixed axis; the strip, free in x on its
 * bottom, is carried along by Coulomb friction (mu = 0.3) and advances
 * less than the roller's circumference (Reynolds creep). The model is
 * ../shared/specs/reynolds_roller.md; see README.md.
 */
#ifndef reynolds_roller_rolling_problem_h
#define reynolds_roller_rolling_problem_h

#include <common/contact/current_mortar_geometry.h>
#include <common/physics/rigid_body.h>
#include <common/problems/contact_application.h>

#include "parameters.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace ReynoldsRoller
{
  using namespace dealii;

  /** Material ids: the strip, the rigid roller's carrier cell and the
   * elastic roller. */
  namespace MaterialIds
  {
    constexpr types::material_id strip          = 1;
    constexpr types::material_id roller_carrier = 2;
    constexpr types::material_id roller         = 3;
  } // namespace MaterialIds

  /** Boundary ids of the strip (in 3D also its z faces). */
  namespace BoundaryIds
  {
    /** y = -H/2: pushed up by the indentation. */
    constexpr types::boundary_id bottom = 1;
    /** y = H/2, the secondary contact surface. */
    constexpr types::boundary_id top = 2;
    /** x = -L1 and x = L2: free. */
    constexpr types::boundary_id ends = 3;
    /** z = 0 and z = W of the 3D extrusion: u_z = 0. */
    constexpr types::boundary_id sides = 4;
    /** The elastic roller's rim (the primary contact surface) and hub
     * (turned rigidly). */
    constexpr types::boundary_id roller_rim = 5;
    constexpr types::boundary_id roller_hub = 6;
  } // namespace BoundaryIds

  /** The strip's corners: top left (point A), bottom left, top right,
   * bottom right. */
  constexpr unsigned int n_corners = 4;

  /** The state at one accepted step. */
  struct StepRecord
  {
    /** Pseudo-time, indentation (mm) and clockwise roller angle (deg). */
    double time, indentation, angle;
    /** u_x of each corner (mm), A first. */
    std::array<double, n_corners> corner_ux;
    /** Force of the strip on the roller (N per mm of depth) and its
     * moment about the roller's axis (N mm per mm, counterclockwise
     * positive). The drive balances that moment: the driving torque,
     * clockwise positive (the sense of the turn), equals it. */
    Tensor<1, 2> roller_force;
    double       roller_moment;
    /** Reaction of the bottom support on the strip (N per mm). */
    Tensor<1, 2> bottom_reaction;
    /** |roller force - bottom reaction| over |roller force|: the strip's
     * balance (the roller's force is the strip's contact force reversed). */
    double balance;
    /** Largest |J - 1| of the projected dilatation over the exactly
     * incompressible cells (0 if the rubber is compressible). */
    double dilatation_error;
  };

  /**
   * @brief The rolling problem: the strip's top (secondary surface)
   * against the rigid roller (an analytic circle, the primary side),
   * contact in the current configuration. In plane strain (dim = 2) or as
   * its 3D extrusion (dim = 3: the roller a cylinder along z, u_z = 0 on
   * the strip's z faces), whose results are the plane-strain ones and are
   * reported per mm of depth, on the face z = 0.
   */
  template <int dim>
  class RollingProblem : public Common::Problems::ContactApplication<dim>
  {
  public:
    explicit RollingProblem(const Parameters &parameters);

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
    using Base::solid;
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

    /** The roller in its initial position: a full circle about (0, H/2 +
     * R), turned clockwise by the channel 'Roller angle'. */
    Common::Contact::RigidTool<dim>
    make_roller() const;

    /** The modulus that scales the complementarity constants (MPa): the
     * rubber's against the rigid roller; against the elastic one, the
     * moduli of the two bodies in series, 1 / (1 / E_rubber + 1 / E_roller),
     * so that a roller softer than the rubber is not judged by the
     * rubber's stiffness. */
    double
    contact_modulus() const;

    /** The roller's axis (0, H/2 + R + initial gap) (mm). */
    Point<dim>
    roller_centre() const;

    /** The elastic roller's loads: the force of the strip on it and its
     * moment about the axis (counterclockwise positive), from the
     * reactions of its hub at @p state, in the current configuration. */
    std::pair<Tensor<1, dim>, double>
    elastic_roller_loads(const Common::Solvers::LoadState &state);

    /** Write contact_half_turn.csv and its plots: the contact zone at the
     * accepted step at @p angle (the first at or past half a turn). */
    void
    write_half_turn_profile(const double angle);

    /** The strip's corners in the reference configuration, A first (in
     * 3D on the face z = 0). */
    std::array<Point<dim>, n_corners>
    corners() const;

    /** The depth the forces of the model act on: 1 mm in plane strain,
     * the width W in 3D (mm). */
    double
    depth() const;

    /** The x and y components of @p force divided by depth() (N per mm of
     * depth). */
    Tensor<1, 2>
    per_unit_depth(const Tensor<1, dim> &force) const;

    const Parameters                           &parameters;
    Common::Physics::PrescribedTranslation<dim> roller_carrier;
    /** The elastic roller's hub DoFs, each with its component and the
     * reference position of its node: turned rigidly about the axis. */
    struct HubDof
    {
      types::global_dof_index dof;
      unsigned int            component;
      Point<dim>              position;
    };
    std::vector<HubDof> hub_dofs;
    /** The y DoFs of the bottom (prescribed: the indentation) and its x
     * DoFs (held before the stage that frees them). */
    std::vector<types::global_dof_index> bottom_y_dofs, bottom_x_dofs;
    bool                                 bottom_held = false;
    /** The horizontal reaction of the bottom's support at each owned DoF
     * of bottom_x_dofs when it was freed (N per mm); applied to them as a
     * force times one less the channel 'Bottom x release'. Empty until
     * then. */
    std::map<types::global_dof_index, double> released_reactions;
    /** The state at every accepted step. */
    std::vector<StepRecord> records;
    /** True once the contact zone of half a turn is written. */
    bool half_turn_written = false;
  };
} // namespace ReynoldsRoller

#endif
