/*
 * Large sliding with Coulomb friction against a rigid tool, in the current
 * configuration (Common::Contact::CurrentMortarGeometry): a compressible
 * neo-Hookean block, 10 x 5 mm (E = 100 MPa, nu = 0.3, plane strain, Q1,
 * 8 x 4 cells), lies on a rigid plane y = 0 (an analytic line carried by
 * the fixed reference node of a carrier cell). Its top is moved down by
 * 0.25 mm (5 %) in two steps, then dragged 50 mm along x (five block
 * lengths) in steps that start at 1e-3 mm. Exact Coulomb friction,
 * mu = 0.3, dual Lagrange multipliers.
 *
 * Checks:
 * - stick phase: after a drag of 1e-3 mm the tangential reaction on the
 *   top is below mu times the normal one and nodes stick;
 * - slip phase: once every closed node slips, the tangential reaction
 *   equals mu times the normal one within 1e-8, at every step to 50 mm;
 * - once the block slides steadily (from 5 mm) the normal reaction stays
 *   within 1e-6 of its value, and every step from 1 mm on takes at most
 *   two Newton iterations (the state moves with the block);
 * - Newton's method converges quadratically where the block starts to
 *   slide (drag 0.1 to 0.5 mm, every node turning from stick to slip): the
 *   residual ratios log(r_k+1)/log(r_k) of the iterations after the active
 *   set has settled, above round-off (1e-12), are printed and exceed 1.8;
 *   the tangent holds the geometric stiffness of the rows
 *   (CurrentMortarGeometry::contact_force_derivative()). Once sliding,
 *   each 2.5 mm step takes one iteration: the state moves with the block.
 */

#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/two_body_meshes.h>
#include <common/materials/finite_strain_material.h>
#include <common/physics/finite_strain_solid.h>
#include <common/problems/contact_newton_problem.h>

#include "../newton_rates.h"
#include "../tests.h"

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

namespace
{
  constexpr types::boundary_id bottom_id  = 1;
  constexpr types::boundary_id top_id     = 2;
  constexpr types::material_id block_id   = 1;
  constexpr types::material_id carrier_id = 9;
  constexpr double             mu         = 0.3;
  constexpr double             press      = 0.25; // mm
  constexpr double             drag       = 50.;  // mm

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
    Triangulation<2> block, carrier;
    GridGenerator::subdivided_hyper_rectangle(block,
                                              {8, 4},
                                              Point<2>(0., 0.),
                                              Point<2>(10., 5.));
    for (const auto &cell : block.active_cell_iterators())
      {
        cell->set_material_id(block_id);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            cell->face(f)->set_boundary_id(
              std::abs(cell->face(f)->center()[1]) < 1e-12      ? bottom_id :
              std::abs(cell->face(f)->center()[1] - 5.) < 1e-12 ? top_id :
                                                                  0);
      }
    GridGenerator::hyper_rectangle(carrier,
                                   Point<2>(-20., -10.),
                                   Point<2>(-19., -9.));
    for (const auto &cell : carrier.active_cell_iterators())
      cell->set_material_id(carrier_id);
    Common::Geometry::join_bodies<2>({&block, &carrier}, triangulation);
  }

  const FESystem<2> fe(FE_Q<2>(1), 2);
  const MappingQ<2> mapping(1);
  DoFHandler<2>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  // The carrier is fixed; its first vertex carries the plane.
  AffineConstraints<double>              constraints;
  std::array<types::global_dof_index, 2> reference_dofs{};
  std::vector<types::global_dof_index>   top_dofs;
  {
    constraints.reinit(complete_index_set(dof_handler.n_dofs()));
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == carrier_id)
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto dof : cell_dofs)
            constraints.add_line(dof);
          reference_dofs = {
            {cell->vertex_dof_index(0, 0), cell->vertex_dof_index(0, 1)}};
        }
    const IndexSet top =
      DoFTools::extract_boundary_dofs(dof_handler, ComponentMask(), {top_id});
    for (const auto dof : top)
      {
        constraints.add_line(dof);
        top_dofs.push_back(dof);
      }
    constraints.close();
  }

  std::map<types::material_id,
           std::shared_ptr<const Common::Materials::FiniteStrainMaterial>>
    laws;
  laws[block_id]   = std::make_shared<Common::Materials::NeoHookean>(100., 0.3);
  laws[carrier_id] = laws[block_id];
  Common::Physics::FiniteStrainSolid<2> solid(
    mapping,
    fe,
    laws,
    Common::Physics::Kinematics::cartesian,
    Common::Physics::FiniteStrainParameters());

  Common::Contact::RigidProfile plane;
  plane.add_line(Point<2>(100., 0.), Point<2>(-100., 0.));
  Common::Contact::RigidTool<2> tool;
  tool.name    = "plane";
  tool.surface = std::make_shared<Common::Contact::RigidSurface<2>>(plane);
  tool.reference_node_dofs = reference_dofs;
  Common::Contact::CurrentMortarGeometry<2> geometry(dof_handler,
                                                     mapping,
                                                     bottom_id,
                                                     {tool},
                                                     1.,
                                                     false);

  Common::Contact::ContactParameters contact;
  contact.primary_boundary_id   = numbers::invalid_boundary_id;
  contact.secondary_boundary_id = bottom_id;
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
                                                    100.,
                                                    MPI_COMM_WORLD);
  problem.setup(constraints);

  // Pseudo-time s in the load factor: pressing for s in [0, 1], dragging
  // for s in [1, 2].
  Common::Problems::ExternalLoad load;
  load.add = [](const Common::Solvers::LoadState &,
                const AffineConstraints<double> &,
                TrilinosWrappers::MPI::Vector &) {
  };
  load.magnitude = [](const Common::Solvers::LoadState &) {
    return 50.;
  };
  load.prescribed_displacements =
    [&](const Common::Solvers::LoadState          &state,
        std::map<types::global_dof_index, double> &values) {
      const double s = state.load_factor();
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (std::abs(cell->vertex(v)[1] - 5.) < 1e-12)
            {
              values[cell->vertex_dof_index(v, 0)] =
                s <= 1. ? 0. : drag * (s - 1.);
              values[cell->vertex_dof_index(v, 1)] = -press * std::min(s, 1.);
            }
    };

  ConditionalOStream  quiet(std::cout, std::getenv("VERBOSE") != nullptr);
  std::vector<double> schedule = {0.5, 1.};
  for (const double d : {1e-3, 0.01, 0.1, 0.5, 1., 2.5})
    schedule.push_back(1. + d / drag);
  for (double d = 5.; d <= drag + 1e-12; d += 2.5)
    schedule.push_back(1. + d / drag);

  bool   all_slip_pass = true, stick_pass = false, quadratic_pass = false;
  bool   steady_pass   = true;
  double steady_normal = 0.;
  for (unsigned int step = 0; step < schedule.size(); ++step)
    {
      const auto state =
        Common::Solvers::LoadState::with_load_factor(schedule[step]);
      const auto statistics = problem.solve(state, load, quiet);
      if (!statistics.converged)
        {
          deallog << "step " << step
                  << ": Newton failure: " << statistics.failure << std::endl;
          all_slip_pass = false;
          break;
        }
      problem.commit();
      const auto   R      = problem.reaction_forces({top_id}, state, load)[0];
      const double normal = -R[1], tangential = std::abs(R[0]);
      const auto  &enforcement = problem.enforcement();
      unsigned int n_stick = 0, n_slip = 0;
      for (unsigned int j = 0; j < problem.coupling().n_rows(); ++j)
        (enforcement.status(j) == Common::Contact::PointStatus::stick ?
           n_stick :
         enforcement.status(j) == Common::Contact::PointStatus::slip ?
           n_slip :
           n_stick) += enforcement.is_active(j) ? 1 : 0;
      const double drag_now = std::max(0., schedule[step] - 1.) * drag;
      std::string  verdict;
      if (schedule[step] > 1. && drag_now < 2e-3)
        {
          stick_pass = n_stick > 0 && tangential < mu * normal;
          verdict    = std::string(", stick phase: ") + pass_fail(stick_pass);
        }
      else if (schedule[step] > 1. && n_stick == 0)
        {
          const bool coulomb =
            std::abs(tangential - mu * normal) <= 1e-8 * mu * normal;
          all_slip_pass = all_slip_pass && coulomb;
          verdict       = std::string(", T = mu N: ") + pass_fail(coulomb);
          if (drag_now >= 5.)
            {
              if (steady_normal == 0.)
                steady_normal = normal;
              steady_pass = steady_pass && std::abs(normal - steady_normal) <=
                                             1e-6 * steady_normal;
            }
        }
      // Residual ratios of the step in which the block starts to slide:
      // those of the iterations after the active set has settled, above
      // round-off (1e-12: the iteration reaches 2e-11 from 2e-5 in one
      // step, and that step counts).
      std::string rates;
      if (std::abs(drag_now - 0.5) < 1e-9)
        {
          const auto ratios = NewtonRates::residual_ratios(statistics, 1e-12);
          quadratic_pass    = ratios.quadratic;
          rates =
            ", residual ratios log r(k+1)/log r(k):" + ratios.to_string() +
            " " + pass_fail(quadratic_pass);
        }
      // Once sliding, the state moves with the block: at most two
      // iterations per step.
      if (drag_now >= 1.)
        steady_pass = steady_pass && statistics.n_iterations <= 2;
      const double ratio = tangential / (mu * normal);
      deallog << "drag " << format(drag_now, 4) << " mm: stick " << n_stick
              << ", slip " << n_slip << ", N = " << format(normal, 6)
              << " N/mm, T/(mu N) = "
              << (ratio < 1e-10 ? std::string("0") : format(ratio, 6))
              << verdict << rates << std::endl;
    }
  deallog << "stick phase " << pass_fail(stick_pass) << ", T = mu N while "
          << "slipping " << pass_fail(all_slip_pass) << ", steady normal force "
          << pass_fail(steady_pass) << ", quadratic convergence "
          << pass_fail(quadratic_pass) << std::endl;
}
