/*
 * Objectivity of contact in the current configuration
 * (Common::Contact::CurrentMortarGeometry): the two blocks of the patch
 * test (tests/two_block_patch.h, plane strain, non-matching meshes, Q1),
 * neo-Hookean, the lower one E = 1000 MPa, nu = 0.3, the upper one
 * E = 300 MPa, nu = 0.45, with Coulomb friction mu = 1. The bottom of
 * the lower block is clamped; the top of the upper block is moved down by
 * 0.2 mm (10 % of the stack) in two steps, which presses the blocks
 * together with a non-uniform pressure and, as the blocks spread
 * differently under the clamped ends, with tangential tractions. Then the
 * clamped boundaries turn the whole stack rigidly about (0.5, 1) through
 * 360 degrees in 72 steps of 5 degrees. Every node sticks (|t| up to half
 * of mu p).
 *
 * The materials and the contact conditions are frame-indifferent, so the
 * exact state of each step of the turn is the pressed state turned rigidly.
 * Checks at every step of the turn, against the pressed state:
 * - the status of every secondary node is unchanged;
 * - every nodal pressure is unchanged within 1e-8 of the largest one, and
 *   the magnitude of every tangential traction as well;
 * - no slip accumulates: the accumulated relative tangential displacement
 *   of every node changes by less than 1e-8 mm (the interface points move
 *   by up to 3.6 mm in the turn).
 * Measured: pressures within 3e-11 p_max, tangential tractions within
 * 6e-13 p_max, slip below 2e-15 mm, 4 Newton iterations per step. The
 * accepted relative position of each pair is turned with its normal
 * (CurrentMortarGeometry::accepted_relative_displacements()); without
 * that turn the tractions drifted by 2e-7 p_max per 2-degree step.
 */

#include <common/materials/finite_strain_material.h>
#include <common/physics/finite_strain_solid.h>

#include "../tests.h"
#include "two_block_patch.h"

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;
using namespace TwoBlockPatch;

namespace
{
  constexpr double compression = 0.2; // mm, 10 % of the stack height 2
  constexpr double mu          = 1.;
  // Pseudo-time: pressing over (0, 1], the turn over (1, 2].
  constexpr unsigned int n_press_steps = 2;
  constexpr unsigned int n_turn_steps  = 72;

  /** Rotation by @p angle (rad) about the z axis. */
  Tensor<2, 2>
  rotation(const double angle)
  {
    const double c = std::cos(angle), s = std::sin(angle);
    return Tensor<2, 2>({{c, -s}, {s, c}});
  }

  /** State of one secondary node. */
  struct NodeState
  {
    Common::Contact::PointStatus status;
    double                       pressure;
    double                       tangential_traction;
    Tensor<1, 2>                 accumulated_slip;
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const Setting setting{1000., 300., 0.45, 1., 1.};
  Patch<2>      patch(1, setting, Common::Contact::FrictionLaw::coulomb, mu);
  patch.current_configuration = true;
  AffineConstraints<double> constraints;
  patch.make_grid_and_dofs(constraints);

  // Clamped bottom and top: every component of their DoFs is prescribed.
  std::map<types::global_dof_index, Point<2>> support_points;
  DoFTools::map_dofs_to_support_points(patch.mapping,
                                       patch.dof_handler,
                                       support_points);
  std::vector<std::pair<types::global_dof_index, bool>> clamped; // top?
  for (const auto &[id, top] :
       {std::make_pair(BoundaryIds::lower_bottom, false),
        std::make_pair(BoundaryIds::upper_top, true)})
    for (const auto dof : DoFTools::extract_boundary_dofs(patch.dof_handler,
                                                          ComponentMask(),
                                                          {id}))
      {
        constraints.add_line(dof);
        clamped.emplace_back(dof, top);
      }
  constraints.close();

  // Which component each clamped DoF carries.
  std::map<types::global_dof_index, unsigned int> component;
  {
    std::vector<types::global_dof_index> dofs(patch.fe.n_dofs_per_cell());
    for (const auto &cell : patch.dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          component[dofs[i]] = patch.fe.system_to_component_index(i).first;
      }
  }

  std::map<types::material_id,
           std::shared_ptr<const Common::Materials::FiniteStrainMaterial>>
    laws;
  laws[MaterialIds::lower] =
    std::make_shared<Common::Materials::NeoHookean>(1000., 0.3);
  laws[MaterialIds::upper] =
    std::make_shared<Common::Materials::NeoHookean>(300., 0.45);
  patch.setup_problem(constraints,
                      std::make_unique<Common::Physics::FiniteStrainSolid<2>>(
                        patch.mapping,
                        patch.fe,
                        laws,
                        Common::Physics::Kinematics::cartesian,
                        Common::Physics::FiniteStrainParameters()));

  // Prescribed motion: the top pressed down, then both clamped boundaries
  // turned about the centre.
  const Point<2>                 centre(0.5, 1.);
  Common::Problems::ExternalLoad load;
  load.add = [](const Common::Solvers::LoadState &,
                const AffineConstraints<double> &,
                TrilinosWrappers::MPI::Vector &) {
  };
  // The scale of the relative residuals: the force of the pressed state
  // (about 50 N per mm of thickness).
  load.magnitude = [](const Common::Solvers::LoadState &) {
    return 50.;
  };
  load.prescribed_displacements =
    [&](const Common::Solvers::LoadState          &state,
        std::map<types::global_dof_index, double> &values) {
      const double t     = state.load_factor();
      const double press = compression * std::min(t, 1.);
      const auto   R     = rotation(2. * numbers::PI * std::max(t - 1., 0.));
      for (const auto &[dof, top] : clamped)
        {
          const Point<2> &X = support_points.at(dof);
          Point<2>        pressed(X);
          if (top)
            pressed[1] -= press;
          const Point<2> x = centre + R * (pressed - centre);
          values[dof]      = x[component.at(dof)] - X[component.at(dof)];
        }
    };

  const auto &enforcement = patch.contact_problem->enforcement();
  const auto &surface = patch.contact_problem->coupling().secondary_surface();
  const auto  node_states = [&]() {
    std::vector<NodeState> states(surface.n_nodes());
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      states[j] = {enforcement.status(j),
                   enforcement.pressure(j),
                   enforcement.tangential_traction(j).norm(),
                   enforcement.accumulated_slip(j)};
    return states;
  };

  ConditionalOStream     quiet(std::cout, std::getenv("VERBOSE") != nullptr);
  std::vector<NodeState> pressed;
  double                 largest_pressure = 0.;
  bool status_pass = true, pressure_pass = true, traction_pass = true,
       slip_pass              = true;
  unsigned int max_iterations = 0;
  for (unsigned int step = 1; step <= n_press_steps + n_turn_steps; ++step)
    {
      const double t = step <= n_press_steps ?
                         double(step) / n_press_steps :
                         1. + double(step - n_press_steps) / n_turn_steps;
      const auto   statistics =
        patch.contact_problem
          ->solve(Common::Solvers::LoadState::with_load_factor(t), load, quiet);
      if (!statistics.converged)
        {
          deallog << "step " << step
                  << ": Newton failure: " << statistics.failure << std::endl;
          return 0;
        }
      patch.contact_problem->commit();
      const auto states = node_states();

      if (step == n_press_steps)
        {
          pressed = states;
          for (const auto &s : states)
            quiet << "  p " << s.pressure << " |t|/(mu p) "
                  << s.tangential_traction / (mu * s.pressure) << std::endl;
          unsigned int n_stick = 0, n_slip = 0, n_open = 0;
          for (const auto &s : states)
            {
              largest_pressure = std::max(largest_pressure, s.pressure);
              (s.status == Common::Contact::PointStatus::stick ? n_stick :
               s.status == Common::Contact::PointStatus::slip  ? n_slip :
                                                                 n_open)++;
            }
          deallog << "pressed: " << n_stick << " nodes stick, " << n_slip
                  << " slip, " << n_open
                  << " open; largest pressure = " << format(largest_pressure, 4)
                  << " MPa" << std::endl;
          continue;
        }
      if (step < n_press_steps)
        continue;

      max_iterations = std::max(max_iterations, statistics.n_iterations);
      double pressure_change = 0., traction_change = 0., slip_change = 0.;
      for (unsigned int j = 0; j < states.size(); ++j)
        {
          status_pass = status_pass && states[j].status == pressed[j].status;
          pressure_change =
            std::max(pressure_change,
                     std::abs(states[j].pressure - pressed[j].pressure));
          traction_change = std::max(traction_change,
                                     std::abs(states[j].tangential_traction -
                                              pressed[j].tangential_traction));
          slip_change     = std::max(
            slip_change,
            (states[j].accumulated_slip - pressed[j].accumulated_slip).norm());
        }
      pressure_pass =
        pressure_pass && pressure_change <= 1e-8 * largest_pressure;
      traction_pass =
        traction_pass && traction_change <= 1e-8 * largest_pressure;
      slip_pass = slip_pass && slip_change <= 1e-8;
      quiet << "turn " << 360. * (t - 1.) << " deg: " << statistics.n_iterations
            << " iterations, pressure change/p_max "
            << pressure_change / largest_pressure << ", traction change/p_max "
            << traction_change / largest_pressure << ", slip change "
            << slip_change << " mm" << std::endl;
    }
  deallog << "turned 360 degrees in " << n_turn_steps << " steps, at most "
          << max_iterations << " Newton iterations per step" << std::endl;
  deallog << "status unchanged " << pass_fail(status_pass)
          << ", pressures unchanged " << pass_fail(pressure_pass)
          << ", tangential tractions unchanged " << pass_fail(traction_pass)
          << ", no slip accumulated " << pass_fail(slip_pass) << std::endl;
}
