/*
 * Rolling without slip in the current configuration
 * (Common::Contact::CurrentMortarGeometry): a rigid cylinder of radius
 * R = 10 mm (an analytic arc, a RigidTool turned by the load program)
 * rolls on a stiff neo-Hookean strip (E = 210000 MPa, nu = 0.3, plane
 * strain, Q1), 18 mm long and t = 2 mm thick, that lies on a rigid
 * frictionless backing (u_y = 0 on its bottom) and is otherwise free. The
 * cylinder's axis is held at x = 0; it is pressed d = 0.01 mm into the
 * strip in two steps, then turned counterclockwise by 45 degrees in 18
 * steps. Coulomb friction, mu = 1: the strip is held in x only by
 * friction with the cylinder.
 *
 * In the rigid limit the strip moves by R phi. The strip's compliance
 * lets it creep: in the stick zone its surface moves with the cylinder
 * but is strained tangentially, by less than its compressive strain under
 * the cylinder, d/t = 0.5 %, so the check is |travel/(R phi) - 1| < d/t.
 *
 * Checks:
 * - the first step, with the strip held in x by friction alone, is not
 *   singular, and every step converges;
 * - the strip's travel after 45 degrees is R phi within d/t;
 * - every step sticks in the middle of the contact zone (nodes stick);
 * - the force on the tool (CurrentMortarGeometry::tool_loads()) equals
 *   the reaction of the backing within 1e-8 of the vertical force F, and
 *   its horizontal component vanishes within 1e-8 of F (the strip has no
 *   other horizontal support);
 * - the moment on the tool about its axis stays below 1e-3 F R: a free
 *   roller needs no driving torque but for the small loss of micro-slip
 *   at the edges of the contact zone (measured: below 4e-4 F R).
 */

#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/two_body_meshes.h>
#include <common/materials/finite_strain_material.h>
#include <common/physics/finite_strain_solid.h>
#include <common/problems/contact_newton_problem.h>

#include "../tests.h"
#include "../tool_on_strip.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
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
using namespace ToolOnStrip;

namespace
{
  constexpr double       radius       = 10.;  // mm
  constexpr double       thickness    = 2.;   // mm
  constexpr double       indentation  = 0.01; // mm
  constexpr double       turn         = 0.25 * numbers::PI;
  constexpr double       mu           = 1.;
  constexpr unsigned int n_turn_steps = 18;

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
  ToolOnStrip::make_mesh(triangulation, -12., 6., 180, 4, thickness);

  const FESystem<2> fe(FE_Q<2>(1), 2);
  const MappingQ<2> mapping(1);
  DoFHandler<2>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  // The carrier moves rigidly with the cylinder's axis; its first vertex
  // is the tool's reference node. The strip's bottom rests on the backing.
  AffineConstraints<double> constraints;
  const auto carrier = ToolOnStrip::constrain(dof_handler, constraints);
  constraints.close();
  const auto &reference_dofs = carrier.reference_dofs;
  const auto &carrier_dofs   = carrier.vertical_dofs;

  std::map<types::material_id,
           std::shared_ptr<const Common::Materials::FiniteStrainMaterial>>
    laws;
  laws[strip_id] =
    std::make_shared<Common::Materials::NeoHookean>(210000., 0.3);
  laws[carrier_id] = laws[strip_id];
  Common::Physics::FiniteStrainSolid<2> solid(
    mapping,
    fe,
    laws,
    Common::Physics::Kinematics::cartesian,
    Common::Physics::FiniteStrainParameters());

  // The cylinder: an arc about (0, t + R) wide enough for the material
  // points that meet the strip during the turn.
  Common::Contact::RigidProfile circle;
  const Point<2>                centre(0., thickness + radius);
  circle.add_arc(centre, radius, -3.6, -0.9);
  Common::Contact::RigidTool<2> tool;
  tool.name    = "cylinder";
  tool.surface = std::make_shared<Common::Contact::RigidSurface<2>>(circle);
  tool.reference_node_dofs = reference_dofs;
  tool.centre              = centre;
  tool.rotation            = [](const Common::Solvers::LoadState &state) {
    return turn * std::max(state.load_factor() - 1., 0.);
  };
  Common::Contact::CurrentMortarGeometry<2> geometry(dof_handler,
                                                     mapping,
                                                     top_id,
                                                     {tool},
                                                     1.,
                                                     false);

  Common::Contact::ContactParameters contact;
  contact.primary_boundary_id   = numbers::invalid_boundary_id;
  contact.secondary_boundary_id = top_id;
  contact.enforcement  = Common::Contact::Enforcement::lagrange_multiplier;
  contact.friction_law = Common::Contact::FrictionLaw::coulomb;
  contact.friction_coefficient  = mu;
  contact.penalty_stiffness     = 1e6;
  contact.ncp_factor            = 1.;
  contact.tangential_ncp_factor = 0.5;
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
                                                    210000.,
                                                    MPI_COMM_WORLD);
  problem.setup(constraints);

  // Pseudo-time s in the load factor: pressing for s in [0, 1], turning
  // for s in [1, 2].
  Common::Problems::ExternalLoad load;
  load.add = [](const Common::Solvers::LoadState &,
                const AffineConstraints<double> &,
                TrilinosWrappers::MPI::Vector &) {
  };
  // The scale of the relative residuals: about the vertical force
  // (N per mm of thickness).
  load.magnitude = [](const Common::Solvers::LoadState &) {
    return 1000.;
  };
  load.prescribed_displacements =
    [&](const Common::Solvers::LoadState          &state,
        std::map<types::global_dof_index, double> &values) {
      for (const auto dof : carrier_dofs)
        values[dof] = -indentation * std::min(state.load_factor(), 1.);
    };

  // A material point of the strip far from the contact: the left end of
  // its bottom.
  types::global_dof_index end_dof = numbers::invalid_dof_index;
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      if (cell->vertex(v).distance(Point<2>(-12., 0.)) < 1e-12)
        end_dof = cell->vertex_dof_index(v, 0);

  ConditionalOStream quiet(std::cout, std::getenv("VERBOSE") != nullptr);
  bool               converged = true, stick_pass = true, balance_pass = true,
       moment_pass            = true;
  unsigned int max_iterations = 0;
  for (unsigned int step = 1; step <= 2 + n_turn_steps; ++step)
    {
      const double s =
        step <= 2 ? 0.5 * step : 1. + double(step - 2) / n_turn_steps;
      const auto state      = Common::Solvers::LoadState::with_load_factor(s);
      const auto statistics = problem.solve(state, load, quiet);
      if (!statistics.converged)
        {
          deallog << "step " << step
                  << ": Newton failure: " << statistics.failure << std::endl;
          converged = false;
          break;
        }
      problem.commit();
      max_iterations = std::max(max_iterations, statistics.n_iterations);

      const auto  &enforcement = problem.enforcement();
      unsigned int n_stick = 0, n_slip = 0;
      for (unsigned int j = 0; j < problem.coupling().n_rows(); ++j)
        if (enforcement.is_active(j))
          (enforcement.status(j) == Common::Contact::PointStatus::stick ?
             n_stick :
             n_slip)++;
      stick_pass = stick_pass && n_stick > 0;

      const auto backing = problem.reaction_forces({bottom_id}, state, load)[0];
      const auto loads   = geometry.tool_loads(problem.enforcement().state(),
                                             dof_handler.locally_owned_dofs(),
                                             MPI_COMM_WORLD);
      // The strip is pushed down by the tool and up by the backing: the
      // tool receives the backing's reaction.
      const double vertical = std::abs(backing[1]);
      balance_pass =
        balance_pass &&
        std::abs(loads[0].force[1] - backing[1]) <= 1e-8 * vertical &&
        std::abs(loads[0].force[0]) <= 1e-8 * vertical;
      moment_pass =
        moment_pass && std::abs(loads[0].moment[2]) <= 1e-3 * vertical * radius;

      const double travel = problem.displacement()(end_dof);
      const double angle  = turn * std::max(s - 1., 0.);
      quiet << "step " << step << ": " << statistics.n_iterations
            << " iterations, " << n_stick << " stick, " << n_slip
            << " slip, travel " << travel << " mm, R phi " << radius * angle
            << " mm, tool force " << loads[0].force << ", backing " << backing
            << ", tool moment " << loads[0].moment << std::endl;
      if (step == 2 + n_turn_steps)
        {
          const double creep = travel / (radius * angle) - 1.;
          deallog << "after 45 degrees: travel " << format(travel, 6)
                  << " mm, R phi = " << format(radius * angle, 6)
                  << " mm, |travel/(R phi) - 1| < d/t = "
                  << indentation / thickness << ": "
                  << pass_fail(std::abs(creep) < indentation / thickness)
                  << std::endl;
        }
    }
  deallog << "every step converged " << pass_fail(converged) << " (at most "
          << max_iterations
          << " Newton iterations per step), nodes stick at every step "
          << pass_fail(stick_pass)
          << ", tool force = backing reaction, no horizontal force "
          << pass_fail(balance_pass) << ", tool moment below 1e-3 F R "
          << pass_fail(moment_pass) << std::endl;
}
