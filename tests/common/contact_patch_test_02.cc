/*
 * Non-matching contact patch test in 3D (mortar segmentation by polygon
 * clipping in an auxiliary plane): the lower block [0,1]^3 mm
 * (E = 70000 MPa, 4x4x4 cells) and the upper block [0,1]^2 x [1,2] mm
 * (E = 210000 MPa, 3x3x3 cells), nu = 0.3, so that the 16 secondary and 9
 * primary faces overlap in general polygons. The lower block rests on
 * u_z = 0, the planes x = 0 and y = 0 are symmetry planes of both blocks,
 * and p = 100 MPa acts on the top of the upper block; frictionless, dual
 * Lagrange multipliers, semismooth Newton, Q1 and Q2. The exact solution,
 * uniaxial stress sigma_zz = -p, lies in the finite element space, so the
 * test checks that (a) every active secondary node carries p to 1e-8
 * relative, and every paired node is active; (b) at every quadrature point
 * of both blocks sigma_zz = -p and the other components vanish, to 1e-8
 * relative to p; (c) the total contact force is (0, 0, -p) times the unit
 * interface area to 1e-10 relative; (d) the Newton method converges on
 * its residual test; (e) the interface slides freely: the mean relative
 * tangential displacement at each active node equals the exact
 * nu p (1/E_upper - 1/E_lower) (x, y) to 1e-8 relative.
 *
 * The checks run again with a corner of the lower block's top layer
 * (x, y < 1/2) and a side of the upper block's bottom layer (x > 1/2)
 * refined once more, so that both surfaces carry hanging nodes. A hanging
 * secondary node has no multiplier of its own: its dual function goes to
 * its parents and the basis is made biorthogonal again on the constrained
 * space (MortarCoupling::condense_hanging_nodes()). The exact solution lies
 * in the constrained space, and (a) also requires every secondary node
 * that is not hanging to be paired. Without the condensation the hanging
 * nodes count as active with zero pressure and their parents carry their
 * share, and (b) and (e) fail too.
 */

#include <common/contact/contact_postprocessor.h>

#include "../tests.h"
#include "two_block_patch.h"

#include <deal.II/base/conditional_ostream.h>

#include <fstream>
#include <iostream>

using namespace dealii;
using namespace TwoBlockPatch;

namespace
{
  constexpr int dim = 3;

  void
  run(const unsigned int degree, const bool refine_locally)
  {
    const Setting             setting{70000., 210000., 0.3, 1., 100.};
    Patch<dim>                patch(degree,
                     setting,
                     Common::Contact::FrictionLaw::frictionless,
                     0.);
    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints, refine_locally);
    patch.add_lower_support(constraints);
    patch.add_symmetry(constraints);
    constraints.close();
    patch.setup_problem(constraints);

    // Hanging nodes: surface nodes whose vertical DoF is constrained.
    const auto count_hanging = [&](const auto &surface) {
      unsigned int count = 0;
      for (unsigned int j = 0; j < surface.n_nodes(); ++j)
        count += constraints.is_constrained(surface.node(j).dofs[dim - 1]);
      return count;
    };
    const unsigned int n_hanging_secondary =
      count_hanging(patch.contact_problem->coupling().secondary_surface());
    if (refine_locally)
      deallog << "Hanging nodes: secondary " << n_hanging_secondary
              << ", primary "
              << count_hanging(
                   patch.contact_problem->coupling().primary_surface())
              << std::endl;

    const auto statistics = patch.solve_and_commit();

    const auto  &coupling    = patch.contact_problem->coupling();
    const auto  &enforcement = patch.contact_problem->enforcement();
    const auto  &solution    = patch.contact_problem->displacement();
    const double p           = setting.pressure;

    // (a) Nodal pressures; (e) relative tangential displacement.
    const double slip_rate =
      setting.poisson_ratio * p * (1. / setting.E_upper - 1. / setting.E_lower);
    unsigned int n_paired           = 0;
    double       max_pressure_error = 0., max_slip_error = 0.;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      {
        n_paired += coupling.row(j).has_partner;
        if (!enforcement.is_active(j))
          continue;
        max_pressure_error =
          std::max(max_pressure_error,
                   std::abs(enforcement.pressure(j) - p) / p);
        const Point<dim> &x =
          coupling.secondary_surface().node(j).reference_position;
        const Tensor<1, dim> d = coupling.relative_displacement(j, solution);
        for (unsigned int c = 0; c < dim - 1; ++c)
          max_slip_error =
            std::max(max_slip_error,
                     std::abs(d[c] - slip_rate * x[c]) / std::abs(slip_rate));
      }
    const bool pressures_exact =
      enforcement.n_active() == n_paired &&
      n_paired + n_hanging_secondary == coupling.n_rows() && n_paired > 0 &&
      max_pressure_error < 1e-8;
    deallog << "Secondary nodes " << coupling.n_rows() << ", paired "
            << n_paired << ", active " << enforcement.n_active() << std::endl;
    deallog << "(a) nodal pressures: " << pass_fail(pressures_exact);
    if (!pressures_exact)
      deallog << " (largest relative error " << format(max_pressure_error, 2)
              << ")";
    deallog << std::endl;

    // (b) Uniaxial stress everywhere.
    const QGauss<dim>                    quadrature(degree + 1);
    FEValues<dim>                        fe_values(patch.mapping,
                            patch.fe,
                            quadrature,
                            update_gradients);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    double                               max_stress_error = 0.;
    for (const auto &cell : patch.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strains);
          const auto &law = patch.physics->material(cell->material_id());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              SymmetricTensor<2, dim> error = law.stress(strains[q]);
              error[dim - 1][dim - 1] += p;
              max_stress_error = std::max(max_stress_error, error.norm() / p);
            }
        }
    deallog << "(b) uniform stress: " << pass_fail(max_stress_error < 1e-8)
            << std::endl;

    // (c) Total contact force.
    const Tensor<1, dim> force =
      Common::Contact::total_contact_force(coupling, enforcement);
    Tensor<1, dim> expected;
    expected[dim - 1] = -p * interface_area(setting, dim);
    deallog << "Total contact force F_z: " << format(force[dim - 1]) << " N"
            << std::endl;
    deallog << "(c) contact force: "
            << pass_fail((force - expected).norm() / p < 1e-10) << std::endl;

    // (d) Newton.
    deallog << "Newton iterations: " << statistics.n_iterations << std::endl;
    deallog << "(d) Newton convergence: "
            << pass_fail(statistics.converged && !statistics.converged_on_step)
            << std::endl;

    deallog << "Relative tangential displacement rate: " << format(slip_rate)
            << std::endl;
    deallog << "(e) frictionless sliding: "
            << pass_fail(n_paired > 0 && max_slip_error < 1e-8) << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();

  for (const unsigned int degree : {1u, 2u})
    run(degree, false);
  deallog << "With hanging nodes on both contact surfaces" << std::endl;
  for (const unsigned int degree : {1u, 2u})
    run(degree, true);
}
