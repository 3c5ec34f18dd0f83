// A run that fails on MPI rank 1 only, while rank 0 waits for it in a
// collective call: Common::IO::run_main() must report the error once and
// end every rank with a non-zero exit (tests/mpi/throw_on_rank_1.sh). The
// ranks hold the parallel factors of a direct solver (MUMPS) when rank 1
// throws: releasing them is a collective call, which the unwinding of
// rank 1 alone must not enter.

#include <common/io/run_main.h>
#include <common/solvers/linear_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

int
main(int argc, char **argv)
{
  return Common::IO::run_main(
    argc,
    argv,
    "throw_on_rank_1",
    "fails on MPI rank 1 only",
    [](dealii::ParameterHandler &) {},
    [](const std::string &) {
      using namespace dealii;
      const unsigned int rank =
        Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const unsigned int n_ranks =
        Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

      // A diagonal system with two rows per rank, factorised by MUMPS.
      IndexSet owned(2 * n_ranks);
      owned.add_range(2 * rank, 2 * rank + 2);
      DynamicSparsityPattern dsp(2 * n_ranks, 2 * n_ranks, owned);
      for (const auto i : owned)
        dsp.add(i, i);
      TrilinosWrappers::SparseMatrix matrix;
      matrix.reinit(owned, owned, dsp, MPI_COMM_WORLD);
      TrilinosWrappers::MPI::Vector x(owned, MPI_COMM_WORLD);
      TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD);
      for (const auto i : owned)
        {
          matrix.set(i, i, 2.);
          b(i) = 1.;
        }
      matrix.compress(VectorOperation::insert);
      b.compress(VectorOperation::insert);
      Common::Solvers::LinearSolverParameters parameters;
      parameters.type           = Common::Solvers::LinearSolverType::mumps;
      parameters.tolerance      = 1e-12;
      parameters.max_iterations = 1;
      Common::Solvers::LinearSolver solver(parameters);
      solver.solve(matrix, x, b);
      AssertThrow(std::abs(x(2 * rank) - 0.5) < 1e-14,
                  ExcMessage("the direct solve is wrong"));

      if (rank == 1)
        AssertThrow(false, ExcMessage("thrown on rank 1 only"));
      // Rank 0 waits here for rank 1, which never comes.
      MPI_Barrier(MPI_COMM_WORLD);
    });
}
