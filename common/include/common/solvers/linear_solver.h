/**
 * @file linear_solver.h
 * The "Linear solver" subsection and the solve of one linear system:
 * sparse direct (UMFPACK on one rank; MUMPS or KLU through Trilinos
 * Amesos, in parallel) or Krylov methods (conjugate gradients for symmetric
 * systems, GMRES for the non-symmetric ones of friction) preconditioned by
 * smoothed-aggregation algebraic multigrid (Trilinos ML) with the
 * rigid-body modes as near null space, for large 3D cases.
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
    /**
     * A direct solver could not factorise the matrix: its message names
     * the solver's status (for MUMPS the code INFOG(1) and its meaning).
     * A nonlinear problem treats it as a failed Newton iteration and cuts
     * the load step back; any other caller reports it.
     */
    DeclException1(ExcFactorisationFailed,
                   std::string,
                   << "the linear system could not be factorised: " << arg1);

    enum class LinearSolverType
    {
      umfpack,
      mumps,
      klu,
      cg_amg,
      gmres_amg
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
      /** What the solves so far cost, for the run's profile. */
      struct Statistics
      {
        /** Numeric factorisations of the direct solvers. */
        unsigned int n_factorisations = 0;
        /** Solves by GMRES with reused factors that converged. */
        unsigned int n_reuse_solves = 0;
        /** GMRES iterations of those solves (one solve with the factors
         * each). */
        unsigned int n_reuse_iterations = 0;
        /** GMRES attempts with reused factors given up for a new
         * factorisation. */
        unsigned int n_failed_reuse = 0;
        /** Wall time of the numeric factorisations (s). */
        double factorisation_time = 0.;
      };

      explicit LinearSolver(const LinearSolverParameters &parameters);
      ~LinearSolver();

      /** @brief The cost of the solves since construction. */
      const Statistics &
      statistics() const;

      /** @brief Forget the symbolic factorisation (new pattern). */
      void
      reset();

      /** @brief Whether the solver is one of the multigrid ones, which
       * can use set_near_null_space(). */
      bool
      uses_multigrid() const;

      /**
       * @brief Near null space for the algebraic multigrid of 'cg amg'
       * and 'gmres amg', e.g. Physics::rigid_body_modes().
       * @param modes One vector per mode with its values at the locally
       * owned DoFs, in the order of the matrix's locally owned rows.
       * @param n_components Number of DoFs per node (the displacement
       * components); the DoFs of a node must be numbered consecutively.
       * Without this call, the multigrid takes the constant of each
       * component only.
       */
      void
      set_near_null_space(const std::vector<std::vector<double>> &modes,
                          const unsigned int                      n_components);

      /**
       * @brief Solve \f$A x = b\f$. Throws with a one-line message if
       * the solver fails.
       * @param relative_tolerance Relative residual at which an iterative
       * solve (GMRES with reused factors, the multigrid solvers) may stop,
       * if larger than the parameter "Tolerance" (inexact Newton); a direct
       * solve is exact regardless.
       * @return Number of iterations (1 for a direct solve, the GMRES
       * iterations for a solve with reused factors, the Krylov iterations
       * of the multigrid solvers).
       */
      unsigned int
      solve(const dealii::TrilinosWrappers::SparseMatrix &A,
            dealii::TrilinosWrappers::MPI::Vector        &x,
            const dealii::TrilinosWrappers::MPI::Vector  &b,
            const double relative_tolerance = 0.);

    private:
      struct DirectSolverData;
      const LinearSolverParameters      parameters;
      std::unique_ptr<DirectSolverData> direct;
      Statistics                        stats;
      /** Near null space, mode after mode (ML's column-major layout). */
      std::vector<double> null_space;
      unsigned int        n_null_space_modes = 0;
      unsigned int        n_components       = 1;

      /** Solve with 'cg amg' or 'gmres amg'. */
      unsigned int
      solve_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
                dealii::TrilinosWrappers::MPI::Vector        &x,
                const dealii::TrilinosWrappers::MPI::Vector  &b,
                const double relative_tolerance) const;
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
