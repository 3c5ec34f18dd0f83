// Load and unload of a bar, finite-strain J2 plasticity, 3D
// (Common::Physics::FiniteStrainSolid): the cube [0, 10]^3 mm, 2 cells per
// direction, symmetry planes x = 0, y = 0, z = 0 (normal displacement
// zero), the face x = 10 pulled to a logarithmic strain of 0.1 in 5
// steps (E = 70500 MPa, nu = 0.342, Swift law of benchmark 3), then
// released (the face freed, no load). For the displacement element Q1,
// the F-bar element Q1 and the mixed element Q2-P1:
// - the axial force times the stretch over the initial area equals the
//   Kirchhoff stress of the closed form tau = sigma_f(ln(lambda) - tau/E)
//   (relative error < 1e-8) at every step;
// - after release: every internal force vanishes (1e-8 N against forces
//   of 1e4 N), the permanent log strain equals the equivalent plastic
//   strain of the closed form (1e-8), and the release is elastic (the
//   plastic strain does not change, 1e-12);
// - Newton converges in at most 6 iterations per step, quadratically: the
//   order estimated from the last three residuals above 1e-12 exceeds 1.8
//   at every step.

#include "../finite_strain_problem.h"
#include "../tests.h"

#include <deal.II/grid/grid_generator.h>

using namespace dealii;
using namespace Common;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Materials::FiniteStrainMaterialParameters material;
  material.model                  = Materials::FiniteStrainModel::j2_plasticity;
  material.youngs_modulus         = 70500.;
  material.poisson_ratio          = 0.342;
  material.hardening.type         = Materials::HardeningType::swift;
  material.hardening.yield_stress = 194.;
  material.hardening.strength_coefficient = 550.4;
  material.hardening.exponent             = 0.223;
  material.hardening.youngs_modulus       = 70500.;
  const auto law = Materials::create_finite_strain_material(material);
  const Materials::HardeningLaw hardening(material.hardening);
  const double                  E = material.youngs_modulus, L = 10.;

  Triangulation<3> triangulation;
  GridGenerator::subdivided_hyper_cube(triangulation, 2, 0., L);

  const std::vector<
    std::tuple<std::string, Physics::ElementTechnology, unsigned int>>
    elements = {{"Q1", Physics::ElementTechnology::displacement, 1},
                {"Q1 F-bar", Physics::ElementTechnology::f_bar, 1},
                {"Q1-P0", Physics::ElementTechnology::mixed, 1},
                {"Q2", Physics::ElementTechnology::displacement, 2},
                {"Q2-P1", Physics::ElementTechnology::mixed, 2}};
  for (const auto &[name, technology, degree] : elements)
    {
      Physics::FiniteStrainParameters parameters;
      parameters.technology = technology;
      FiniteStrainTest::Problem<3> problem(triangulation,
                                           degree,
                                           *law,
                                           parameters);
      for (unsigned int d = 0; d < 3; ++d)
        problem.prescribe(problem.dofs(d,
                                       [d](const Point<3> &x) {
                                         return std::abs(x[d]) < 1e-10;
                                       }),
                          [](auto, double) { return 0.; });
      const auto end = problem.dofs(0, [L](const Point<3> &x) {
        return std::abs(x[0] - L) < 1e-10;
      });
      problem.prescribe(end, [L](auto, const double load) {
        return L * (std::exp(0.1 * load) - 1.);
      });
      std::vector<std::pair<types::global_dof_index, double>> end_dofs;
      for (const auto dof : end)
        end_dofs.emplace_back(dof, 1.);

      double       stress_error = 0., tau = 0., lowest_order = 2.;
      unsigned int most_iterations = 0;
      bool         converged       = true;
      for (unsigned int step = 1; step <= 5; ++step)
        {
          std::vector<double> norms;
          const int           iterations = problem.solve(0.2 * step, &norms);
          // Order of convergence from the last three residuals above
          // round-off (the first entry is the tangent predictor's).
          std::vector<double> e;
          for (unsigned int k = 1; k < norms.size(); ++k)
            if (norms[k] > 1e-12)
              e.push_back(norms[k]);
          if (e.size() >= 3)
            lowest_order =
              std::min(lowest_order,
                       std::log(e[e.size() - 1] / e[e.size() - 2]) /
                         std::log(e[e.size() - 2] / e[e.size() - 3]));
          converged       = converged && iterations >= 0;
          most_iterations = std::max<unsigned int>(most_iterations, iterations);
          const double eps = 0.02 * step;
          double       lo = 0., hi = E * eps;
          for (unsigned int it = 0; it < 200; ++it)
            {
              const double mid = 0.5 * (lo + hi);
              (mid - hardening.flow_stress(std::max(eps - mid / E, 0.)) > 0. ?
                 hi :
                 lo)           = mid;
            }
          tau                = std::min(0.5 * (lo + hi), E * eps);
          const double force = problem.reaction(end_dofs);
          stress_error =
            std::max(stress_error,
                     std::abs(force * std::exp(eps) / (L * L) - tau) / tau);
        }
      const double ep = 0.1 - tau / E;
      deallog << name << ": converged " << converged
              << ", at most 6 Newton iterations per step "
              << (most_iterations <= 6)
              << ", axial stress error < 1e-8: " << (stress_error < 1e-8)
              << ", order of convergence > 1.8: " << (lowest_order > 1.8)
              << std::endl;

      // Release the pulled face; the bar springs back elastically.
      const auto plastic_strain_before =
        problem.solid->cell_averages(0).plastic_strain;
      problem.release([&](const types::global_dof_index dof) {
        return std::find(end.begin(), end.end(), dof) != end.end();
      });
      const int iterations = problem.solve(1.);
      // Every internal force vanishes but the reactions of the symmetry
      // planes, which vanish too in uniaxial stress.
      const double largest   = problem.internal_force().linfty_norm();
      const double permanent = std::log(1. + problem.u(end[0]) / L);
      deallog << name << " released: converged " << (iterations >= 0)
              << ", forces vanish " << (largest < 1e-8)
              << ", permanent strain = plastic strain "
              << (std::abs(permanent - ep) < 1e-8) << ", elastic "
              << (std::abs(problem.solid->cell_averages(0).plastic_strain -
                           plastic_strain_before) < 1e-12)
              << std::endl;
    }
}
