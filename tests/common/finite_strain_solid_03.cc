// Exactly incompressible neo-Hookean thick-walled cylinder under internal
// pressure, plane strain (Common::Physics::FiniteStrainSolid, mixed Q2-P1
// element, augmented Lagrangian): quarter of the annulus A = 10 <= R <=
// B = 20 mm, E = 10 MPa, nu = 0.5 (mu = 10/3 MPa), symmetry planes x = 0
// and y = 0, the inner surface moved radially to the inner stretch
// lambda_a = a/A = 1.1, 1.2, ..., 2.0. Rivlin's closed form: the
// deformation r^2 = R^2 + a^2 - A^2 and the pressure
//   p = mu/2 (2 ln(lambda_a/lambda_b) + lambda_b^-2 - lambda_a^-2),
// lambda_b = b/B. The pressure of the finite elements is the radial
// internal force of the inner surface over its current area (the quarter
// arc pi a/2, per mm of depth). Checks: relative pressure error < 1e-3
// at every stretch, the projected J within the augmentation tolerance
// (1e-8) of 1, the outer radius b within 1e-4 mm of the closed form.

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

  const double     A = 10., B = 20., mu = 10. / 3.;
  Triangulation<2> triangulation;
  GridGenerator::quarter_hyper_shell(triangulation, Point<2>(), A, B);
  triangulation.refine_global(2);

  const Materials::NeoHookeanSplit rubber(10., 0.5);
  Physics::FiniteStrainParameters  parameters;
  parameters.technology = Physics::ElementTechnology::mixed;
  FiniteStrainTest::Problem<2> problem(triangulation, 2, rubber, parameters);

  // The load is the inner stretch minus 1.
  const auto radial =
    FiniteStrainTest::prescribe_quarter_annulus(problem, A, A);
  // A DoF on the outer surface at y = 0 (radial there is x).
  const auto outer = problem.dofs(0, [B](const Point<2> &x) {
    return std::abs(x[0] - B) < 1e-8 && std::abs(x[1]) < 1e-10;
  });

  double       pressure_error = 0., radius_error = 0., dilatation = 0.;
  unsigned int most_augmentations = 0;
  bool         converged          = true;
  for (unsigned int step = 1; step <= 10; ++step)
    {
      const double stretch = 1. + 0.1 * step;
      converged            = converged && problem.solve(stretch - 1.) >= 0;
      most_augmentations =
        std::max(most_augmentations, problem.n_augmentations);
      dilatation     = std::max(dilatation, problem.last_dilatation_error);
      const double a = stretch * A;
      const double b = std::sqrt(B * B + a * a - A * A);
      const double lambda_b = b / B;
      const double p_exact =
        mu / 2. *
        (2. * std::log(stretch / lambda_b) + 1. / (lambda_b * lambda_b) -
         1. / (stretch * stretch));
      const double p = problem.reaction(radial) / (numbers::PI * a / 2.);
      pressure_error =
        std::max(pressure_error, std::abs(p - p_exact) / p_exact);
      radius_error =
        std::max(radius_error, std::abs(B + problem.u(outer[0]) - b));
      if (step % 5 == 0)
        deallog << "lambda_a = " << std::setprecision(1) << stretch
                << ": p = " << std::setprecision(4) << p << " MPa, closed form "
                << p_exact << " MPa" << std::endl;
    }
  deallog << "converged " << converged
          << ", pressure error < 1e-3: " << (pressure_error < 1e-3)
          << ", outer radius error < 1e-4 mm: " << (radius_error < 1e-4)
          << ", |projected J - 1| <= 1e-8: " << (dilatation <= 1e-8)
          << ", at most 5 augmentations per step: " << (most_augmentations <= 5)
          << std::endl;
}
