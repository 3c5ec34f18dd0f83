// Elastic-perfectly plastic thick-walled cylinder under internal pressure,
// plane strain, in the small-strain limit (Common::Physics::FiniteStrainSolid
// with J2 plasticity, mixed Q2-P1 element): quarter of the annulus
// a = 10 <= r <= b = 20 mm, E = 200000 MPa, nu = 0.4999, yield stress
// 20 MPa without hardening (strains of a few 1e-4). Hill's closed form for
// an incompressible material with the von Mises condition in plane strain
// (k = sigma_y / sqrt 3): with the plastic zone reaching radius c,
//   p = k (2 ln(c/a) + 1 - c^2/b^2),   u(r) = k c^2 / (2 G r).
// The inner surface is moved radially to u(a) for c = 10 (first yield),
// 11.25, ..., 17.5 mm; the pressure of the finite elements is the radial
// internal force of the inner surface over its current quarter arc.
// Checks: the pressure within 0.5 % of Hill's at c = 12.5, 15 and 17.5;
// the cells with centres inside r < c - h yield (positive equivalent
// plastic strain) and those outside r > c + h do not; every step
// converges.

#include "../finite_strain_problem.h"
#include "../tests.h"

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

using namespace dealii;
using namespace Common;

namespace
{
  std::string
  scientific(const double x)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(1) << x;
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const double A = 10., B = 20., E = 200000., nu = 0.4999, sigma_y = 20.;
  const double k = sigma_y / std::sqrt(3.), G = E / (2. * (1. + nu));

  Triangulation<2> triangulation;
  GridGenerator::quarter_hyper_shell(triangulation, Point<2>(), A, B);
  triangulation.refine_global(2);
  const double h = (B - A) / 4.;

  Materials::HardeningParameters hardening;
  hardening.type         = Materials::HardeningType::linear;
  hardening.yield_stress = sigma_y;
  const Materials::J2Plasticity   steel(E, nu, hardening);
  Physics::FiniteStrainParameters parameters;
  parameters.technology = Physics::ElementTechnology::mixed;
  FiniteStrainTest::Problem<2> problem(triangulation, 2, steel, parameters);
  // With a bulk modulus 1.7e7 times the yield stress, the round-off of
  // J - 1 (1e-16) puts a floor of about 4e-8 under the relative residual;
  // Newton reaches it in two iterations.
  problem.newton_tolerance = 1e-6;

  // The load is the inner radial displacement u(a) (mm).
  const auto radial =
    FiniteStrainTest::prescribe_quarter_annulus(problem, A, 1.);

  bool converged = true, pressures = true, zones = true;
  for (unsigned int step = 0; step <= 6; ++step)
    {
      const double c        = A + 1.25 * step;
      const double u_a      = k * c * c / (2. * G * A);
      const int    n_newton = problem.solve(u_a);
      converged             = converged && n_newton >= 0;
      const double p_hill   = k * (2. * std::log(c / A) + 1. - c * c / (B * B));
      const double p =
        problem.reaction(radial) / (numbers::PI / 2. * (A + u_a));
      const double error = std::abs(p - p_hill) / p_hill;
      if (step % 2 == 0 && step > 0)
        pressures = pressures && error < 5e-3;

      // Plastic zone against c, one cell width either side.
      bool zone = true;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        {
          const double r = cell->center().norm();
          const double plastic_strain =
            problem.solid->cell_averages(cell->active_cell_index())
              .plastic_strain;
          if (r < c - h && step > 0)
            zone = zone && plastic_strain > 0.;
          if (r > c + h)
            zone = zone && plastic_strain == 0.;
        }
      zones = zones && zone;
      deallog << std::fixed << std::setprecision(2) << "c = " << c
              << " mm: Newton iterations " << n_newton
              << ", p = " << std::setprecision(4) << p << " MPa, Hill "
              << p_hill << " MPa, relative error " << scientific(error)
              << ", plastic zone matches: " << (zone ? "yes" : "no")
              << std::endl;
    }
  deallog << "pressure within 0.5 % at c = 12.5, 15, 17.5: "
          << (pressures ? "PASS" : "FAIL") << std::endl;
  deallog << "plastic zone within one cell of c: " << (zones ? "PASS" : "FAIL")
          << std::endl;
  deallog << "every step converged: " << (converged ? "PASS" : "FAIL")
          << std::endl;
}
