/*
 * Rigid body in translation (common/physics/rigid_body.h) in contact: the
 * two-block patch (tests/two_block_patch.h) with the upper block made rigid
 * (u_x fixed, as its symmetry line demands; u_y follows the master DoF of
 * its top left vertex) pressed by p = 100 MPa on its top onto the elastic
 * lower block (E = 70000 MPa, nu = 0.3; u_y = 0 at the bottom, u_x = 0 on
 * the symmetry line), frictionless, non-matching meshes, Q1 and Q2, plane
 * strain and the axisymmetric stack. The exact solution has the lower
 * block in uniaxial stress sigma_yy = -p, and the rigid block translates by
 * the lower block's top displacement, -(1 - nu^2) p / E in plane strain and
 * -p / E for the axisymmetric stack (unit heights). Checks: (a) every
 * active secondary node's pressure equals p to 1e-8 relative; (b) at every
 * quadrature point of the lower block sigma_yy = -p, sigma_xx = sigma_xy = 0
 * to 1e-8 relative, and the rigid block carries no strain (every strain
 * component below 1e-12 of the lower block's); (c) every DoF of the rigid
 * block has u_x = 0 and u_y equal to the exact translation to 1e-10
 * relative; (d) the total contact force equals p times the loaded area to
 * 1e-10 relative; (e) the Newton method converges on its residual test (not
 * on the step test), which needs the contact forces on the rigid block's
 * nodes to reach its master DoF.
 */

#include <common/contact/contact_postprocessor.h>
#include <common/physics/rigid_body.h>

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
  void
  run(const unsigned int degree, const Setting &setting)
  {
    Patch<dim> patch(degree,
                     setting,
                     Common::Contact::FrictionLaw::frictionless,
                     0.);

    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints);
    patch.add_lower_support(constraints);
    patch.add_symmetry(constraints);
    const FEValuesExtractors::Scalar x_displacement(0);
    const auto master = Common::Physics::add_rigid_translation_constraints(
      patch.dof_handler,
      MaterialIds::upper,
      Point<dim>(0., 1. + setting.upper_height),
      patch.fe.component_mask(x_displacement),
      constraints);
    constraints.close();
    patch.setup_problem(constraints);

    const auto statistics = patch.solve_and_commit();

    const auto  &coupling    = patch.contact_problem->coupling();
    const auto  &enforcement = patch.contact_problem->enforcement();
    const auto  &solution    = patch.contact_problem->displacement();
    const double p           = setting.pressure;
    const double E           = setting.E_lower;
    const double nu          = setting.poisson_ratio;
    const bool   axisymmetric =
      setting.kinematics == Common::Physics::Kinematics::axisymmetric;

    // (a) Nodal pressures.
    double max_deviation = 0.;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      if (enforcement.is_active(j))
        max_deviation =
          std::max(max_deviation, std::abs(enforcement.pressure(j) - p) / p);
    const bool pressures_exact =
      enforcement.n_active() > 0 && max_deviation < 1e-8;
    deallog << "Active secondary nodes: " << enforcement.n_active()
            << std::endl;
    deallog << "(a) nodal pressures: " << pass_fail(pressures_exact)
            << std::endl;

    // (b) Uniaxial stress in the lower block, no strain in the rigid one.
    const QGauss<dim>                    quadrature(degree + 1);
    FEValues<dim>                        fe_values(patch.mapping,
                            patch.fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    std::vector<Tensor<1, dim>>          displacements(quadrature.size());
    double max_stress_error = 0., max_rigid_strain = 0.;
    for (const auto &cell : patch.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strains);
          fe_values[displacement].get_function_values(solution, displacements);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double hoop =
                axisymmetric ?
                  displacements[q][0] / fe_values.quadrature_point(q)[0] :
                  0.;
              if (cell->material_id() == MaterialIds::upper)
                {
                  max_rigid_strain = std::max(
                    {max_rigid_strain, strains[q].norm(), std::abs(hoop)});
                  continue;
                }
              const auto &law = patch.physics->material(cell->material_id());
              SymmetricTensor<2, dim> sigma = law.stress(strains[q]);
              for (unsigned int d = 0; d < dim; ++d)
                sigma[d][d] += law.lame_lambda() * hoop;
              max_stress_error = std::max({max_stress_error,
                                           std::abs(sigma[0][0]) / p,
                                           std::abs(sigma[1][1] + p) / p,
                                           std::abs(sigma[0][1]) / p});
            }
        }
    const double strain_scale = p / E;
    const bool   stress_exact = max_stress_error < 1e-8;
    const bool   rigid        = max_rigid_strain < 1e-12 * strain_scale;
    deallog << "(b) lower block uniaxial stress: " << pass_fail(stress_exact)
            << ", rigid block unstrained: " << pass_fail(rigid) << std::endl;

    // (c) The rigid block's translation.
    const double translation = -(axisymmetric ? 1. : 1. - nu * nu) * p / E * 1.;
    double       max_x = 0., max_y_error = 0.;
    std::vector<types::global_dof_index> dof_indices(patch.fe.dofs_per_cell);
    for (const auto &cell : patch.dof_handler.active_cell_iterators())
      if (cell->material_id() == MaterialIds::upper)
        {
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < dof_indices.size(); ++i)
            {
              const double u = solution(dof_indices[i]);
              if (patch.fe.system_to_component_index(i).first == 0)
                max_x = std::max(max_x, std::abs(u));
              else
                max_y_error =
                  std::max(max_y_error,
                           std::abs(u - translation) / std::abs(translation));
            }
        }
    const bool translation_exact =
      max_x < 1e-10 * std::abs(translation) && max_y_error < 1e-10;
    deallog << "Rigid block u_y (master DoF): " << format(solution(master[1]))
            << " mm, exact " << format(translation) << " mm" << std::endl;
    deallog << "(c) rigid translation: " << pass_fail(translation_exact)
            << std::endl;

    // (d) Total contact force.
    const Tensor<1, dim> force =
      Common::Contact::total_contact_force(coupling, enforcement);
    const double applied     = p * interface_area(setting);
    const bool   force_exact = std::abs(force[1] + applied) / applied < 1e-10 &&
                             std::abs(force[0]) / applied < 1e-10;
    deallog << "(d) contact force: " << pass_fail(force_exact) << std::endl;

    // (e) Newton.
    deallog << "Newton iterations: " << statistics.n_iterations
            << ", converged on the residual test: "
            << yes_no(statistics.converged && !statistics.converged_on_step)
            << std::endl;
    deallog << "(e) Newton convergence: "
            << pass_fail(statistics.converged && !statistics.converged_on_step)
            << std::endl;
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
          deallog << "Q" << degree << std::endl;
          run<2>(degree, setting);
        }
    }
}
