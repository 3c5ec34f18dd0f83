/*
 * Reuse of sparse direct factors (Linear solver/Reuse factorisation,
 * Common::Solvers::LinearSolver) on the 5-point Laplacian of a 20 x 20 grid
 * plus identity, with MUMPS:
 * (a) the first solve factorises (1 iteration reported);
 * (b) the same pattern with two rows changed, a rank-2 change, is solved
 *     by GMRES preconditioned with the old factors: GMRES needs 2 or 3
 *     iterations;
 * (c) a matrix far from the factored one (20 times the diagonal; GMRES
 *     would need far more than the 5 iterations allowed here to reduce
 *     the residual by 1e-12) is factorised anew (1 iteration reported);
 * (d) a small change of that one is solved with the new factors.
 * Every solution must leave a relative residual |Ax - b|/|b| below 1e-10
 * (the solver's tolerance is 1e-12).
 */

#include <common/solvers/linear_solver.h>

#include "../five_point_matrix.h"
#include "../tests.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

using namespace dealii;

namespace
{
  constexpr unsigned int n_side = 20, n = n_side * n_side;

  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }

  /** Laplacian plus identity, with @p diagonal_factor times its diagonal. */
  void
  fill(TrilinosWrappers::SparseMatrix &A, const double diagonal_factor)
  {
    A = 0.;
    for (unsigned int i = 0; i < n_side; ++i)
      for (unsigned int j = 0; j < n_side; ++j)
        {
          const unsigned int row = i * n_side + j;
          A.set(row, row, diagonal_factor * 5.);
          if (i > 0)
            A.set(row, row - n_side, -1.);
          if (i + 1 < n_side)
            A.set(row, row + n_side, -1.);
          if (j > 0)
            A.set(row, row - 1, -1.);
          if (j + 1 < n_side)
            A.set(row, row + 1, -1.);
        }
    A.compress(VectorOperation::insert);
  }

  double
  relative_residual(const TrilinosWrappers::SparseMatrix &A,
                    const TrilinosWrappers::MPI::Vector  &x,
                    const TrilinosWrappers::MPI::Vector  &b)
  {
    TrilinosWrappers::MPI::Vector r(b);
    A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const IndexSet                 all = complete_index_set(n);
  TrilinosWrappers::SparseMatrix A;
  reinit_five_point(A, n_side);
  TrilinosWrappers::MPI::Vector x(all, MPI_COMM_WORLD), b(x);
  for (unsigned int i = 0; i < n; ++i)
    b(i) = 1. + 0.01 * i;

  Common::Solvers::LinearSolverParameters parameters;
  parameters.type                = Common::Solvers::LinearSolverType::mumps;
  parameters.tolerance           = 1e-12;
  parameters.max_iterations      = 5; // bounds GMRES: no timing dependence
  parameters.reuse_factorisation = true;
  Common::Solvers::LinearSolver solver(parameters);

  // Solve and report whether the iteration count lies in [lo, hi] and
  // the residual is small.
  const auto solve_and_check = [&](const std::string &label,
                                   const unsigned int lo,
                                   const unsigned int hi) {
    const unsigned int iterations = solver.solve(A, x, b);
    deallog << label << ", " << iterations << " iteration(s): "
            << pass_fail(iterations >= lo && iterations <= hi &&
                         relative_residual(A, x, b) < 1e-10)
            << std::endl;
  };

  fill(A, 1.);
  solve_and_check("(a) first solve factorises", 1, 1);

  A.set(37, 37, 9.);
  A.set(211, 212, -3.);
  A.compress(VectorOperation::insert);
  solve_and_check("(b) two rows changed: GMRES with the old factors", 2, 3);

  fill(A, 20.);
  solve_and_check("(c) a distant matrix is factorised anew", 1, 1);

  A.set(100, 100, 150.);
  A.compress(VectorOperation::insert);
  solve_and_check("(d) one row changed: GMRES with the new factors", 1, 2);
}
