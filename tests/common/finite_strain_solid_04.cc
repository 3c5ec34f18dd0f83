// Cook's membrane, nearly incompressible, plane strain, finite strain
// (Common::Physics::FiniteStrainSolid): the tapered panel x = 48 xi,
// y = 44 xi + eta (44 - 28 xi) (mm), 0 <= xi, eta <= 1, clamped at x = 0,
// with a uniform dead shear traction of 6.25 N/mm^2 in y on the edge
// x = 48 (100 N per mm of depth), in 10 load steps. Split neo-Hookean law
// with the shear modulus of deal.II's step-44, mu = 80.194 MPa, and
// nu = 0.4999 (E = 2 mu (1 + nu)). The result is the vertical displacement
// of the tip (48, 60) on N x N meshes for the plain Q1 element, the F-bar
// Q1 element and the mixed Q2-P1 element.
// Checks: (a) F-bar Q1 and Q2-P1 converge to the same tip displacement:
// within 0.5 % of each other at the finest meshes (Q1 32 x 32, Q2 16 x 16),
// and the F-bar tip approaches the finest Q2-P1 one at every refinement;
// (b) the plain Q1
// element locks: at 32 x 32 its tip displacement is below 80 % of the
// converged one; (c) every load step converges.
// For scripts/finite_strain_study.py, each run is also printed to standard
// output as "cook,<element>,<n>,<DoFs>,<tip (mm)>,<Newton iterations>,
// <wall time (s)>", and the environment variable COOK_FINEST (default 32)
// sets the finest Q1 mesh (Q2: half of it).

#include "../finite_strain_problem.h"
#include "../tests.h"

#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <string>

using namespace dealii;
using namespace Common;

namespace
{
  constexpr double       mu       = 80.194;
  constexpr double       nu       = 0.4999;
  constexpr double       traction = 6.25; // N/mm^2 on the 16 mm edge
  constexpr unsigned int n_steps  = 10;

  struct Run
  {
    /** Tip displacement u_y(48, 60) (mm), NaN if a step failed. */
    double       tip          = 0.;
    unsigned int n_dofs       = 0;
    unsigned int n_iterations = 0;
  };

  Run
  tip_displacement(const Physics::ElementTechnology technology,
                   const unsigned int               degree,
                   const unsigned int               n)
  {
    Triangulation<2> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {n, n},
                                              Point<2>(),
                                              Point<2>(1., 1.));
    GridTools::transform(
      [](const Point<2> &p) {
        return Point<2>(48. * p[0], 44. * p[0] + p[1] * (44. - 28. * p[0]));
      },
      triangulation);

    const Materials::NeoHookeanSplit rubber(2. * mu * (1. + nu), nu);
    Physics::FiniteStrainParameters  parameters;
    parameters.technology = technology;
    FiniteStrainTest::Problem<2> problem(triangulation,
                                         degree,
                                         rubber,
                                         parameters);
    // K/mu = 5000: the round-off of the volumetric stress puts a floor of
    // a few 1e-10 under the relative residual, which Newton reaches
    // quadratically.
    problem.newton_tolerance = 1e-8;
    const auto clamped       = [](const Point<2> &x) {
      return x[0] < 1e-10;
    };
    for (unsigned int c = 0; c < 2; ++c)
      problem.prescribe(problem.dofs(c, clamped),
                        [](auto, double) { return 0.; });

    // Consistent nodal forces of the traction on x = 48.
    const QGauss<1>                      face_quadrature(degree + 1);
    FEFaceValues<2>                      fe_face(problem.mapping,
                            problem.fe,
                            face_quadrature,
                            update_values | update_JxW_values);
    std::vector<types::global_dof_index> indices(problem.fe.n_dofs_per_cell());
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            std::abs(cell->face(f)->center()[0] - 48.) < 1e-10)
          {
            fe_face.reinit(cell, f);
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              if (problem.fe.system_to_component_index(i).first == 1)
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  problem.external_force(indices[i]) +=
                    traction * fe_face.shape_value_component(i, q, 1) *
                    fe_face.JxW(q);
          }

    const auto tip = problem.dofs(1, [](const Point<2> &x) {
      return std::abs(x[0] - 48.) < 1e-10 && std::abs(x[1] - 60.) < 1e-10;
    });
    AssertThrow(tip.size() == 1, ExcInternalError());
    Run run;
    run.n_dofs = problem.dof_handler.n_dofs();
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const int n = problem.solve(static_cast<double>(step) / n_steps);
        if (n < 0)
          {
            run.tip = std::numeric_limits<double>::quiet_NaN();
            return run;
          }
        run.n_iterations += n;
      }
    run.tip = problem.u(tip[0]);
    return run;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  struct Element
  {
    std::string                name;
    Physics::ElementTechnology technology;
    unsigned int               degree;
    std::vector<unsigned int>  meshes;
  };
  const char               *finest_text = std::getenv("COOK_FINEST");
  const unsigned int        finest = finest_text ? std::atoi(finest_text) : 32;
  std::vector<unsigned int> q1_meshes, q2_meshes;
  for (unsigned int n = 2; n <= finest; n *= 2)
    {
      q1_meshes.push_back(n);
      if (2 * n <= finest)
        q2_meshes.push_back(n);
    }
  const std::vector<Element> elements = {
    {"Q1", Physics::ElementTechnology::displacement, 1, q1_meshes},
    {"Q1 F-bar", Physics::ElementTechnology::f_bar, 1, q1_meshes},
    {"Q2-P1", Physics::ElementTechnology::mixed, 2, q2_meshes}};

  std::map<std::string, std::vector<double>> tips;
  bool                                       converged = true;
  for (const auto &element : elements)
    for (const unsigned int n : element.meshes)
      {
        const auto start = std::chrono::steady_clock::now();
        const Run run = tip_displacement(element.technology, element.degree, n);
        const double wall = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start)
                              .count();
        converged = converged && std::isfinite(run.tip);
        tips[element.name].push_back(run.tip);
        deallog << std::left << std::setw(9) << element.name << n << " x " << n
                << ": tip u_y = " << std::setprecision(4) << run.tip << " mm"
                << std::endl;
        std::cout << "cook," << element.name << "," << n << "," << run.n_dofs
                  << "," << std::setprecision(8) << run.tip << ","
                  << run.n_iterations << "," << wall << std::endl;
      }

  const auto  &fbar          = tips["Q1 F-bar"];
  const auto  &mixed         = tips["Q2-P1"];
  const double converged_tip = mixed.back();
  const auto   relative      = [](const double a, const double b) {
    return std::abs(a - b) / std::abs(b);
  };
  deallog << "(a) F-bar Q1 against Q2-P1, finest meshes, within 0.5 %: "
          << (relative(fbar.back(), converged_tip) < 5e-3 ? "PASS" : "FAIL")
          << std::endl;
  bool gap_shrinks = true;
  for (unsigned int i = 1; i < fbar.size(); ++i)
    gap_shrinks = gap_shrinks && std::abs(fbar[i] - converged_tip) <
                                   std::abs(fbar[i - 1] - converged_tip);
  deallog << "    F-bar approaches Q2-P1 at every refinement: "
          << (gap_shrinks ? "PASS" : "FAIL") << std::endl;
  deallog << "(b) plain Q1 locks, finest mesh below 80 % of the converged tip: "
          << (tips["Q1"].back() < 0.8 * converged_tip ? "PASS" : "FAIL")
          << std::endl;
  deallog << "(c) every load step converged: " << (converged ? "PASS" : "FAIL")
          << std::endl;
}
