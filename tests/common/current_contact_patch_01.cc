/*
 * Large-deformation contact patch test of the current-configuration mortar
 * geometry (Common::Contact::CurrentMortarGeometry): the two-block patch
 * (tests/two_block_patch.h, plane strain, non-matching meshes: 8 against
 * 6 faces) with compressible neo-Hookean blocks of one material
 * (E = 1000 MPa, nu = 0.3), both on the symmetry line x = 0, the lower one
 * on a frictionless support, the top of the upper one moved down by 30 %
 * of the height of the stack (0.6 mm) in 6 steps. Frictionless contact.
 *
 * The exact state is homogeneous: uniaxial Cauchy stress -p in both
 * blocks, which spread alike, so the two contact faces stay in place
 * against each other while both stretch by 15 % and the non-matching
 * nodes move with them; the edges of the two surfaces coincide at every
 * step (the free-edge extension of the meshed primary surface keeps the
 * last secondary face covered while the iterates move the edges).
 * Checks, for Q1 and Q2, after every step:
 * - every secondary node is closed, and the nodal pressures are uniform
 *   within 1e-8 of their mean;
 * - the Cauchy stress of every cell of both blocks is uniaxial within
 *   1e-8 of p (sigma_xx, sigma_xy), with sigma_yy = -p within 1e-8 of p:
 *   the mortar tractions of the current configuration carry the stress of
 *   the bodies;
 * - force balance: the pressure times the current contact length equals
 *   the reaction on the top within 1e-8;
 * - Newton's method converges quadratically in the first step: the
 *   residual ratio log(r_k+1)/log(r_k) above round-off (1e-10) is printed
 *   and exceeds 1.8 (the residuals are about 2e-3, 8e-7 and 2e-13).
 */

#include <common/contact/contact_postprocessor.h>
#include <common/materials/finite_strain_material.h>
#include <common/physics/finite_strain_solid.h>

#include "../newton_rates.h"
#include "../tests.h"
#include "two_block_patch.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;
using namespace TwoBlockPatch;

namespace
{
  constexpr double compression = 0.6; // mm, 30 % of the stack height 2

  void
  run(const unsigned int degree)
  {
    const Setting setting{1000., 1000., 0.3, 1., 1.};
    Patch<2>      patch(degree,
                   setting,
                   Common::Contact::FrictionLaw::frictionless,
                   0.);
    patch.current_configuration = true;
    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints);
    patch.add_lower_support(constraints);
    patch.add_symmetry(constraints);
    const FEValuesExtractors::Scalar y_displacement(1);
    const IndexSet                   top_dofs =
      DoFTools::extract_boundary_dofs(patch.dof_handler,
                                      patch.fe.component_mask(y_displacement),
                                      {BoundaryIds::upper_top});
    for (const auto dof : top_dofs)
      if (!constraints.is_constrained(dof))
        constraints.add_line(dof);
    constraints.close();

    std::map<types::material_id,
             std::shared_ptr<const Common::Materials::FiniteStrainMaterial>>
      laws;
    laws[MaterialIds::lower] =
      std::make_shared<Common::Materials::NeoHookean>(1000., 0.3);
    laws[MaterialIds::upper] =
      std::make_shared<Common::Materials::NeoHookean>(1000., 0.3);
    patch.setup_problem(constraints,
                        std::make_unique<Common::Physics::FiniteStrainSolid<2>>(
                          patch.mapping,
                          patch.fe,
                          laws,
                          Common::Physics::Kinematics::cartesian,
                          Common::Physics::FiniteStrainParameters()));
    const auto &solid =
      dynamic_cast<const Common::Physics::FiniteStrainSolid<2> &>(
        patch.contact_problem->solid());

    Common::Problems::ExternalLoad load;
    load.add = [](const Common::Solvers::LoadState &,
                  const AffineConstraints<double> &,
                  TrilinosWrappers::MPI::Vector &) {
    };
    // The scale of the relative residuals: the force of the final stress
    // (about 200 N per mm of thickness).
    load.magnitude = [](const Common::Solvers::LoadState &) {
      return 200.;
    };
    load.prescribed_displacements =
      [&top_dofs](const Common::Solvers::LoadState          &state,
                  std::map<types::global_dof_index, double> &values) {
        for (const auto dof : top_dofs)
          values[dof] = -compression * state.load_factor();
      };

    bool               all_pass = true;
    ConditionalOStream quiet(std::cout, std::getenv("VERBOSE") != nullptr);
    const unsigned int n_steps = 6;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const auto state =
          Common::Solvers::LoadState::with_load_factor(double(step) / n_steps);
        const auto statistics =
          patch.contact_problem->solve(state, load, quiet);
        if (!statistics.converged)
          {
            deallog << "Q" << degree << " step " << step
                    << ": Newton failure: " << statistics.failure << std::endl;
            all_pass = false;
            break;
          }
        patch.contact_problem->commit();

        // Pressures of the secondary nodes.
        const auto  &enforcement = patch.contact_problem->enforcement();
        const auto  &coupling    = patch.contact_problem->coupling();
        const auto  &surface     = coupling.secondary_surface();
        double       p_sum = 0., p_min = 1e300, p_max = -1e300;
        unsigned int n_closed = 0;
        for (unsigned int j = 0; j < surface.n_nodes(); ++j)
          {
            if (!enforcement.is_active(j))
              continue;
            ++n_closed;
            p_sum += enforcement.pressure(j);
            p_min = std::min(p_min, enforcement.pressure(j));
            p_max = std::max(p_max, enforcement.pressure(j));
          }
        const double p = p_sum / std::max(1u, n_closed);

        // Stress of every cell.
        double stress_defect = 0.;
        for (const auto &cell : patch.dof_handler.active_cell_iterators())
          {
            const auto &sigma =
              solid.cell_averages(cell->active_cell_index()).cauchy_stress;
            stress_defect = std::max({stress_defect,
                                      std::abs(sigma[0][0]),
                                      std::abs(sigma[0][1]),
                                      std::abs(sigma[1][1] + p)});
          }

        // Force balance: pressure times the current contact length against
        // the reaction on the top.
        double x_max = 0.;
        for (unsigned int j = 0; j < surface.n_nodes(); ++j)
          x_max = std::max(x_max, surface.node(j).position[0]);
        const double reaction =
          -patch.contact_problem->reaction_forces({BoundaryIds::upper_top},
                                                  state,
                                                  load)[0][1];

        quiet << "step " << step << ": pressure spread/p "
              << (p_max - p_min) / p << ", stress defect/p "
              << stress_defect / p << ", |p L - reaction|/reaction "
              << std::abs(p * x_max - reaction) / reaction << std::endl;
        std::string rates;
        if (step == 1)
          {
            // Three iterations: 2e-3, 8e-7, 2e-13; the last is at
            // round-off, which leaves one ratio.
            const auto ratios =
              NewtonRates::residual_ratios(statistics, 1e-10, 1.8, 1);
            all_pass = all_pass && ratios.quadratic;
            rates =
              ", residual ratios log r(k+1)/log r(k):" + ratios.to_string() +
              " " + pass_fail(ratios.quadratic);
          }
        const bool closed  = n_closed == surface.n_nodes();
        const bool uniform = (p_max - p_min) <= 1e-8 * p;
        const bool stress  = stress_defect <= 1e-8 * p;
        const bool balance = std::abs(p * x_max - reaction) <= 1e-8 * reaction;
        all_pass           = all_pass && closed && uniform && stress && balance;
        if (step == 1 || step == n_steps ||
            !(closed && uniform && stress && balance))
          deallog << "Q" << degree << " step " << step << ": "
                  << statistics.n_iterations
                  << " Newton iterations, p = " << format(p, 6)
                  << " MPa, contact length " << format(x_max, 6)
                  << " mm, closed " << n_closed << "/" << surface.n_nodes()
                  << " " << pass_fail(closed) << ", pressure spread/p "
                  << pass_fail(uniform) << ", stress uniaxial and = -p "
                  << pass_fail(stress) << ", p L = reaction "
                  << pass_fail(balance) << rates << std::endl;
      }
    deallog << "Q" << degree << ": all steps " << pass_fail(all_pass)
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  run(1);
  run(2);
}
