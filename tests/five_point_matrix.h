/**
 * @file five_point_matrix.h
 * The pattern of the 5-point stencil on an n x n grid, for the tests of the
 * linear solvers.
 */
#ifndef tests_five_point_matrix_h
#define tests_five_point_matrix_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

/** Reinitialise @p A, on MPI_COMM_WORLD with every row on every rank, with
 * the pattern of the 5-point stencil on a grid of @p n_side x @p n_side
 * points numbered row by row. */
inline void
reinit_five_point(dealii::TrilinosWrappers::SparseMatrix &A,
                  const unsigned int                      n_side)
{
  const unsigned int             n = n_side * n_side;
  dealii::DynamicSparsityPattern dsp(n, n);
  for (unsigned int row = 0; row < n; ++row)
    for (const int offset :
         {-static_cast<int>(n_side), -1, 0, 1, static_cast<int>(n_side)})
      if (static_cast<int>(row) + offset >= 0 &&
          static_cast<int>(row) + offset < static_cast<int>(n))
        dsp.add(row, row + offset);
  const dealii::IndexSet all = dealii::complete_index_set(n);
  A.reinit(all, all, dsp, MPI_COMM_WORLD);
}

#endif
