/**
 * @file linear_solver.h
 * The "Linear solver" subsection and the solve of one linear system:
 * sparse direct (UMFPACK on one rank; MUMPS or KLU through Trilinos
 * Amesos, in parallel) or
 * conjugate gradients with algebraic multigrid (ML) for large 3D cases.
 */
#ifndef common_solvers_linear_solver_h
#define common_solvers_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

namespace Common
{
  namespace Solvers
  {
    /** Values of the parameter "Solver type" in subsection "Linear
     * solver". */
    enum class LinearSolverType
    {
      umfpack,
      mumps,
      klu,
      cg_amg
    };

    /**
     * @brief Parameters of subsection "Linear solver".
     */
    struct LinearSolverParameters
    {
      /** @brief Declare the entries of subsection "Linear solver". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read the entries of subsection "Linear solver". */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      LinearSolverType type;
      /** Relative residual tolerance of the iterative solver. */
      double tolerance;
      /** Iteration limit of the iterative solver. */
      unsigned int max_iterations;
      /** Direct solvers: solve later systems by GMRES preconditioned with
       * the factors of an earlier matrix while that is cheaper than a new
       * factorisation. */
      bool reuse_factorisation = false;
    };

    /**
     * @brief Linear solver that keeps what can be reused between solves
     * with matrices of one sparsity pattern: the symbolic factorisation of
     * the sparse direct solvers and, with "Reuse factorisation", their
     * numeric factors. A later matrix of a Newton iteration (a few contact
     * rows changed) is then solved by GMRES, right-preconditioned with the
     * factors of the earlier one, to the relative residual "Tolerance";
     * when GMRES would need longer than a new factorisation (more solves
     * with the factors than half the measured factorisation time allows)
     * or stalls, the matrix is factorised anew. Call reset() when the
     * pattern changes.
     */
    class LinearSolver
    {
    public:
      explicit LinearSolver(const LinearSolverParameters &parameters);
      ~LinearSolver();

      /** @brief Forget the symbolic factorisation (new pattern). */
      void
      reset();

      /**
       * @brief Solve \f$A x = b\f$. Throws with a one-line message if
       * the solver fails.
       * @return Number of iterations (1 for a direct solve, the GMRES
       * iterations for a solve with reused factors).
       */
      unsigned int
      solve(const dealii::TrilinosWrappers::SparseMatrix &A,
            dealii::TrilinosWrappers::MPI::Vector        &x,
            const dealii::TrilinosWrappers::MPI::Vector  &b);

    private:
      struct DirectSolverData;
      const LinearSolverParameters      parameters;
      std::unique_ptr<DirectSolverData> direct;
    };

    /**
     * @brief Solve \f$A x = b\f$ once, without reuse. Throws with a one-line message if the
     * solver fails.
     * @return Number of iterations (1 for direct solvers).
     */
    unsigned int
    solve_linear_system(const LinearSolverParameters &parameters,
                        const dealii::TrilinosWrappers::SparseMatrix &A,
                        dealii::TrilinosWrappers::MPI::Vector        &x,
                        const dealii::TrilinosWrappers::MPI::Vector  &b);
  } // namespace Solvers
} // namespace Common

#endif
