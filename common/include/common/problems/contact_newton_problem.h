/**
 * @file contact_newton_problem.h
 * One contact-Newton problem for every scene: a solid operator (any
 * kinematics and material) and one contact pair (any contact geometry,
 * normal enforcement and friction law), solved by the semismooth Newton
 * method at the states of a load program. Owns the constraints, the
 * sparsity pattern, the linear system and the Newton callbacks, and
 * commits or restores the state of the solid and of the contact together.
 * Knows no mesh, boundary condition or load, which the application
 * supplies.
 */
#ifndef common_problems_contact_newton_problem_h
#define common_problems_contact_newton_problem_h

#include <common/contact/contact_enforcement.h>
#include <common/contact/contact_geometry.h>
#include <common/contact/contact_parameters.h>
#include <common/contact/mortar_coupling.h>
#include <common/physics/solid_operator.h>
#include <common/solvers/linear_solver.h>
#include <common/solvers/load_program.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace Common
{
  namespace Problems
  {
    /**
     * @brief External load of a problem at a state of the load program.
     */
    struct ExternalLoad
    {
      /** Add \f$f_{ext}\f$ at @p state to the vector, distributed through
       * the given constraints; not compressed (N). */
      std::function<void(const Solvers::LoadState                &state,
                         const dealii::AffineConstraints<double> &constraints,
                         dealii::TrilinosWrappers::MPI::Vector   &vector)>
        add;
      /** Size of the load at @p state, the scale of the relative
       * residuals (N). */
      std::function<double(const Solvers::LoadState &state)> magnitude;
      /** Optional: prescribed displacements at @p state (mm), for DoFs
       * that carry a (homogeneous) Dirichlet constraint in the constraints
       * given to setup(); the first Newton iteration of a step moves them
       * there. */
      std::function<
        void(const Solvers::LoadState                          &state,
             std::map<dealii::types::global_dof_index, double> &values)>
        prescribed_displacements;
    };

    /**
     * @brief Time per phase of the contact solve (s): wall time, and the
     * processor time of the Newton solves.
     */
    struct ContactSolveTimes
    {
      double contact_setup     = 0.;
      double newton            = 0.;
      double assembly          = 0.;
      double linear_solve      = 0.;
      double residual          = 0.;
      double active_set_update = 0.;
      /** Pairing and integrating the rows again in the current
       * configuration (within the Newton solves). */
      double geometry_update = 0.;
      /** Processor time of contact set-up and Newton solves. */
      double contact_cpu = 0.;
    };

    /**
     * @brief The DoFs one rank stores in its ghosted vectors and
     * constraints: owned ones plus ghosts.
     */
    struct StoredDoFs
    {
      /** DoFs the rank owns. */
      dealii::types::global_dof_index n_owned = 0;
      /** Ghosts on the rank's own cells (the partition interface). */
      dealii::types::global_dof_index n_partition_ghosts = 0;
      /** Further ghosts: DoFs of the contact rows the rank holds (its own
       * secondary nodes and those its cells need, with their primary
       * nodes) and the DoFs their constraints refer to (the contact
       * interface). */
      dealii::types::global_dof_index n_contact_ghosts = 0;
    };



    /**
     * @brief A solid with one contact pair, solved by the semismooth
     * Newton method.
     */
    template <int dim>
    class ContactNewtonProblem
    {
    public:
      /**
       * @param[in] dof_handler DoFs of the displacement (distributed).
       * @param[in] mapping Geometry mapping (rigid-body modes for
       * multigrid).
       * @param[in] solid Bulk terms.
       * @param[in] geometry Geometry of the contact pair.
       * @param[in] contact Enforcement and friction parameters.
       * @param[in] reference_modulus Scales the complementarity constant
       * (MPa), usually the secondary body's Young's modulus.
       * All references must outlive this object.
       */
      ContactNewtonProblem(
        const dealii::DoFHandler<dim>            &dof_handler,
        const dealii::Mapping<dim>               &mapping,
        Physics::SolidOperator<dim>              &solid,
        Contact::ContactGeometry<dim>            &geometry,
        const Contact::ContactParameters         &contact,
        const Solvers::LinearSolverParameters    &linear_solver,
        const Solvers::NonlinearSolverParameters &nonlinear_solver,
        const double                              reference_modulus,
        const MPI_Comm                            mpi_communicator);

      /**
       * @brief Build the contact geometry, the initial active set, the
       * sparsity pattern that serves every active set, and the vectors.
       * @param[in] constraints Hanging-node and homogeneous Dirichlet
       * constraints (they act on Newton increments), closed; at least the
       * lines of the locally relevant DoFs and of the contact pair's DoFs.
       * Must outlive this object (a changed contact pattern reads them
       * again).
       */
      void
      setup(const dealii::AffineConstraints<double> &constraints);

      /**
       * @brief Solve at @p state from the current state by the semismooth
       * Newton method.
       * @param[in] verbose Stream for the residual history.
       */
      Solvers::NewtonStatistics
      solve(const Solvers::LoadState   &state,
            const ExternalLoad         &load,
            dealii::ConditionalOStream &verbose);

      /** @brief Keep the current state (displacement, material state,
       * contact state and friction history) as the last accepted one. */
      void
      commit();

      /** @brief Return to the last accepted state. */
      void
      restore();

      /**
       * @brief Support the DoFs @p dofs where they are now, from the next
       * solve on: homogeneous Dirichlet constraints on their Newton
       * increments join those given to setup(), so their displacement keeps
       * its current value. This is a support that a stage of a load program
       * adds, e.g. to hold a body that the tools release. The sparsity
       * pattern is kept. No DoF may belong to a node of the secondary
       * surface, whose contact constraints would conflict (throws). Every
       * rank passes the same list.
       */
      void
      hold_dofs(const std::vector<dealii::types::global_dof_index> &dofs);

      /**
       * @brief Stop supporting the DoFs @p dofs that hold_dofs() holds,
       * from the next solve on: a stage of a load program that frees a
       * support (the displacement keeps its current value as the start of
       * the next step, and the support's reaction is released within that
       * step). DoFs not held are ignored. Every rank passes the same list.
       */
      void
      release_dofs(const std::vector<dealii::types::global_dof_index> &dofs);

      /**
       * @brief Processor time of one assembly (cell matrices included) and
       * one solve with the current active set held fixed, the least any
       * contact solver must pay: the median of @p n_repeats measurements.
       * The state is left unchanged (s).
       */
      double
      time_fixed_active_set_solve(const Solvers::LoadState &state,
                                  const ExternalLoad       &load,
                                  const unsigned int        n_repeats = 3);

      /**
       * @brief Reaction force on each boundary of @p boundary_ids at the
       * current state: the sum over the boundary's DoFs of the internal
       * forces minus the external load at @p state, per component (N;
       * per mm of thickness in plane strain, the full ring when
       * axisymmetric). Collective; the result is the same on every rank.
       */
      std::vector<dealii::Tensor<1, dim>>
      reaction_forces(
        const std::vector<dealii::types::boundary_id> &boundary_ids,
        const Solvers::LoadState                      &state,
        const ExternalLoad                            &load);

      /**
       * @brief Reaction force at the DoFs @p dofs at the current state: the
       * sum of their internal forces minus the external load at @p state
       * (N; per mm of thickness in plane strain). For supports at single
       * nodes, such as those of hold_dofs(). Collective; the result is the
       * same on every rank.
       */
      double
      reaction_force(const std::vector<dealii::types::global_dof_index> &dofs,
                     const Solvers::LoadState                           &state,
                     const ExternalLoad                                 &load);

      /**
       * @brief Internal forces minus the external load at @p state at every
       * owned DoF, without constraints (N; per mm of thickness in plane
       * strain): at a support, its reaction on the body. Collective.
       */
      dealii::TrilinosWrappers::MPI::Vector
      nodal_reactions(const Solvers::LoadState &state,
                      const ExternalLoad       &load);

      /** @brief Displacement (mm): readable at the DoFs of the rank's own
       * cells and of the contact pair. */
      const dealii::TrilinosWrappers::MPI::Vector &
      displacement() const;

      /** @brief Condensed residual f_ext - f_int of the last evaluation
       * (N), readable where displacement() is. */
      const dealii::TrilinosWrappers::MPI::Vector &
      bulk_residual() const;

      /** @brief The mortar operators. */
      const Contact::MortarCoupling<dim> &
      coupling() const;

      /** @brief The contact geometry. */
      const Contact::ContactGeometry<dim> &
      contact_geometry() const;

      /** @brief The enforcement, with pressures and active set. */
      const Contact::ContactEnforcement<dim> &
      enforcement() const;

      /** @brief The secondary surface. */
      const Contact::ContactSurface<dim> &
      secondary_surface() const;

      /** @brief The solid operator. */
      const Physics::SolidOperator<dim> &
      solid() const;

      /** @brief The DoFs this rank stores, by kind. */
      const StoredDoFs &
      stored_dofs() const;

      /** @brief Time per phase so far. */
      const ContactSolveTimes &
      times() const;

      /** @brief The linear solver's factorisations and reused-factor
       * solves so far. */
      const Solvers::LinearSolver::Statistics &
      linear_solver_statistics() const;

    private:
      /** True if the problem is nonlinear: a nonlinear solid, or contact
       * in the current configuration. */
      bool
      is_nonlinear() const;

      /** The springs of stabilized solves: their stiffness, once. */
      void
      setup_stabilization();

      /** Add the springs' forces -k (u - anchor) at @p u to @p r (owned,
       * compressed), except at DoFs @p constraints fix. */
      void
      add_stabilization_forces(
        const dealii::TrilinosWrappers::MPI::Vector &u,
        const dealii::AffineConstraints<double>     &constraints,
        dealii::TrilinosWrappers::MPI::Vector       &r) const;

      /** The DoFs this rank stores (owned, partition ghosts, the DoFs of
       * the contact rows it holds and the targets of their constraints),
       * the Dirichlet and hanging-node constraints of those DoFs out of
       * @p base_constraints, and the ghosted vectors. */
      void
      setup_stored_dofs(
        const dealii::AffineConstraints<double> &base_constraints);

      /** Current configuration: bring the contact geometry to the current
       * displacement, rebuild the pattern if the coupling grew, and
       * measure the friction history with the new rows. Nothing in the
       * reference configuration. */
      void
      update_geometry();

      /** Current configuration with Lagrange multipliers: add the
       * geometric stiffness of contact at the nodal tractions of the last
       * residual evaluation (ContactGeometry::contact_force_derivative())
       * to the system, and its part of the trial corrections
       * (add_trial_corrections()). */
      void
      add_geometric_contact_stiffness();

      /** The full derivatives of the weighted gaps of the closed rows this
       * rank holds (ContactGeometry::weighted_gap_derivative()) into
       * @p derivatives; false where the fixed rows' gradient is exact (the
       * reference configuration). Owned rows only if @p owned_only. */
      bool
      closed_gap_derivatives(
        const bool                                                owned_only,
        typename Contact::NormalEnforcement<dim>::GapDerivatives &derivatives)
        const;

      /**
       * Lagrange multipliers, where the geometry linearises its rows
       * (ContactGeometry::linearises_rows()): the constraints of the
       * closed nodes come from the fixed rows' gradient B, so that
       * the condensed system tests equilibrium with the contact forces as
       * they are distributed, while the increment must satisfy the full
       * linearisation G of the gaps (trial_corrections, G less B). With P_B
       * and P_G the maps of the two constraint sets, the Newton system is
       * P_B^T A P_G: add P_B^T A (P_G - P_B) to the matrix and the
       * inhomogeneities' share to the right-hand side. A is the bulk
       * tangent here; the geometric stiffness of contact and the friction
       * tangent take their share where they are assembled
       * (TrialCorrections::extend_columns()). The converged state is that
       * of the fixed rows' constraints: these terms change the iteration
       * only.
       */
      void
      add_trial_corrections();

      /** Move the increment of each corrected DoF from the fixed rows'
       * constraint to the full linearisation (trial_corrections). */
      void
      apply_trial_corrections();

      /** Add the block @p block (rows @p row_dofs, columns @p column_dofs)
       * of the tangent and the right-hand side @p rhs at its rows to the
       * system, distributed through the iteration's constraints (the
       * inhomogeneities of constrained columns move to the right-hand
       * side). */
      void
      distribute_block(
        const std::vector<dealii::types::global_dof_index> &row_dofs,
        const std::vector<dealii::types::global_dof_index> &column_dofs,
        const dealii::FullMatrix<double>                   &block,
        const dealii::Vector<double>                       &rhs);

      /** Build the sparsity pattern and the matrices for the current
       * coupling. */
      void
      setup_matrices();

      /** One Newton iteration, its linear system solved to the relative
       * residual @p linear_tolerance (0: the linear solver's own); returns
       * the relative norm of the update. */
      double
      assemble_and_solve(const Solvers::LoadState &state,
                         const ExternalLoad       &load,
                         const double              linear_tolerance);

      Solvers::NewtonResidual
      evaluate_residual(const Solvers::LoadState &state,
                        const ExternalLoad       &load);

      /** True if the problem is nonlinear (a nonlinear solid or contact in
       * the current configuration) and enforced by Lagrange multipliers:
       * after each Newton update the linearised bulk residual
       * r(u_k) + r'(u_k) du is formed, and a closed node opens only if the
       * multiplier of that linearised step is tensile as well as the one
       * recovered from the residual at the new iterate
       * (ContactEnforcement::keep_linearized_compression()). For a linear
       * problem the two are the same. */
      bool
      uses_linearized_tractions() const;

      /** f_ext - f_int at the displacement @p u (ghosted), condensed as in
       * compute_bulk_residual(); a compressed owned vector. */
      dealii::TrilinosWrappers::MPI::Vector
      bulk_residual_at(const dealii::TrilinosWrappers::MPI::Vector &u,
                       const Solvers::LoadState                    &state,
                       const ExternalLoad                          &load);

      /** f_ext - f_int from the internal force @p internal_force at @p u
       * (assembled, not compressed; it is overwritten): the springs of a
       * stabilized solve included, condensed as in compute_bulk_residual();
       * a compressed owned vector. */
      dealii::TrilinosWrappers::MPI::Vector
      bulk_residual_from(dealii::TrilinosWrappers::MPI::Vector &internal_force,
                         const dealii::TrilinosWrappers::MPI::Vector &u,
                         const Solvers::LoadState                    &state,
                         const ExternalLoad                          &load);

      /** f_ext - f_int at the current state, condensed with the Dirichlet
       * and hanging-node constraints (N): stored, ghosted, in
       * residual_vector and returned as a compressed owned vector. */
      dealii::TrilinosWrappers::MPI::Vector
      compute_bulk_residual(const Solvers::LoadState &state,
                            const ExternalLoad       &load);

      /** The bulk tangent condensed with the Dirichlet and hanging-node
       * constraints only (friction needs the stiffness rows of slipping
       * nodes): assembled once for a linear solid, at every iteration
       * otherwise. */
      void
      assemble_bulk_matrix();

      /** The stabilization springs added to bulk_matrix, which is then
       * compressed and marked current if it stays so. */
      void
      finish_bulk_matrix();

      const dealii::DoFHandler<dim>           &dof_handler;
      const dealii::Mapping<dim>              &mapping;
      Physics::SolidOperator<dim>             &solid_operator;
      Contact::ContactGeometry<dim>           &geometry;
      const Contact::ContactParameters         contact_parameters;
      const Solvers::NonlinearSolverParameters nonlinear_solver_parameters;
      const double                             reference_modulus;
      const MPI_Comm                           mpi_communicator;

      dealii::IndexSet locally_owned_dofs;
      /** The DoFs of the rank's own cells. */
      dealii::IndexSet locally_active_dofs;
      /** With friction on several ranks, the cells around the rank's own
       * secondary nodes (Contact::cells_around_owned_nodes()), by active
       * cell index, and their DoFs; empty otherwise. */
      std::vector<bool> friction_cells;
      dealii::IndexSet  friction_cell_dofs;
      dealii::IndexSet  locally_relevant_dofs;

      const dealii::AffineConstraints<double> *base_constraints = nullptr;
      /** DoFs supported by hold_dofs(), in addition to base_constraints. */
      std::vector<dealii::types::global_dof_index> held_dofs;
      /** Stiffness of the stabilizing spring at each owned DoF (N/mm;
       * NonlinearSolverParameters::stabilization_factor), set up at the
       * first stabilized step; its anchor; and whether the springs act. */
      dealii::TrilinosWrappers::MPI::Vector stabilization_stiffness;
      dealii::TrilinosWrappers::MPI::Vector stabilization_anchor;
      bool                                  stabilized = false;
      /** Factor on the springs' stiffness: 1 at the first stabilized
       * solve of a step, halved after each. */
      double stabilization_scale = 1.;
      /** Smallest cell's smallest vertex distance (mm). */
      double                                            smallest_cell = 0.;
      std::unique_ptr<Contact::ContactEnforcement<dim>> contact_enforcement;

      dealii::AffineConstraints<double> constraints_dirichlet_and_hanging_nodes;
      dealii::AffineConstraints<double> constraints;
      /** The iteration's TrialCorrections of the closed nodes. */
      Contact::TrialCorrections              trial_corrections;
      dealii::TrilinosWrappers::SparseMatrix system_matrix;
      dealii::TrilinosWrappers::SparseMatrix bulk_matrix;
      bool                                   bulk_matrix_current = false;
      dealii::TrilinosWrappers::MPI::Vector  solution;
      dealii::TrilinosWrappers::MPI::Vector  solution_owned;
      dealii::TrilinosWrappers::MPI::Vector  accepted_solution;
      /** The accepted state before accepted_solution, for the
       * extrapolated initial guess. */
      dealii::TrilinosWrappers::MPI::Vector previous_accepted_solution;
      /** Pseudo-times of the two accepted states (NaN until accepted). */
      double accepted_time          = 0.;
      double previous_accepted_time = 0.;
      /** Pseudo-time of the last solve(), which commit() accepts. */
      double solved_time = 0.;
      /** accepted_solution, readable where solution is (current
       * configuration only). */
      dealii::TrilinosWrappers::MPI::Vector accepted_ghosted;
      dealii::TrilinosWrappers::MPI::Vector newton_update;
      dealii::TrilinosWrappers::MPI::Vector system_rhs;
      dealii::TrilinosWrappers::MPI::Vector residual_vector;
      /** The bulk residual of the linearised problem at the new iterate,
       * r(u) + r'(u) du, readable where residual_vector is
       * (uses_linearized_tractions()). */
      dealii::TrilinosWrappers::MPI::Vector linearized_residual;
      /** True from a Newton update until the residual of the new iterate
       * has used linearized_residual. */
      bool linearized_residual_current = false;
      // Declared after the matrix: Amesos refers to it when destroyed.
      Solvers::LinearSolver linear_solver;

      StoredDoFs        stored_dof_counts;
      ContactSolveTimes solve_times;
    };
  } // namespace Problems
} // namespace Common

#endif
