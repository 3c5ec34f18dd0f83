/*
 * Benchmark 2 of the FENET/NAFEMS advanced contact benchmarks, axisymmetric
 * model: a steel punch with a rounded edge pressed onto an aluminium
 * cylindrical foundation by a uniform pressure on its top.
 */
#ifndef punch3d_punch_problem_h
#define punch3d_punch_problem_h

#include <common/analytic/rounded_punch.h>
#include <common/contact/contact_postprocessor.h>
#include <common/physics/solid_operator.h>
#include <common/problems/contact_application.h>
#include <common/solvers/load_program.h>

#include "parameters.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace Punch3d
{
  using namespace dealii;

  /** Boundary ids of the two bodies (see README.md). */
  namespace BoundaryIds
  {
    constexpr types::boundary_id foundation_bottom = 1;
    constexpr types::boundary_id foundation_top    = 2;
    constexpr types::boundary_id foundation_axis   = 3;
    constexpr types::boundary_id foundation_side   = 4;
    constexpr types::boundary_id punch_contact     = 5;
    constexpr types::boundary_id punch_top         = 6;
    constexpr types::boundary_id punch_axis        = 7;
    constexpr types::boundary_id punch_side        = 8;
    /** 3D quarter model: the symmetry planes z = 0 and x = 0 of both
     * bodies. */
    constexpr types::boundary_id symmetry_z0 = 9;
    constexpr types::boundary_id symmetry_x0 = 10;
  } // namespace BoundaryIds

  /** Material ids: one per body. */
  namespace MaterialIds
  {
    constexpr types::material_id punch      = 1;
    constexpr types::material_id foundation = 2;
  } // namespace MaterialIds

  /** Distance of a point from the axis: r = x in the axisymmetric model,
   * sqrt(x^2 + z^2) in the 3D one (y is the axis). */
  template <int dim>
  inline double
  radius(const Point<dim> &p)
  {
    return dim == 2 ? std::abs(p[0]) : std::hypot(p[0], p[dim - 1]);
  }

  /**
   * The rounded punch on the foundation, small strain, mortar contact with
   * optional Coulomb friction: for dim = 2 the axisymmetric model (r, z),
   * for dim = 3 the quarter model revolved from the same meridian meshes
   * (y the axis, symmetry planes x = 0 and z = 0). Results are reported
   * along r (on the plane z = 0 in 3D) and forces for the full bodies.
   */
  template <int dim>
  class PunchProblem : public Common::Problems::ContactApplication<dim>
  {
  public:
    explicit PunchProblem(const Parameters &parameters);

  private:
    using Base = Common::Problems::ContactApplication<dim>;
    using Base::console;
    using Base::constraints_dirichlet_and_hanging_nodes;
    using Base::contact_problem;
    using Base::dof_handler;
    using Base::fe;
    using Base::mapping;
    using Base::mpi_communicator;
    using Base::triangulation;

    /** Fraction of the bodies the model holds: 1 (axisymmetric, integrals
     * over full rings) or 1/4 (3D quarter). */
    static constexpr double model_fraction = dim == 2 ? 1. : 0.25;

    /** Axisymmetric kinematics in 2D, the solid itself in 3D. */
    static Common::Physics::Kinematics
    kinematics()
    {
      return dim == 2 ? Common::Physics::Kinematics::axisymmetric :
                        Common::Physics::Kinematics::cartesian;
    }

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

    /** The geometry of the contact pair: the meshed punch face, or an
     * analytic rigid surface (Model/Punch = rigid surface). */
    std::unique_ptr<Common::Contact::ContactGeometry<dim>>
    make_contact_geometry() const;
    /** Half-space solution for the full load the model applies: the
     * pressure times the discrete loaded area once setup_system() has
     * measured it (in 3D the mapped quarter disc, with Q1 its chords),
     * times pi a^2 before. */
    Common::Analytic::RoundedPunchHalfSpace
    half_space_reference() const;

    /** Contact results at a load factor. */
    struct Results
    {
      std::vector<Common::Contact::ContactPointResult<dim>> profile;
      double centre_pressure;          // MPa, innermost paired node
      double centre_radius;            // mm, its radius
      double peak_pressure;            // MPa
      double peak_radius;              // mm
      double contact_radius;           // mm
      double stick_radius;             // mm
      double peak_tangential_traction; // MPa, largest |t|
      double contact_force;            // N, compressive positive
      double applied_force;            // N
      double axis_displacement;        // mm, u_z of the foundation top, r = 0
    };
    Results
    evaluate_results(const double load_factor) const;

    const Parameters &parameters;
    /** The axial DoF of the foundation's top vertex on the axis. */
    types::global_dof_index axis_dof;
    /** Area of the discrete punch top, full body (mm^2). */
    double loaded_area;
  };
} // namespace Punch3d

#endif
