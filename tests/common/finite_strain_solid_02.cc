// The tangent of Common::Physics::FiniteStrainSolid against central
// differences of its internal forces: at a random displacement (amplitude
// 3 % of the cell size) of a distorted mesh, for every element technology
// (Q1, Q2, Q1 F-bar, Q1-P0, Q2-P1), kinematics (plane strain,
// axisymmetric, 3D) and law (split neo-Hookean, J2 plasticity with a
// plastic state), the product of the tangent with a random direction v
// equals (f(u + h v) - f(u - h v)) / (2h) with h = 1e-6: largest
// difference over the largest entry < 1e-6. The J2 state is committed at
// a stretched configuration first, so that the check runs on plastic
// points (the number of plastic points is printed as "plastic").

#include "../finite_strain_problem.h"
#include "../tests.h"

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <random>

using namespace dealii;
using namespace Common;

template <int dim>
void
check(const std::string                     &name,
      const Materials::FiniteStrainMaterial &law,
      const Physics::ElementTechnology       technology,
      const unsigned int                     degree,
      const Physics::Kinematics              kinematics)
{
  Triangulation<dim> triangulation;
  Point<dim>         lower, upper;
  for (unsigned int d = 0; d < dim; ++d)
    {
      lower[d] = 1.;
      upper[d] = 3.;
    }
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            std::vector<unsigned int>(dim, 2),
                                            lower,
                                            upper);
  GridTools::distort_random(0.2, triangulation, false, 7);

  Physics::FiniteStrainParameters parameters;
  parameters.technology = technology;
  FiniteStrainTest::Problem<dim> problem(triangulation,
                                         degree,
                                         law,
                                         parameters,
                                         kinematics);
  const IndexSet all = complete_index_set(problem.dof_handler.n_dofs());
  using Vector       = TrilinosWrappers::MPI::Vector;

  std::mt19937                           generator(5);
  std::uniform_real_distribution<double> random(-1., 1.);
  // A plastic state: commit a stretch along x of 8 %.
  for (types::global_dof_index i = 0; i < all.size(); ++i)
    problem.u(i) = problem.component(i) == 0 ?
                     0.08 * (problem.support_points.at(i)[0] - 1.) :
                     0.;
  problem.solid->commit(problem.dof_handler, problem.u);
  unsigned int n_plastic = 0;
  for (const auto &cell : problem.dof_handler.active_cell_iterators())
    n_plastic +=
      problem.solid->cell_averages(cell->active_cell_index()).plastic_strain >
      0.;

  Vector u(all, MPI_COMM_WORLD), v(all, MPI_COMM_WORLD);
  for (types::global_dof_index i = 0; i < all.size(); ++i)
    {
      u(i) = problem.u(i) + 0.03 * random(generator);
      v(i) = random(generator);
    }
  AffineConstraints<double> none;
  none.close();
  DynamicSparsityPattern pattern(all.size());
  DoFTools::make_sparsity_pattern(problem.dof_handler, pattern);
  TrilinosWrappers::SparseMatrix K;
  K.reinit(all, all, pattern, MPI_COMM_WORLD);
  Vector r(all, MPI_COMM_WORLD), Kv(all, MPI_COMM_WORLD),
    plus(all, MPI_COMM_WORLD), minus(all, MPI_COMM_WORLD);
  problem.solid->assemble_system(problem.dof_handler, none, u, K, r);
  K.compress(VectorOperation::add);
  K.vmult(Kv, v);
  const double h = 1e-6;
  Vector       w = u;
  w.add(h, v);
  problem.solid->assemble_internal_force(problem.dof_handler, none, w, plus);
  w.add(-2. * h, v);
  problem.solid->assemble_internal_force(problem.dof_handler, none, w, minus);
  plus.add(-1., minus);
  plus *= 1. / (2. * h);
  plus.add(-1., Kv);
  deallog << name << ": plastic " << (n_plastic > 0)
          << ", tangent against central differences < 1e-6: "
          << (plus.linfty_norm() / Kv.linfty_norm() < 1e-6) << std::endl;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const Materials::NeoHookeanSplit rubber(10., 0.45);
  Materials::HardeningParameters   hardening;
  hardening.type              = Materials::HardeningType::linear;
  hardening.yield_stress      = 194.;
  hardening.hardening_modulus = 1000.;
  const Materials::J2Plasticity metal(70500., 0.342, hardening);

  using T = Physics::ElementTechnology;
  using K = Physics::Kinematics;
  const std::vector<std::tuple<std::string, T, unsigned int>> elements = {
    {"Q1", T::displacement, 1},
    {"Q2", T::displacement, 2},
    {"Q1 F-bar", T::f_bar, 1},
    {"Q1-P0", T::mixed, 1},
    {"Q2-P1", T::mixed, 2}};
  for (const auto &[element, technology, degree] : elements)
    for (const auto &[law_name, law] : std::vector<
           std::pair<std::string, const Materials::FiniteStrainMaterial *>>{
           {"rubber", &rubber},
           {"J2", &metal}})
      {
        check<2>("plane strain, " + element + ", " + law_name,
                 *law,
                 technology,
                 degree,
                 K::cartesian);
        check<2>("axisymmetric, " + element + ", " + law_name,
                 *law,
                 technology,
                 degree,
                 K::axisymmetric);
        check<3>("3D, " + element + ", " + law_name,
                 *law,
                 technology,
                 degree,
                 K::cartesian);
      }
}
