/*
 * Non-matching contact patch test, plane strain: two elastic blocks, the
 * lower one [0,1]x[0,1] mm (E = 70000 MPa) and the upper one [0,1]x[1,2] mm
 * (E = 210000 MPa), both nu = 0.3, meshed with 4x4 and 3x3 coarse cells (one
 * global refinement), so that the meshes do not match along the interface
 * y = 1. The lower block rests on u_y = 0, both left sides are symmetry
 * lines (u_x = 0), and a uniform pressure p = 100 MPa acts on the top of the
 * upper block. The contact (secondary: top of the lower block, primary:
 * bottom of the upper block) is frictionless and enforced with condensed
 * dual Lagrange multipliers by the semismooth Newton method. The different
 * moduli make the interface slide. The exact solution, a uniform stress
 * sigma_yy = -p, lies in the finite element space, so for Q1 and Q2 the test
 * checks that (a) every active secondary node's recovered pressure equals p
 * to 1e-8 relative, (b) at every quadrature point of both bodies
 * sigma_yy = -p and sigma_xx = sigma_xy = 0 to 1e-8 relative to p, (c) the
 * total contact force equals p times the interface length to 1e-10 relative,
 * (d) the Newton method converges (the number of iterations is printed), and
 * (e) the interface slides freely: no tangential traction, and the mean
 * relative tangential displacement at each secondary node equals the exact
 * one to 1e-8 relative.
 * The same checks run on the axisymmetric model (axis x = 0, two stacked
 * cylinders of radius 1, ring-weighted integrals): exact uniaxial stress
 * with zero hoop stress, contact force p pi to 1e-10 relative, relative
 * radial displacement nu p r (1/E_upper - 1/E_lower). With Q2 the secondary
 * vertex on the axis has no ring measure and is not paired; every paired
 * node carries p.
 */

#include <common/contact/contact_postprocessor.h>

#include "../tests.h"
#include "two_block_patch.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include <fstream>
#include <iostream>

using namespace dealii;
using namespace TwoBlockPatch;

namespace
{



  template <int dim>
  class PatchTest
  {
  public:
    PatchTest(const unsigned int degree, const Setting &setting)
      : patch(degree, setting, Common::Contact::FrictionLaw::frictionless, 0.)
    {}

    void
    run();

  private:
    void
    setup_system();
    void
    check_results(const Common::Solvers::NewtonStatistics &statistics);

    Patch<dim> patch;
  };



  // The lower block rests on u_y = 0; both left sides are symmetry lines.
  template <int dim>
  void
  PatchTest<dim>::setup_system()
  {
    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints);
    patch.add_lower_support(constraints);
    patch.add_symmetry(constraints);
    constraints.close();
    patch.setup_problem(constraints);
  }



  template <int dim>
  void
  PatchTest<dim>::check_results(
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const auto  &coupling      = patch.contact_problem->coupling();
    const auto  &enforcement   = patch.contact_problem->enforcement();
    const auto  &solution      = patch.contact_problem->displacement();
    const auto  &bulk_residual = patch.contact_problem->bulk_residual();
    const double p             = patch.setting.pressure;
    const bool   axisymmetric =
      patch.setting.kinematics == Common::Physics::Kinematics::axisymmetric;

    // (a) Nodal pressures.
    unsigned int n_paired      = 0;
    double       max_deviation = 0., sum = 0.;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      {
        n_paired += coupling.row(j).has_partner;
        if (!enforcement.is_active(j))
          continue;
        const double pj = enforcement.pressure(j);
        sum += pj;
        max_deviation = std::max(max_deviation, std::abs(pj - p) / p);
      }
    const unsigned int n_active        = enforcement.n_active();
    const double       mean            = n_active > 0 ? sum / n_active : 0.;
    const bool         all_active      = n_active == n_paired && n_active > 0;
    const bool         pressures_exact = max_deviation < 1e-8;
    deallog << "Secondary nodes " << coupling.n_rows() << ", paired "
            << n_paired << ", active " << n_active << std::endl;
    deallog << "All paired secondary nodes active: " << yes_no(all_active)
            << std::endl;
    deallog << "Mean contact pressure: " << format(mean) << " MPa" << std::endl;
    deallog << "max |p_j - p|/p < 1e-8: " << yes_no(pressures_exact)
            << std::endl;
    deallog << "(a) nodal pressures: "
            << pass_fail(all_active && pressures_exact) << std::endl;

    // (b) Uniform stress at every quadrature point of both bodies.
    const QGauss<dim>                    fe_quadrature(patch.degree + 1);
    FEValues<dim>                        fe_values(patch.mapping,
                            patch.fe,
                            fe_quadrature,
                            update_values | update_gradients |
                              update_quadrature_points);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strains(fe_quadrature.size());
    std::vector<Tensor<1, dim>>          displacements(fe_quadrature.size());
    double       max_xx = 0., max_yy = 0., max_xy = 0., max_hoop = 0.;
    unsigned int n_points = 0;
    for (const auto &cell : patch.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strains);
          fe_values[displacement].get_function_values(solution, displacements);
          const auto &law = patch.physics->material(cell->material_id());
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              SymmetricTensor<2, dim> sigma = law.stress(strains[q]);
              if (axisymmetric)
                {
                  // Hoop strain u_r/r in the trace, and the hoop stress.
                  const double hoop =
                    displacements[q][0] / fe_values.quadrature_point(q)[0];
                  for (unsigned int d = 0; d < dim; ++d)
                    sigma[d][d] += law.lame_lambda() * hoop;
                  const double sigma_hoop =
                    law.lame_lambda() * (trace(strains[q]) + hoop) +
                    2. * law.lame_mu() * hoop;
                  max_hoop = std::max(max_hoop, std::abs(sigma_hoop) / p);
                }
              max_xx = std::max(max_xx, std::abs(sigma[0][0]) / p);
              max_yy = std::max(max_yy, std::abs(sigma[1][1] + p) / p);
              max_xy = std::max(max_xy, std::abs(sigma[0][1]) / p);
              ++n_points;
            }
        }
    const bool stress_uniform = max_xx < 1e-8 && max_yy < 1e-8 &&
                                max_xy < 1e-8 && max_hoop < 1e-8 &&
                                n_points > 0;
    deallog << "Quadrature points checked: " << n_points << std::endl;
    deallog << "max |sigma_yy + p|/p < 1e-8: " << yes_no(max_yy < 1e-8)
            << std::endl;
    deallog << "max |sigma_xx|/p < 1e-8: " << yes_no(max_xx < 1e-8)
            << std::endl;
    deallog << "max |sigma_xy|/p < 1e-8: " << yes_no(max_xy < 1e-8)
            << std::endl;
    if (axisymmetric)
      deallog << "max |sigma_hoop|/p < 1e-8: " << yes_no(max_hoop < 1e-8)
              << std::endl;
    deallog << "(b) uniform stress: " << pass_fail(stress_uniform) << std::endl;

    // (c) Total contact force on the secondary surface: (0, -p A), A = L
    // per unit thickness or pi L^2 over the full ring.
    const Tensor<1, dim> force =
      Common::Contact::total_contact_force(coupling, enforcement);
    const double applied     = p * interface_area(patch.setting);
    const bool   force_exact = std::abs(force[1] + applied) / applied < 1e-10 &&
                             std::abs(force[0]) / applied < 1e-10;
    deallog << "Total contact force F_y: " << format(force[1])
            << (axisymmetric ? " N" : " N/mm") << std::endl;
    deallog << "|F_y + p A|/(p A) < 1e-10 and |F_x|/(p A) < 1e-10: "
            << yes_no(force_exact) << std::endl;
    deallog << "(c) contact force: " << pass_fail(force_exact) << std::endl;

    // (d) Newton.
    deallog << "Newton iterations: " << statistics.n_iterations << std::endl;
    deallog << "Newton converged: " << yes_no(statistics.converged)
            << std::endl;
    deallog << "(d) Newton convergence: " << pass_fail(statistics.converged)
            << std::endl;

    // (e) Frictionless sliding: no tangential traction, and the mean
    // relative tangential displacement (primary minus secondary) of the
    // exact solution, (eps_xx,upper - eps_xx,lower) x, with
    // eps_xx = nu (1 + nu) p / E in plane strain and nu p / E under the
    // uniaxial stress of the axisymmetric stack.
    const double nu = patch.setting.poisson_ratio;
    const double slip_rate =
      nu * (axisymmetric ? 1. : 1. + nu) * p *
      (1. / patch.setting.E_upper - 1. / patch.setting.E_lower);
    const auto profile      = Common::Contact::contact_profile(coupling,
                                                          enforcement,
                                                          solution,
                                                          bulk_residual,
                                                          0);
    double     max_traction = 0., max_slip_error = 0., end_slip = 0.;
    for (const auto &point : profile)
      {
        max_traction =
          std::max(max_traction, std::abs(point.tangential_traction) / p);
        max_slip_error =
          std::max(max_slip_error,
                   std::abs(point.slip - slip_rate * point.position[0]) /
                     std::abs(slip_rate * interface_length));
        end_slip = point.slip;
      }
    const bool sliding_exact =
      !profile.empty() && max_traction < 1e-8 && max_slip_error < 1e-8;
    deallog << "Relative tangential displacement at x = 1: " << format(end_slip)
            << " mm (exact " << format(slip_rate * interface_length) << " mm)"
            << std::endl;
    deallog << "max |slip_j - slip_exact(x_j)|/|slip_exact(1)| < 1e-8: "
            << yes_no(max_slip_error < 1e-8) << std::endl;
    deallog << "max |tangential traction|/p < 1e-8: "
            << yes_no(max_traction < 1e-8) << std::endl;
    deallog << "(e) frictionless sliding: " << pass_fail(sliding_exact)
            << std::endl;
  }



  template <int dim>
  void
  PatchTest<dim>::run()
  {
    setup_system();
    const auto statistics = patch.solve_and_commit();
    check_results(statistics);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();

  for (const Setting &setting : {plane_strain_stack, axisymmetric_stack})
    {
      deallog << title(setting) << std::endl;
      for (const unsigned int degree : {1u, 2u})
        {
          PatchTest<2> test(degree, setting);
          test.run();
        }
    }
}
