/*
 * A matrix that cannot be factorised (Common::Solvers::LinearSolver with
 * MUMPS and with KLU): the 5-point Laplacian plus identity of a 10 x 10
 * grid with one row and its column zeroed (numerically singular, the
 * pattern unchanged).
 * (a) The solve throws ExcFactorisationFailed, whose message names the
 *     cause: MUMPS' INFOG(1) = -10 ("numerically singular"), and for KLU
 *     "singular to working precision".
 * (b) The same solver object then solves the regular matrix of the same
 *     pattern to a relative residual below 1e-10: a failure leaves no
 *     stale factors behind.
 */

#include <common/io/run_main.h>
#include <common/solvers/linear_solver.h>

#include "../five_point_matrix.h"
#include "../tests.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <tuple>

using namespace dealii;

namespace
{
  constexpr unsigned int n_side = 10, n = n_side * n_side, zeroed = 37;

  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }

  /** Laplacian plus identity; with @p singular, row and column zeroed. */
  void
  fill(TrilinosWrappers::SparseMatrix &A, const bool singular)
  {
    A = 0.;
    for (unsigned int i = 0; i < n_side; ++i)
      for (unsigned int j = 0; j < n_side; ++j)
        {
          const unsigned int row = i * n_side + j;
          const auto         set = [&](const unsigned int col, double v) {
            if (singular && (row == zeroed || col == zeroed))
              v = 0.;
            A.set(row, col, v);
          };
          set(row, 5.);
          if (i > 0)
            set(row - n_side, -1.);
          if (i + 1 < n_side)
            set(row + n_side, -1.);
          if (j > 0)
            set(row - 1, -1.);
          if (j + 1 < n_side)
            set(row + 1, -1.);
        }
    A.compress(VectorOperation::insert);
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
  TrilinosWrappers::MPI::Vector x(all, MPI_COMM_WORLD), b(x), r(x);
  for (unsigned int i = 0; i < n; ++i)
    b(i) = 1. + 0.01 * i;

  for (const auto &[type, name, expected] :
       {std::tuple{Common::Solvers::LinearSolverType::mumps,
                   "MUMPS",
                   "INFOG(1) = -10, the matrix is numerically singular"},
        std::tuple{Common::Solvers::LinearSolverType::klu,
                   "KLU",
                   "singular to working precision"}})
    {
      Common::Solvers::LinearSolverParameters parameters;
      parameters.type      = type;
      parameters.tolerance = 1e-12;
      Common::Solvers::LinearSolver solver(parameters);

      fill(A, true);
      std::string message = "no exception";
      try
        {
          solver.solve(A, x, b);
        }
      catch (const Common::Solvers::ExcFactorisationFailed &e)
        {
          message = Common::IO::one_line_message(e);
        }
      deallog << name << " (a) singular matrix reported: "
              << (message.find(expected) != std::string::npos ?
                    "PASS" :
                    "FAIL: " + message)
              << std::endl;

      fill(A, false);
      solver.solve(A, x, b);
      A.vmult(r, x);
      r -= b;
      deallog << name << " (b) regular matrix solved after the failure: "
              << pass_fail(r.l2_norm() / b.l2_norm() < 1e-10) << std::endl;
    }
}
