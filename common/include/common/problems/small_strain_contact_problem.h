/**
 * @file small_strain_contact_problem.h
 * A small-strain elastic problem with one mortar contact pair, solved by
 * the semismooth Newton method: contact set-up, the sparsity pattern that
 * serves every active set, one Newton iteration (constraints, assembly,
 * solve), the residuals with pressure recovery, and commit/restore for load
 * stepping. Wires physics/, contact/ and solvers/ together; owns no mesh,
 * boundary condition or load, which the application supplies.
 */
#ifndef common_problems_small_strain_contact_problem_h
#define common_problems_small_strain_contact_problem_h

#include <common/contact/contact_enforcement.h>
#include <common/contact/contact_parameters.h>
#include <common/contact/contact_search.h>
#include <common/contact/contact_surface.h>
#include <common/contact/mortar_coupling.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/solvers/linear_solver.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <map>
#include <memory>

namespace Common
{
  namespace Problems
  {
    /**
     * @brief External load of a problem, scaled by the load factor.
     */
    struct ExternalLoad
    {
      /** Add \f$f_{ext}\f$ at @p load_factor to the vector, distributed
       * through the given constraints; not compressed (N). */
      std::function<void(const double                             load_factor,
                         const dealii::AffineConstraints<double> &constraints,
                         dealii::TrilinosWrappers::MPI::Vector   &vector)>
        add;
      /** Size of the load at @p load_factor, the scale of the relative
       * residuals (N). */
      std::function<double(const double load_factor)> magnitude;
      /** Optional: prescribed displacements at @p load_factor (mm), for
       * DoFs that carry a (homogeneous) Dirichlet constraint in the
       * constraints given to setup(); the first Newton iteration of a
       * load step moves them there. */
      std::function<
        void(const double                                       load_factor,
             std::map<dealii::types::global_dof_index, double> &values)>
        prescribed_displacements;
    };

    /**
     * @brief Wall time per phase of the contact solve (s).
     */
    struct ContactSolveTimes
    {
      double contact_setup     = 0.;
      double newton            = 0.;
      double assembly          = 0.;
      double linear_solve      = 0.;
      double residual          = 0.;
      double active_set_update = 0.;
    };

    /**
     * @brief Small-strain elasticity with one mortar contact pair.
     */
    template <int dim>
    class SmallStrainContactProblem
    {
    public:
      /**
       * @param[in] dof_handler DoFs of the displacement (distributed).
       * @param[in] mapping Geometry mapping of the contact surfaces.
       * @param[in] physics Bulk terms.
       * @param[in] contact Contact pair and enforcement.
       * @param[in] reference_modulus Scales the complementarity constant
       * (MPa), usually the secondary body's Young's modulus.
       * All references must outlive this object.
       */
      SmallStrainContactProblem(
        const dealii::DoFHandler<dim>            &dof_handler,
        const dealii::Mapping<dim>               &mapping,
        Physics::SmallStrainElasticity<dim>      &physics,
        const Contact::ContactParameters         &contact,
        const Solvers::LinearSolverParameters    &linear_solver,
        const Solvers::NonlinearSolverParameters &nonlinear_solver,
        const double                              reference_modulus,
        const MPI_Comm                            mpi_communicator);

      /**
       * @brief Build the contact surfaces, the mortar coupling (reference
       * configuration), the initial active set, the sparsity pattern and
       * the vectors.
       * @param[in] constraints Hanging-node and homogeneous Dirichlet
       * constraints (they act on Newton increments), closed.
       */
      void
      setup(const dealii::AffineConstraints<double> &constraints);

      /**
       * @brief Solve at @p load_factor from the current state by the
       * semismooth Newton method.
       * @param[in] verbose Stream for the residual history.
       */
      Solvers::NewtonStatistics
      solve(const double                load_factor,
            const ExternalLoad         &load,
            dealii::ConditionalOStream &verbose);

      /** @brief Keep the current state as the last accepted one. */
      void
      commit();

      /** @brief Return to the last accepted state. */
      void
      restore();

      /**
       * @brief Time one assembly (cell matrices included) and one solve
       * with the current active set held fixed, the least any contact
       * solver must pay; the state is left unchanged (s).
       */
      double
      time_fixed_active_set_solve(const double        load_factor,
                                  const ExternalLoad &load);

      /** @brief Displacement (mm), every entry readable. */
      const dealii::TrilinosWrappers::MPI::Vector &
      displacement() const;

      /** @brief Condensed residual f_ext - f_int of the last evaluation
       * (N), every entry readable. */
      const dealii::TrilinosWrappers::MPI::Vector &
      bulk_residual() const;

      /** @brief The mortar operators. */
      const Contact::MortarCoupling<dim> &
      coupling() const;

      /** @brief The enforcement, with pressures and active set. */
      const Contact::ContactEnforcement<dim> &
      enforcement() const;

      /** @brief The secondary surface. */
      const Contact::ContactSurface<dim> &
      secondary_surface() const;

      /** @brief Wall time per phase so far. */
      const ContactSolveTimes &
      times() const;

    private:
      /** One Newton iteration; returns the relative norm of the update. */
      double
      assemble_and_solve(const double load_factor, const ExternalLoad &load);

      Solvers::NewtonResidual
      evaluate_residual(const double load_factor, const ExternalLoad &load);

      /** f_ext - f_int at the current state, condensed with the Dirichlet
       * and hanging-node constraints (N): stored, ghosted, in
       * residual_vector and returned as a compressed owned vector. */
      dealii::TrilinosWrappers::MPI::Vector
      compute_bulk_residual(const double load_factor, const ExternalLoad &load);

      const dealii::DoFHandler<dim>           &dof_handler;
      const dealii::Mapping<dim>              &mapping;
      Physics::SmallStrainElasticity<dim>     &physics;
      const Contact::ContactParameters         contact_parameters;
      const Solvers::NonlinearSolverParameters nonlinear_solver_parameters;
      const double                             reference_modulus;
      const MPI_Comm                           mpi_communicator;

      dealii::IndexSet locally_owned_dofs;
      dealii::IndexSet locally_relevant_dofs;

      std::unique_ptr<Contact::ContactSurface<dim>>     primary;
      std::unique_ptr<Contact::ContactSurface<dim>>     secondary;
      std::unique_ptr<Contact::ContactSearch<dim>>      search;
      Contact::MortarCoupling<dim>                      mortar;
      std::unique_ptr<Contact::ContactEnforcement<dim>> contact_enforcement;

      dealii::AffineConstraints<double> constraints_dirichlet_and_hanging_nodes;
      dealii::AffineConstraints<double> constraints;
      dealii::TrilinosWrappers::SparseMatrix system_matrix;
      /** Bulk tangent condensed with the Dirichlet and hanging-node
       * constraints only (friction needs the stiffness rows of slipping
       * nodes); constant in small-strain elasticity. */
      dealii::TrilinosWrappers::SparseMatrix bulk_matrix;
      dealii::TrilinosWrappers::MPI::Vector  solution;
      dealii::TrilinosWrappers::MPI::Vector  solution_owned;
      dealii::TrilinosWrappers::MPI::Vector  accepted_solution;
      dealii::TrilinosWrappers::MPI::Vector  newton_update;
      dealii::TrilinosWrappers::MPI::Vector  system_rhs;
      dealii::TrilinosWrappers::MPI::Vector  residual_vector;
      // Declared after the matrix: Amesos refers to it when destroyed.
      Solvers::LinearSolver linear_solver;

      ContactSolveTimes solve_times;
    };
  } // namespace Problems
} // namespace Common

#endif
