/*
 * A slender strip bent between two rigid tools in the current
 * configuration (Common::Contact::CurrentMortarGeometry with two
 * RigidTools): the half model x >= 0 of an elastic strip (neo-Hookean,
 * E = 70500 MPa, nu = 0.3, plane strain, Q2, 2 x 80 cells), 40 mm long and
 * t = 1 mm thick, symmetric about x = 0 (u_x = 0 there), rests on a
 * cylindrical support of radius 4 mm whose top touches its bottom at
 * x = L = 29 mm, and is pressed at x = 0 by a cylindrical punch of radius
 * 20 mm (moved down by delta through a carrier cell). Nothing else holds
 * it: the strip is held only by the two contacts, each at one point, and
 * its part beyond the support is free. Frictionless. The complementarity
 * constant is 1e-3 E/h: the pressures of this slender body are of order
 * 1 MPa, and with E/h a gap of round-off size (1e-6 mm) would weigh as
 * much as the pressure in the active-set decision.
 *
 * Beam theory: the half strip is a cantilever from the symmetry plane
 * (zero slope) to the support, whose tip moves by delta relative to its
 * root, so the force per unit depth on each tool is
 * F = 3 E' I delta / L^3, E' = E/(1 - nu^2), I = t^3/12. Shear
 * (E' t^2/(4 kappa G L^2) = 1e-3), the shift of the contact points along
 * the curved tools (R theta/L, about 2e-3 each at delta = 0.1 mm) and the
 * Q2 discretisation together stay below 1 %.
 *
 * Checks, at delta = 0.05 and 0.1 mm:
 * - each step converges, quadratically: every iteration from a relative
 *   residual r below 0.1 reaches r^1.8 or the round-off floor 1e-8 (the
 *   bulk residual's round-off, about 1e-11 N/mm per DoF, is 2e-9 of the
 *   small force of this slender strip). A closed node opens only if the
 *   multiplier of the linearised step is tensile too, so the small forces
 *   of a slender body are not confused with the nonlinear error of the
 *   iterate;
 * - exactly the two touching nodes are closed;
 * - the forces on punch and support (CurrentMortarGeometry::tool_loads())
 *   balance within 1e-8 of F;
 * - F agrees with beam theory within 1 %.
 */

#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/two_body_meshes.h>
#include <common/materials/finite_strain_material.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/finite_strain_solid.h>
#include <common/physics/rigid_body.h>
#include <common/problems/contact_newton_problem.h>

#include "../tests.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

using namespace dealii;

namespace
{
  constexpr types::boundary_id symmetry_id    = 1;
  constexpr types::boundary_id surface_id     = 2;
  constexpr types::material_id strip_id       = 1;
  constexpr types::material_id punch_id       = 8;
  constexpr types::material_id support_id     = 9;
  constexpr double             E              = 70500.; // MPa
  constexpr double             nu             = 0.3;
  constexpr double             thickness      = 1.;  // mm
  constexpr double             length         = 40.; // mm
  constexpr double             span           = 29.; // mm
  constexpr double             support_radius = 4.;  // mm
  constexpr double             punch_radius   = 20.; // mm

  std::string
  format(const double value, const unsigned int digits = 6)
  {
    std::ostringstream s;
    s << std::showpoint << std::setprecision(digits) << value;
    return s.str();
  }

  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  parallel::shared::Triangulation<2> triangulation(MPI_COMM_WORLD);
  {
    Triangulation<2> strip, punch_carrier, support_carrier;
    GridGenerator::subdivided_hyper_rectangle(strip,
                                              {80, 2},
                                              Point<2>(0., 0.),
                                              Point<2>(length, thickness));
    for (const auto &cell : strip.active_cell_iterators())
      {
        cell->set_material_id(strip_id);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(
              std::abs(face->center()[0]) < 1e-12          ? symmetry_id :
              std::abs(face->center()[0] - length) < 1e-12 ? 0 :
                                                             surface_id);
      }
    GridGenerator::hyper_rectangle(punch_carrier,
                                   Point<2>(-30., 30.),
                                   Point<2>(-29., 31.));
    GridGenerator::hyper_rectangle(support_carrier,
                                   Point<2>(-30., -30.),
                                   Point<2>(-29., -29.));
    for (const auto &cell : punch_carrier.active_cell_iterators())
      cell->set_material_id(punch_id);
    for (const auto &cell : support_carrier.active_cell_iterators())
      cell->set_material_id(support_id);
    Common::Geometry::join_bodies<2>({&strip, &punch_carrier, &support_carrier},
                                     triangulation);
  }

  const FESystem<2> fe(FE_Q<2>(2), 2);
  const MappingQ<2> mapping(2);
  DoFHandler<2>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  // u_x = 0 on the symmetry plane; the carriers, the tools' reference
  // nodes, move as prescribed (the support stays where it is).
  AffineConstraints<double> constraints;
  constraints.reinit(complete_index_set(dof_handler.n_dofs()));
  Common::Physics::make_homogeneous_constraints<2>(mapping,
                                                   dof_handler,
                                                   {},
                                                   {{0, {symmetry_id}}},
                                                   constraints);
  const auto punch_carrier =
    Common::Physics::add_prescribed_translation_constraints(dof_handler,
                                                            punch_id,
                                                            constraints);
  const auto support_carrier =
    Common::Physics::add_prescribed_translation_constraints(dof_handler,
                                                            support_id,
                                                            constraints);
  constraints.close();

  std::map<types::material_id,
           std::shared_ptr<const Common::Materials::FiniteStrainMaterial>>
    laws;
  laws[strip_id]   = std::make_shared<Common::Materials::NeoHookean>(E, nu);
  laws[punch_id]   = laws[strip_id];
  laws[support_id] = laws[strip_id];
  Common::Physics::FiniteStrainSolid<2> solid(
    mapping,
    fe,
    laws,
    Common::Physics::Kinematics::cartesian,
    Common::Physics::FiniteStrainParameters());

  // The punch touches the strip's top at the axis; the support's top
  // touches its bottom at x = span. Both arcs reach past the points the
  // strip's normals meet.
  Common::Contact::RigidProfile punch, support;
  punch.add_arc(Point<2>(0., thickness + punch_radius),
                punch_radius,
                -0.5 * numbers::PI - 0.2,
                -0.5 * numbers::PI + 0.6);
  support.add_arc(Point<2>(span, -support_radius),
                  support_radius,
                  0.2 * numbers::PI,
                  0.8 * numbers::PI);
  std::vector<Common::Contact::RigidTool<2>> tools(2);
  tools[0].name = "punch";
  tools[0].surface =
    std::make_shared<const Common::Contact::RigidSurface<2>>(punch);
  tools[0].reference_node_dofs = punch_carrier.reference_node_dofs;
  tools[0].centre              = Point<2>(0., thickness + punch_radius);
  tools[1].name                = "support";
  tools[1].surface =
    std::make_shared<const Common::Contact::RigidSurface<2>>(support);
  tools[1].reference_node_dofs = support_carrier.reference_node_dofs;
  tools[1].centre              = Point<2>(span, -support_radius);
  Common::Contact::CurrentMortarGeometry<2> geometry(dof_handler,
                                                     mapping,
                                                     surface_id,
                                                     tools,
                                                     1.,
                                                     false);

  Common::Contact::ContactParameters contact;
  contact.primary_boundary_id   = numbers::invalid_boundary_id;
  contact.secondary_boundary_id = surface_id;
  contact.enforcement  = Common::Contact::Enforcement::lagrange_multiplier;
  contact.friction_law = Common::Contact::FrictionLaw::frictionless;
  contact.friction_coefficient  = 0.;
  contact.penalty_stiffness     = 1e6;
  contact.ncp_factor            = 1e-3;
  contact.tangential_ncp_factor = 1.;
  contact.search_distance       = 1.;
  contact.accelerate_release    = true;
  Common::Solvers::LinearSolverParameters solver_parameters;
  solver_parameters.type      = Common::Solvers::LinearSolverType::mumps;
  solver_parameters.tolerance = 1e-12;
  Common::Solvers::NonlinearSolverParameters newton_parameters;
  newton_parameters.max_iterations = 25;
  newton_parameters.tolerance      = 1e-10;

  Common::Problems::ContactNewtonProblem<2> problem(dof_handler,
                                                    mapping,
                                                    solid,
                                                    geometry,
                                                    contact,
                                                    solver_parameters,
                                                    newton_parameters,
                                                    E,
                                                    MPI_COMM_WORLD);
  problem.setup(constraints);

  // The load factor is the punch's displacement delta (mm).
  const double                   E_plane = E / (1. - nu * nu);
  const double                   I = thickness * thickness * thickness / 12.;
  Common::Problems::ExternalLoad load;
  load.add = [](const Common::Solvers::LoadState &,
                const AffineConstraints<double> &,
                TrilinosWrappers::MPI::Vector &) {
  };
  // The scale of the relative residuals: the beam force at 0.1 mm.
  load.magnitude = [&](const Common::Solvers::LoadState &) {
    return 3. * E_plane * I * 0.1 / (span * span * span);
  };
  load.prescribed_displacements =
    [&](const Common::Solvers::LoadState          &state,
        std::map<types::global_dof_index, double> &values) {
      punch_carrier.prescribe(Tensor<1, 2>({0., -state.load_factor()}), values);
      support_carrier.prescribe(Tensor<1, 2>(), values);
    };

  ConditionalOStream quiet(std::cout, std::getenv("VERBOSE") != nullptr);
  for (const double delta : {0.05, 0.1})
    {
      const auto state = Common::Solvers::LoadState::with_load_factor(delta);
      const auto statistics = problem.solve(state, load, quiet);
      if (!statistics.converged)
        {
          deallog << "delta = " << delta
                  << " mm: Newton failure: " << statistics.failure << std::endl;
          return 0;
        }
      problem.commit();

      const auto  &enforcement = problem.enforcement();
      unsigned int n_closed    = 0;
      for (unsigned int j = 0; j < problem.coupling().n_rows(); ++j)
        n_closed += enforcement.is_active(j) ? 1 : 0;
      const auto   loads = geometry.tool_loads(enforcement.state(),
                                             dof_handler.locally_owned_dofs(),
                                             MPI_COMM_WORLD);
      const double F     = loads[0].force[1];
      const double beam  = 3. * E_plane * I * delta / (span * span * span);
      // The bulk residual's round-off, about 1e-11 N/mm per DoF, is 2e-9
      // of the small force of this slender strip: residuals below 1e-8 are
      // round-off. From a first residual of order 10 (above the quadratic
      // range) they reach it in two or three iterations: every iteration
      // from a residual r below 0.1 must reach r^1.8 or 1e-8.
      bool quadratic = true;
      for (unsigned int k = 1; k < statistics.residuals.size(); ++k)
        {
          const auto  &a  = statistics.residuals[k - 1];
          const auto  &b  = statistics.residuals[k];
          const double r0 = std::max(a.equilibrium, a.complementarity);
          const double r1 = std::max(b.equilibrium, b.complementarity);
          if (r0 < 0.1 && r0 > 1e-8)
            quadratic = quadratic && r1 <= std::max(std::pow(r0, 1.8), 1e-8);
        }
      std::ostringstream history;
      for (const auto &r : statistics.residuals)
        history << " " << std::scientific << std::setprecision(1)
                << std::max(r.equilibrium, r.complementarity);
      deallog << "delta = " << delta << " mm: " << statistics.n_iterations
              << " Newton iterations, residuals" << history.str()
              << ", quadratic " << pass_fail(quadratic) << std::endl;
      deallog << "  closed nodes " << n_closed << " (2 expected) "
              << pass_fail(n_closed == 2) << std::endl;
      deallog << "  punch force " << format(F) << " N/mm, support force "
              << format(loads[1].force[1]) << " N/mm, balance within 1e-8 F "
              << pass_fail(std::abs(F + loads[1].force[1]) <= 1e-8 * F)
              << std::endl;
      deallog << "  beam theory 3 E' I delta / L^3 = " << format(beam)
              << " N/mm, F/beam - 1 = " << format(F / beam - 1., 3)
              << ", within 1 % " << pass_fail(std::abs(F / beam - 1.) < 0.01)
              << std::endl;
    }
}
