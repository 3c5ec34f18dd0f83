#include <common/solvers/linear_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace Common
{
  namespace Solvers
  {
    using namespace dealii;

    void
    LinearSolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        prm.declare_entry("Solver type",
                          "mumps",
                          Patterns::Selection(
                            "umfpack|mumps|klu|cg amg|gmres amg"),
                          "Linear solver: 'umfpack' (sparse direct, one MPI "
                          "rank only), 'mumps' (parallel sparse direct), "
                          "'klu' (sparse direct, gathered on one rank), "
                          "'cg amg' (conjugate gradients with smoothed-"
                          "aggregation algebraic multigrid on the rigid-body "
                          "modes; symmetric systems only, i.e. without "
                          "friction or with a friction coefficient of 0) or "
                          "'gmres amg' (GMRES with the same "
                          "multigrid; also with friction). The multigrid "
                          "solvers are for 3D cases beyond a direct "
                          "solver's memory or time.");
        prm.declare_entry("Tolerance",
                          "1e-12",
                          Patterns::Double(0.),
                          "Relative residual tolerance of 'cg amg', "
                          "'gmres amg' and of GMRES with reused factors. "
                          "Dimensionless.");
        prm.declare_entry("Maximum iterations",
                          "10000",
                          Patterns::Integer(1),
                          "Iteration limit of 'cg amg' and 'gmres amg', and "
                          "upper bound of the GMRES iterations with reused "
                          "factors.");
        prm.declare_entry(
          "Reuse factorisation",
          "false",
          Patterns::Bool(),
          "'mumps' and 'klu': solve the systems of later Newton iterations "
          "by GMRES preconditioned with the factors of an earlier matrix, "
          "to the relative residual 'Tolerance', and factorise anew only "
          "when that would take longer than a factorisation. Pays off in "
          "3D, where one factorisation costs tens of solves.");
      }
      prm.leave_subsection();
    }



    void
    LinearSolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        const std::string name = prm.get("Solver type");
        type                = (name == "umfpack" ? LinearSolverType::umfpack :
                               name == "mumps"   ? LinearSolverType::mumps :
                               name == "klu"     ? LinearSolverType::klu :
                               name == "cg amg"  ? LinearSolverType::cg_amg :
                                                   LinearSolverType::gmres_amg);
        tolerance           = prm.get_double("Tolerance");
        max_iterations      = prm.get_integer("Maximum iterations");
        reuse_factorisation = prm.get_bool("Reuse factorisation");
      }
      prm.leave_subsection();
    }



    namespace
    {
      /** For its lifetime, what is written to std::cerr is dropped:
       * Amesos_Mumps prints a banner of several lines (INFOG(1), INFOG(2))
       * there on every failed phase, which the solver reports in one
       * line instead (ExcFactorisationFailed). */
      class DroppedErrorStream
      {
      public:
        DroppedErrorStream()
          : kept(std::cerr.rdbuf(sink.rdbuf()))
        {}

        ~DroppedErrorStream()
        {
          std::cerr.rdbuf(kept);
        }

        DroppedErrorStream(const DroppedErrorStream &) = delete;
        DroppedErrorStream &
        operator=(const DroppedErrorStream &) = delete;

      private:
        std::ostringstream sink;
        std::streambuf    *kept;
      };



      /** MUMPS' default margin of its workspace over the analysis'
       * estimate, ICNTL(14), in percent. */
      constexpr int mumps_default_workspace_margin = 20;

      /** INFOG(1) of a MUMPS solver after its last phase, the smallest
       * over the ranks of @p comm (errors are negative); 0 for any other
       * direct solver (whose status says nothing more than "failed"). */
      int
      mumps_status(Amesos_BaseSolver &solver, const Epetra_Comm &comm)
      {
        auto *mumps  = dynamic_cast<Amesos_Mumps *>(&solver);
        int   local  = mumps != nullptr ? mumps->GetINFOG()[0] : 0;
        int   global = local;
        comm.MinAll(&local, &global, 1);
        return global;
      }

      /** Whether a direct solver phase that returned @p code failed on any
       * rank of @p comm. */
      bool
      failed_on_any_rank(const int code, const Epetra_Comm &comm)
      {
        int local = code != 0 ? 1 : 0, global = local;
        comm.MaxAll(&local, &global, 1);
        return global != 0;
      }

      /** MUMPS errors that a larger workspace margin cures: -8, -9 (work
       * arrays), -14, -15 (integer arrays) and -17, -20 (communication
       * buffers). */
      bool
      mumps_needs_workspace(const int status)
      {
        return status == -8 || status == -9 || status == -14 || status == -15 ||
               status == -17 || status == -20;
      }

      /** One line on why a factorisation failed. */
      std::string
      describe_factorisation_failure(const int              status,
                                     const LinearSolverType type)
      {
        if (type != LinearSolverType::mumps)
          return "the matrix is singular to working precision";
        std::ostringstream text;
        text << "MUMPS INFOG(1) = " << status;
        if (status == -10)
          text << ", the matrix is numerically singular";
        else if (status == -13)
          text << ", memory allocation failed";
        else if (mumps_needs_workspace(status))
          text << ", workspace too small even after a new analysis with "
               << 2 * mumps_default_workspace_margin << " % margin";
        return text.str();
      }
    } // namespace



    struct LinearSolver::DirectSolverData
    {
      const Epetra_CrsMatrix               *matrix = nullptr;
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    solver;
      /** Numeric factors exist (of an earlier matrix, with reuse). */
      bool factorised = false;
      /** Wall time of the last factorisation and of one solve with its
       * factors (s). */
      double factorisation_time = 0.;
      double solve_time         = 0.;

      /** x = (factored matrix)^-1 b. */
      void
      apply(TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &b) const
      {
        problem->SetLHS(&x.trilinos_vector());
        problem->SetRHS(const_cast<Epetra_MultiVector *>(
          static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
        AssertThrow(solver->Solve() == 0,
                    ExcMessage("The direct solver failed."));
      }
    };



    namespace
    {
      /** The factors of an earlier matrix as a preconditioner. */
      class FactorPreconditioner
      {
      public:
        explicit FactorPreconditioner(
          const std::function<void(TrilinosWrappers::MPI::Vector &,
                                   const TrilinosWrappers::MPI::Vector &)>
            &apply)
          : apply(apply)
        {}

        void
        vmult(TrilinosWrappers::MPI::Vector       &x,
              const TrilinosWrappers::MPI::Vector &b) const
        {
          apply(x, b);
        }

      private:
        std::function<void(TrilinosWrappers::MPI::Vector &,
                           const TrilinosWrappers::MPI::Vector &)>
          apply;
      };

      /** GMRES control that gives up as soon as the mean reduction per
       * iteration so far cannot reach the tolerance within the limit. */
      class StallControl : public SolverControl
      {
      public:
        using SolverControl::SolverControl;

        State
        check(const unsigned int step, const double value) override
        {
          const State state = SolverControl::check(step, value);
          if (state != iterate || step < 3)
            return state;
          const double rate = std::pow(value / initial_value(), 1. / step);
          if (rate >= 1. ||
              step + std::log(tolerance() / value) / std::log(rate) >
                max_steps())
            {
              lcheck = failure;
              return failure;
            }
          return state;
        }
      };



      double
      seconds_since(const std::chrono::steady_clock::time_point start)
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      }



      /** UMFPACK on one rank, on a copy in deal.II's sparse format. */
      unsigned int
      solve_umfpack(const TrilinosWrappers::SparseMatrix &A,
                    TrilinosWrappers::MPI::Vector        &x,
                    const TrilinosWrappers::MPI::Vector  &b)
      {
        AssertThrow(dealii::Utilities::MPI::n_mpi_processes(
                      A.get_mpi_communicator()) == 1,
                    ExcMessage("Linear solver 'umfpack' runs on one MPI "
                               "rank only; use 'mumps' in parallel."));
        // Copy into deal.II's own sparse format, which UMFPACK reads.
        const auto &epetra         = A.trilinos_matrix();
        const auto  for_each_entry = [&epetra](const auto &f) {
          for (int row = 0; row < epetra.NumMyRows(); ++row)
            {
              int     n_entries;
              double *values;
              int    *columns;
              epetra.ExtractMyRowView(row, n_entries, values, columns);
              for (int k = 0; k < n_entries; ++k)
                f(epetra.GRID(row), epetra.GCID(columns[k]), values[k]);
            }
        };
        DynamicSparsityPattern dsp(A.m(), A.n());
        for_each_entry(
          [&dsp](const int i, const int j, const double) { dsp.add(i, j); });
        SparsityPattern pattern;
        pattern.copy_from(dsp);
        SparseMatrix<double> matrix(pattern);
        for_each_entry([&matrix](const int i, const int j, const double value) {
          matrix.set(i, j, value);
        });
        SparseDirectUMFPACK umfpack;
        umfpack.initialize(matrix);
        Vector<double> rhs(b.size()), x_serial(b.size());
        for (const auto i : b.locally_owned_elements())
          rhs(i) = b(i);
        umfpack.vmult(x_serial, rhs);
        for (const auto i : x.locally_owned_elements())
          x(i) = x_serial(i);
        x.compress(VectorOperation::insert);
        return 1;
      }
    } // namespace



    LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
      : parameters(parameters)
    {}



    LinearSolver::~LinearSolver()
    {
      // Releasing parallel factors (MUMPS) is a collective call. While an
      // exception thrown on this rank alone unwinds the stack, the other
      // ranks are elsewhere and the release would wait for them forever;
      // the run ends with MPI_Abort in that case, so the factors are left
      // to it.
      if (std::uncaught_exceptions() > 0 && direct &&
          direct->matrix != nullptr && direct->matrix->Comm().NumProc() > 1)
        {
          (void)direct->solver.release();
          (void)direct->problem.release();
        }
    }



    void
    LinearSolver::reset()
    {
      direct.reset();
    }



    unsigned int
    LinearSolver::solve(const TrilinosWrappers::SparseMatrix &A,
                        TrilinosWrappers::MPI::Vector        &x,
                        const TrilinosWrappers::MPI::Vector  &b,
                        const double relative_tolerance)
    {
      const double tolerance =
        std::max(parameters.tolerance, relative_tolerance);
      if (parameters.type == LinearSolverType::umfpack)
        return solve_umfpack(A, x, b);
      if (parameters.type == LinearSolverType::cg_amg ||
          parameters.type == LinearSolverType::gmres_amg)
        return solve_amg(A, x, b, tolerance);

      // Amesos keeps the symbolic factorisation of the matrix object; a
      // new object (or reset()) starts over.
      if (!direct || direct->matrix != &A.trilinos_matrix())
        {
          direct          = std::make_unique<DirectSolverData>();
          direct->matrix  = &A.trilinos_matrix();
          direct->problem = std::make_unique<Epetra_LinearProblem>();
          direct->problem->SetOperator(
            const_cast<Epetra_CrsMatrix *>(direct->matrix));
          Amesos factory;
          direct->solver.reset(
            factory.Create(parameters.type == LinearSolverType::mumps ?
                             "Amesos_Mumps" :
                             "Amesos_Klu",
                           *direct->problem));
          AssertThrow(direct->solver != nullptr,
                      ExcMessage("The requested direct solver is not "
                                 "available in this Trilinos."));
          const DroppedErrorStream quiet;
          AssertThrow(direct->solver->SymbolicFactorization() == 0,
                      ExcMessage("Symbolic factorisation failed."));
        }

      if (parameters.reuse_factorisation && direct->factorised)
        {
          // As many solves with the old factors as half a factorisation
          // costs, at least 3.
          // capped by "Maximum iterations".
          const unsigned int limit =
            std::min(parameters.max_iterations,
                     static_cast<unsigned int>(
                       std::clamp(0.5 * direct->factorisation_time /
                                    std::max(direct->solve_time, 1e-9),
                                  3.,
                                  200.)));
          StallControl control(limit, tolerance * b.l2_norm());
          control.log_history(false);
          control.log_result(false);
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData data;
          data.max_n_tmp_vectors     = limit + 2;
          data.right_preconditioning = true;
          SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(control, data);
          const FactorPreconditioner                 preconditioner(
            [this](TrilinosWrappers::MPI::Vector       &y,
                   const TrilinosWrappers::MPI::Vector &r) {
              direct->apply(y, r);
            });
          TrilinosWrappers::MPI::Vector x_trial(x);
          x_trial = 0.;
          try
            {
              gmres.solve(A, x_trial, b, preconditioner);
              x = x_trial;
              ++stats.n_reuse_solves;
              stats.n_reuse_iterations += control.last_step();
              return control.last_step();
            }
          catch (const SolverControl::NoConvergence &)
            {
              // Refactorise below.
              ++stats.n_failed_reuse;
              stats.n_reuse_iterations += control.last_step();
            }
        }

      auto                     start = std::chrono::steady_clock::now();
      const Epetra_Comm       &comm  = direct->matrix->Comm();
      const DroppedErrorStream quiet;
      if (failed_on_any_rank(direct->solver->NumericFactorization(), comm))
        {
          // MUMPS sizes its workspace in the analysis of the first matrix of
          // a pattern; pivoting on a later one may need more. Analyse the
          // matrix at hand, with twice the workspace margin, once.
          int  status = mumps_status(*direct->solver, comm);
          bool cured  = false;
          if (mumps_needs_workspace(status))
            {
              dynamic_cast<Amesos_Mumps &>(*direct->solver)
                .SetICNTL(14, 2 * mumps_default_workspace_margin);
              cured =
                !failed_on_any_rank(direct->solver->SymbolicFactorization(),
                                    comm) &&
                !failed_on_any_rank(direct->solver->NumericFactorization(),
                                    comm);
              if (!cured)
                status = mumps_status(*direct->solver, comm);
            }
          if (!cured)
            {
              direct.reset();
              AssertThrow(false,
                          ExcFactorisationFailed(
                            describe_factorisation_failure(status,
                                                           parameters.type)));
            }
        }
      direct->factorised         = true;
      direct->factorisation_time = seconds_since(start);
      ++stats.n_factorisations;
      stats.factorisation_time += direct->factorisation_time;
      start = std::chrono::steady_clock::now();
      direct->apply(x, b);
      direct->solve_time = seconds_since(start);
      return 1;
    }



    const LinearSolver::Statistics &
    LinearSolver::statistics() const
    {
      return stats;
    }



    bool
    LinearSolver::uses_multigrid() const
    {
      return parameters.type == LinearSolverType::cg_amg ||
             parameters.type == LinearSolverType::gmres_amg;
    }



    void
    LinearSolver::set_near_null_space(
      const std::vector<std::vector<double>> &modes,
      const unsigned int                      n_components)
    {
      n_null_space_modes = modes.size();
      this->n_components = n_components;
      null_space.clear();
      for (const auto &mode : modes)
        null_space.insert(null_space.end(), mode.begin(), mode.end());
    }



    unsigned int
    LinearSolver::solve_amg(const TrilinosWrappers::SparseMatrix &A,
                            TrilinosWrappers::MPI::Vector        &x,
                            const TrilinosWrappers::MPI::Vector  &b,
                            const double tolerance) const
    {
      const auto n_rows =
        static_cast<std::size_t>(A.trilinos_matrix().NumMyRows());
      AssertThrow(n_null_space_modes == 0 ||
                    null_space.size() == n_null_space_modes * n_rows,
                  ExcMessage("The near null space does not match the "
                             "locally owned rows of the matrix."));

      // Smoothed aggregation as deal.II's PreconditionAMG sets it up for
      // elliptic problems with higher-order elements, plus the near null
      // space.
      Teuchos::ParameterList list;
      ML_Epetra::SetDefaults("SA", list);
      list.set("aggregation: type", "Uncoupled");
      list.set("aggregation: threshold", 1e-4);
      list.set("smoother: type", "Chebyshev");
      list.set("smoother: sweeps", 2);
      list.set("smoother: Chebyshev alpha", 10.);
      list.set("smoother: ifpack overlap", 0);
      list.set("coarse: max size", 2000);
      list.set("coarse: type", "Amesos-KLU");
      list.set("ML output", 0);
      list.set("PDE equations", static_cast<int>(n_components));
      // The Chebyshev smoother needs the largest eigenvalue of D^-1 A; ML
      // estimates it by conjugate gradients, which fail on the
      // non-symmetric matrices of friction, so GMRES takes the power
      // method.
      if (parameters.type == LinearSolverType::gmres_amg)
        list.set("eigen-analysis: type", "power-method");
      std::vector<double> modes = null_space;
      if (n_null_space_modes > 0)
        {
          list.set("null space: type", "pre-computed");
          list.set("null space: dimension",
                   static_cast<int>(n_null_space_modes));
          list.set("null space: vectors", modes.data());
        }
      TrilinosWrappers::PreconditionAMG amg;
      amg.initialize(A, list);

      SolverControl control(parameters.max_iterations, tolerance * b.l2_norm());
      control.log_history(false);
      control.log_result(false);
      try
        {
          if (parameters.type == LinearSolverType::cg_amg)
            {
              SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
              cg.solve(A, x, b, amg);
            }
          else
            {
              SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData data;
              data.max_n_tmp_vectors     = 102;
              data.right_preconditioning = true;
              SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(control, data);
              gmres.solve(A, x, b, amg);
            }
        }
      catch (const SolverControl::NoConvergence &e)
        {
          std::ostringstream message;
          message << std::scientific << std::setprecision(2)
                  << "The iterative linear solver did not reach the relative "
                  << "residual " << tolerance << " in " << e.last_step
                  << " iterations (reached "
                  << e.last_residual / std::max(b.l2_norm(), 1e-300)
                  << "); raise 'Maximum iterations' or choose a direct "
                  << "solver.";
          AssertThrow(false, ExcMessage(message.str()));
        }
      return control.last_step();
    }



    unsigned int
    solve_linear_system(const LinearSolverParameters         &parameters,
                        const TrilinosWrappers::SparseMatrix &A,
                        TrilinosWrappers::MPI::Vector        &x,
                        const TrilinosWrappers::MPI::Vector  &b)
    {
      LinearSolver solver(parameters);
      return solver.solve(A, x, b);
    }
  } // namespace Solvers
} // namespace Common
