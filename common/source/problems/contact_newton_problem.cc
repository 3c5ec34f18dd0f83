#include <common/contact/contact_assembly.h>
#include <common/io/run_main.h>
#include <common/io/timer.h>
#include <common/physics/rigid_body.h>
#include <common/problems/contact_newton_problem.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace Common
{
  namespace Problems
  {
    using namespace dealii;

    namespace
    {
      /** @p dofs and the DoFs that the lines of @p constraints for them
       * refer to. */
      IndexSet
      with_constraint_targets(const IndexSet                  &dofs,
                              const AffineConstraints<double> &constraints)
      {
        std::vector<types::global_dof_index> targets;
        for (const auto &line : constraints.get_lines())
          if (dofs.is_element(line.index))
            for (const auto &entry : line.entries)
              targets.push_back(entry.first);
        std::sort(targets.begin(), targets.end());
        targets.erase(std::unique(targets.begin(), targets.end()),
                      targets.end());
        IndexSet result = dofs;
        result.add_indices(targets.begin(), targets.end());
        result.compress();
        return result;
      }



      /** The DoFs of the cells marked in @p marked (by active cell index;
       * may be empty). */
      template <int dim>
      IndexSet
      dofs_of_cells(const DoFHandler<dim>   &dof_handler,
                    const std::vector<bool> &marked)
      {
        IndexSet dofs(dof_handler.n_dofs());
        if (marked.empty())
          return dofs;
        std::vector<types::global_dof_index> cell_dofs(
          dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (marked[cell->active_cell_index()])
            {
              cell->get_dof_indices(cell_dofs);
              std::sort(cell_dofs.begin(), cell_dofs.end());
              dofs.add_indices(cell_dofs.begin(), cell_dofs.end());
            }
        dofs.compress();
        return dofs;
      }
    } // namespace



    template <int dim>
    ContactNewtonProblem<dim>::ContactNewtonProblem(
      const DoFHandler<dim>                    &dof_handler,
      const Mapping<dim>                       &mapping,
      Physics::SolidOperator<dim>              &solid,
      Contact::ContactGeometry<dim>            &geometry,
      const Contact::ContactParameters         &contact,
      const Solvers::LinearSolverParameters    &linear_solver,
      const Solvers::NonlinearSolverParameters &nonlinear_solver,
      const double                              reference_modulus,
      const MPI_Comm                            mpi_communicator)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , solid_operator(solid)
      , geometry(geometry)
      , contact_parameters(contact)
      , nonlinear_solver_parameters(nonlinear_solver)
      , reference_modulus(reference_modulus)
      , mpi_communicator(mpi_communicator)
      , linear_solver(linear_solver)
    {}



    template <int dim>
    void
    ContactNewtonProblem<dim>::setup(
      const AffineConstraints<double> &base_constraints)
    {
      locally_owned_dofs     = dof_handler.locally_owned_dofs();
      this->base_constraints = &base_constraints;

      const auto   start     = std::chrono::steady_clock::now();
      const double cpu_start = IO::process_cpu_seconds();

      // The rows this rank holds, integrates and reads: those of its own
      // secondary nodes and of the nodes its cells need (their DoFs and the
      // targets of their constraints, such as the parents of a hanging
      // node); with friction on several ranks also those of the cells
      // around its own nodes, over which their friction tangent (a row of
      // the bulk stiffness) is assembled.
      locally_active_dofs = DoFTools::extract_locally_active_dofs(dof_handler);
      IndexSet   needed_dofs;
      const bool distributed =
        Utilities::MPI::n_mpi_processes(mpi_communicator) > 1;
      const auto needed_rows = [&](
                                 const Contact::ContactSurface<dim> &surface) {
        friction_cells     = distributed && contact_parameters.has_friction() ?
                               Contact::cells_around_owned_nodes(surface,
                                                             locally_owned_dofs,
                                                             dof_handler) :
                               std::vector<bool>();
        friction_cell_dofs = dofs_of_cells(dof_handler, friction_cells);
        IndexSet needed    = locally_active_dofs;
        needed.add_indices(friction_cell_dofs);
        needed_dofs = with_constraint_targets(needed, base_constraints);
        std::vector<bool> rows(surface.n_nodes(), false);
        for (unsigned int j = 0; j < surface.n_nodes(); ++j)
          for (const auto dof : surface.node(j).dofs)
            rows[j] = rows[j] || locally_owned_dofs.is_element(dof) ||
                      needed_dofs.is_element(dof);
        return rows;
      };
      geometry.reinit(base_constraints, needed_rows);
      contact_enforcement =
        std::make_unique<Contact::ContactEnforcement<dim>>(contact_parameters,
                                                           geometry.coupling(),
                                                           reference_modulus);
      contact_enforcement->distribute_rows(locally_owned_dofs,
                                           needed_dofs,
                                           mpi_communicator);
      contact_enforcement->mark_constrained_nodes(base_constraints);
      contact_enforcement->initialize_active_set();
      solve_times.contact_setup = IO::seconds_since(start);
      solve_times.contact_cpu   = IO::process_cpu_seconds() - cpu_start;

      solution_owned.reinit(locally_owned_dofs, mpi_communicator);
      accepted_solution.reinit(locally_owned_dofs, mpi_communicator);
      previous_accepted_solution.reinit(locally_owned_dofs, mpi_communicator);
      accepted_time          = std::numeric_limits<double>::quiet_NaN();
      previous_accepted_time = std::numeric_limits<double>::quiet_NaN();
      newton_update.reinit(locally_owned_dofs, mpi_communicator);
      system_rhs.reinit(locally_owned_dofs, mpi_communicator);
      setup_stored_dofs(base_constraints);

      setup_matrices();
      linear_solver.reset();
      if (linear_solver.uses_multigrid())
        linear_solver.set_near_null_space(
          Physics::rigid_body_modes(mapping,
                                    dof_handler,
                                    solid_operator.kinematics() !=
                                      Physics::Kinematics::axisymmetric),
          dim);
    }



    // The DoFs this rank reads: those of its own cells (owned ones and the
    // partition interface; the shared triangulation makes every other cell
    // a ghost, so deal.II's locally relevant set would be every DoF), the
    // DoFs of the contact rows it holds (its own secondary nodes and those
    // its cells need) with their primary nodes, with friction the DoFs of
    // the cells around its own secondary nodes, and the DoFs that the
    // constraints of those lines refer to (a rigid body's reference node,
    // hanging-node parents). Nothing else is ghosted.
    template <int dim>
    void
    ContactNewtonProblem<dim>::setup_stored_dofs(
      const AffineConstraints<double> &base_constraints)
    {
      const IndexSet &partition_relevant = locally_active_dofs;
      IndexSet        contact_dofs(dof_handler.n_dofs());
      {
        const auto                          &coupling = geometry.coupling();
        const auto                          &rows = contact_enforcement->rows();
        std::vector<types::global_dof_index> dofs;
        for (unsigned int j = 0; j < coupling.n_rows(); ++j)
          {
            if (!rows.is_held(j))
              continue;
            for (const auto dof : coupling.secondary_surface().node(j).dofs)
              dofs.push_back(dof);
            for (const auto &[k, M] : coupling.row(j).primary_weights)
              for (const auto dof : coupling.primary_node(k).dofs)
                dofs.push_back(dof);
          }
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        contact_dofs.add_indices(dofs.begin(), dofs.end());
      }
      IndexSet relevant = partition_relevant;
      relevant.add_indices(contact_dofs);
      // The friction tangent of an owned node is its row of the bulk
      // stiffness: the DoFs of every cell around the node, closed below
      // over the hanging-node parents.
      relevant.add_indices(friction_cell_dofs);
      // A geometry in the current configuration reads the displacement of
      // both surfaces when it pairs them again.
      {
        const auto dofs = geometry.dofs_read_by_update();
        relevant.add_indices(dofs.begin(), dofs.end());
      }
      relevant = with_constraint_targets(relevant, base_constraints);
      relevant.compress();

      stored_dof_counts.n_owned = locally_owned_dofs.n_elements();
      stored_dof_counts.n_partition_ghosts =
        partition_relevant.n_elements() - stored_dof_counts.n_owned;
      stored_dof_counts.n_contact_ghosts =
        relevant.n_elements() - partition_relevant.n_elements();

      locally_relevant_dofs = relevant;
      constraints_dirichlet_and_hanging_nodes.clear();
      constraints_dirichlet_and_hanging_nodes.reinit(locally_relevant_dofs);
      for (const auto &line : base_constraints.get_lines())
        if (locally_relevant_dofs.is_element(line.index))
          {
            constraints_dirichlet_and_hanging_nodes.add_line(line.index);
            constraints_dirichlet_and_hanging_nodes.add_entries(line.index,
                                                                line.entries);
            constraints_dirichlet_and_hanging_nodes
              .set_inhomogeneity(line.index, line.inhomogeneity);
          }
      for (const auto dof : held_dofs)
        if (locally_relevant_dofs.is_element(dof) &&
            !constraints_dirichlet_and_hanging_nodes.is_constrained(dof))
          constraints_dirichlet_and_hanging_nodes.add_line(dof);
      constraints_dirichlet_and_hanging_nodes.close();

      solution.reinit(locally_owned_dofs,
                      locally_relevant_dofs,
                      mpi_communicator);
      solution = solution_owned;
      residual_vector.reinit(locally_owned_dofs,
                             locally_relevant_dofs,
                             mpi_communicator);
      linearized_residual.reinit(locally_owned_dofs,
                                 locally_relevant_dofs,
                                 mpi_communicator);
      if (geometry.is_current_configuration())
        accepted_ghosted.reinit(locally_owned_dofs,
                                locally_relevant_dofs,
                                mpi_communicator);
    }



    // In the current configuration the rows follow every new iterate: the
    // geometry pairs and integrates them again, the sparsity pattern grows
    // when a row meets a new primary node, and the friction history is
    // measured with the new rows.
    template <int dim>
    void
    ContactNewtonProblem<dim>::update_geometry()
    {
      if (!geometry.is_current_configuration())
        return;
      const auto start = std::chrono::steady_clock::now();
      // A rank's rows may meet a primary node outside the pattern while
      // another's do not: every rank builds the new pattern (collective).
      const bool changed = geometry.update(solution);
      if (Utilities::MPI::max(static_cast<unsigned int>(changed),
                              mpi_communicator) > 0)
        {
          // The direct solver refers to the matrix it factorised. The
          // linearised residual of the step just taken is still to be
          // read: it keeps its values through the new layout.
          linear_solver.reset();
          TrilinosWrappers::MPI::Vector kept_linearized_residual;
          if (linearized_residual_current)
            {
              kept_linearized_residual.reinit(locally_owned_dofs,
                                              mpi_communicator);
              kept_linearized_residual = linearized_residual;
            }
          setup_stored_dofs(*base_constraints);
          setup_matrices();
          if (linearized_residual_current)
            linearized_residual = kept_linearized_residual;
        }
      accepted_ghosted = accepted_solution;
      contact_enforcement->update_geometry(
        geometry.accepted_relative_displacements(accepted_ghosted));
      solve_times.geometry_update += IO::seconds_since(start);
    }



    // One sparsity pattern serves every active set: it holds the couplings
    // that any closed node's constraint (or penalty or friction term) can
    // create with the current mortar rows.
    template <int dim>
    void
    ContactNewtonProblem<dim>::setup_matrices()
    {
      DynamicSparsityPattern dsp(locally_relevant_dofs);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      constraints_dirichlet_and_hanging_nodes,
                                      true,
                                      Utilities::MPI::this_mpi_process(
                                        mpi_communicator));
      contact_enforcement->add_sparsity_entries(
        dof_handler,
        constraints_dirichlet_and_hanging_nodes,
        friction_cells,
        dsp);
      // The geometric stiffness of contact in the current configuration.
      for (const auto &group : geometry.coupled_dof_groups())
        constraints_dirichlet_and_hanging_nodes
          .add_entries_local_to_global(group, dsp, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 locally_owned_dofs,
                                                 mpi_communicator,
                                                 locally_relevant_dofs);
      system_matrix.reinit(locally_owned_dofs,
                           locally_owned_dofs,
                           dsp,
                           mpi_communicator);
      bulk_matrix_current = false;
      // Friction reads the bulk tangent's rows, the trial corrections
      // (multipliers, ContactGeometry::linearises_rows()) its columns.
      if (contact_enforcement->has_friction() ||
          (contact_parameters.enforcement ==
             Contact::Enforcement::lagrange_multiplier &&
           geometry.linearises_rows()))
        {
          bulk_matrix.reinit(system_matrix);
          assemble_bulk_matrix();
        }
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::assemble_bulk_matrix()
    {
      if (bulk_matrix_current)
        return;
      bulk_matrix = 0.;
      TrilinosWrappers::MPI::Vector unused(locally_owned_dofs,
                                           mpi_communicator);
      solid_operator.assemble_system(dof_handler,
                                     constraints_dirichlet_and_hanging_nodes,
                                     solution,
                                     bulk_matrix,
                                     unused);
      finish_bulk_matrix();
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::finish_bulk_matrix()
    {
      if (stabilized)
        {
          FullMatrix<double> k(1, 1);
          for (const auto i : locally_owned_dofs)
            {
              k(0, 0) = stabilization_scale * stabilization_stiffness(i);
              constraints_dirichlet_and_hanging_nodes
                .distribute_local_to_global(
                  k,
                  std::vector<types::global_dof_index>{i},
                  bulk_matrix);
            }
        }
      bulk_matrix.compress(VectorOperation::add);
      bulk_matrix_current = solid_operator.is_linear() && !stabilized;
    }



    // One semismooth Newton iteration: Dirichlet and hanging-node
    // constraints and, for Lagrange multipliers, one condensed constraint
    // per closed node (two for a sticking one); bulk tangent and residual;
    // external load; friction or penalty terms if selected.
    template <int dim>
    double
    ContactNewtonProblem<dim>::assemble_and_solve(
      const Solvers::LoadState &state,
      const ExternalLoad       &load,
      const double              linear_tolerance)
    {
      const auto start = std::chrono::steady_clock::now();
      // The bulk tangent (friction reads its rows) and the bulk residual
      // (friction, and the linearised residual below) come from the same
      // integration of the cells as the system.
      const bool friction = contact_enforcement->has_friction();
      const bool lagrange = contact_parameters.enforcement ==
                            Contact::Enforcement::lagrange_multiplier;
      // With multipliers in the current configuration, the trial
      // corrections need the full derivatives of the gaps and the bulk
      // tangent's columns.
      typename Contact::NormalEnforcement<dim>::GapDerivatives derivatives;
      const bool full_derivatives = lagrange && geometry.linearises_rows() &&
                                    closed_gap_derivatives(false, derivatives);
      const bool needs_bulk_tangent =
        (friction || full_derivatives) && !bulk_matrix_current;
      const bool needs_bulk_residual = friction || uses_linearized_tractions();
      constraints.clear();
      constraints.reinit(locally_relevant_dofs);
      constraints.merge(constraints_dirichlet_and_hanging_nodes);
      if (load.prescribed_displacements)
        {
          std::map<types::global_dof_index, double> values;
          load.prescribed_displacements(state, values);
          for (const auto &[dof, value] : values)
            {
              // Each rank holds the constraints of its stored DoFs only.
              if (!locally_relevant_dofs.is_element(dof))
                continue;
              AssertThrow(constraints.is_constrained(dof),
                          ExcMessage("A prescribed displacement acts on a "
                                     "DoF without a Dirichlet constraint."));
              constraints.set_inhomogeneity(dof, value - solution(dof));
            }
        }
      trial_corrections.clear();
      if (lagrange)
        contact_enforcement->add_constraints(
          constraints,
          solution,
          full_derivatives ? &derivatives : nullptr,
          full_derivatives ? &trial_corrections : nullptr);
      constraints.close();

      system_matrix = 0.;
      system_rhs    = 0.;
      typename Physics::SolidOperator<dim>::BulkTerms bulk;
      bulk.constraints = &constraints_dirichlet_and_hanging_nodes;
      TrilinosWrappers::MPI::Vector internal_force, bulk_residual;
      if (needs_bulk_tangent)
        {
          bulk_matrix  = 0.;
          bulk.tangent = &bulk_matrix;
        }
      if (needs_bulk_residual)
        {
          internal_force.reinit(locally_owned_dofs, mpi_communicator);
          bulk.internal_force = &internal_force;
        }
      solid_operator.assemble_system_and_bulk_terms(dof_handler,
                                                    constraints,
                                                    solution,
                                                    system_matrix,
                                                    system_rhs,
                                                    bulk);
      if (needs_bulk_tangent)
        finish_bulk_matrix();
      if (needs_bulk_residual)
        {
          bulk_residual =
            bulk_residual_from(internal_force, solution, state, load);
          residual_vector = bulk_residual;
        }
      load.add(state, constraints, system_rhs);
      if (stabilized)
        {
          FullMatrix<double> k(1, 1);
          Vector<double>     f(1);
          for (const auto i : locally_owned_dofs)
            {
              k(0, 0) = stabilization_scale * stabilization_stiffness(i);
              f(0)    = -k(0, 0) * (solution(i) - stabilization_anchor(i));
              constraints.distribute_local_to_global(
                k,
                f,
                std::vector<types::global_dof_index>{i},
                system_matrix,
                system_rhs);
            }
        }
      add_geometric_contact_stiffness();
      if (contact_parameters.enforcement == Contact::Enforcement::penalty)
        {
          // Where the rows follow the configuration, the penalty force's
          // tangent needs the full derivative of the gap.
          const bool full = closed_gap_derivatives(true, derivatives);
          contact_enforcement->assemble_penalty(constraints,
                                                solution,
                                                locally_owned_dofs,
                                                system_matrix,
                                                system_rhs,
                                                full ? &derivatives : nullptr);
        }
      contact_enforcement->assemble_friction(constraints,
                                             solution,
                                             bulk_matrix,
                                             residual_vector,
                                             locally_owned_dofs,
                                             system_matrix,
                                             system_rhs,
                                             &trial_corrections);
      if (full_derivatives)
        add_trial_corrections();
      system_matrix.compress(VectorOperation::add);
      system_rhs.compress(VectorOperation::add);
      solve_times.assembly += IO::seconds_since(start);

      const auto solve_start = std::chrono::steady_clock::now();
      newton_update          = 0.;
      // An inexact solve need not go below what the Newton tolerance asks
      // of the equilibrium residual: a hundredth of it, relative to the
      // right-hand side.
      const double rhs_norm = system_rhs.l2_norm();
      const double tolerance =
        linear_tolerance > 0. && rhs_norm > 0. ?
          std::max(linear_tolerance,
                   0.01 * nonlinear_solver_parameters.tolerance *
                     load.magnitude(state) / rhs_norm) :
          linear_tolerance;
      linear_solver.solve(system_matrix, newton_update, system_rhs, tolerance);
      constraints.distribute(newton_update);
      if (full_derivatives)
        apply_trial_corrections();
      solve_times.linear_solve += IO::seconds_since(solve_start);

      // The linearised bulk residual at the new iterate, r(u) + r'(u) du,
      // by a difference quotient along du (one residual evaluation). The
      // probe moves the nodes by 1e-8 of the displacement (at least of
      // 1e-3 mm), whatever the size of du: its nonlinear error is of order
      // 1e-8 |du| and its round-off of order 1e-8 |r| |du| / |u|, both of
      // which vanish with the Newton step.
      const double update_size = newton_update.linfty_norm();
      if (uses_linearized_tractions() && update_size > 0.)
        {
          const auto   residual_start = std::chrono::steady_clock::now();
          const double epsilon =
            1e-8 * std::max(solution_owned.linfty_norm(), 1e-3) / update_size;
          const TrilinosWrappers::MPI::Vector &r_now = bulk_residual;
          TrilinosWrappers::MPI::Vector        probe = solution_owned;
          probe.add(epsilon, newton_update);
          TrilinosWrappers::MPI::Vector probe_ghosted(solution);
          probe_ghosted = probe;
          TrilinosWrappers::MPI::Vector r_probe =
            bulk_residual_at(probe_ghosted, state, load);
          r_probe.add(-1., r_now);
          r_probe *= 1. / epsilon;
          r_probe.add(1., r_now);
          linearized_residual         = r_probe;
          linearized_residual_current = true;
          solve_times.residual += IO::seconds_since(residual_start);
        }
      solution_owned += newton_update;
      solution = solution_owned;
      // A nonlinear solid's tangent belongs to the new state.
      bulk_matrix_current = bulk_matrix_current && solid_operator.is_linear();
      update_geometry();
      const double update_norm  = newton_update.l2_norm();
      const double current_norm = solution_owned.l2_norm();
      return current_norm > 0. ? update_norm / current_norm :
                                 (update_norm > 0. ? 1. : 0.);
    }



    // The contact forces of the current tractions change with the rows in
    // the current configuration: minus their derivative joins the tangent,
    // distributed through the constraints of the iteration (its inhomogeneous
    // columns move to the right-hand side).
    template <int dim>
    void
    ContactNewtonProblem<dim>::add_geometric_contact_stiffness()
    {
      if (!geometry.is_current_configuration())
        return;
      const auto                 &coupling = geometry.coupling();
      const auto                 &rows     = contact_enforcement->rows();
      std::vector<Tensor<1, dim>> tractions(coupling.n_rows());
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        if (rows.is_owned(j) && contact_enforcement->is_active(j))
          tractions[j] =
            -contact_enforcement->pressure(j) * coupling.row(j).normal +
            contact_enforcement->tangential_traction(j);
      FullMatrix<double> column;
      Vector<double>     rhs;
      geometry.contact_force_derivative(
        tractions,
        [&](const std::vector<types::global_dof_index> &row_dofs,
            const types::global_dof_index               dof,
            const std::vector<double>                  &values) {
          column.reinit(row_dofs.size(), 1);
          rhs.reinit(row_dofs.size());
          for (unsigned int i = 0; i < row_dofs.size(); ++i)
            column(i, 0) = values[i];
          std::vector<types::global_dof_index> column_dofs{dof};
          trial_corrections.extend_columns(column_dofs, column, rhs);
          distribute_block(row_dofs, column_dofs, column, rhs);
        });
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::distribute_block(
      const std::vector<types::global_dof_index> &row_dofs,
      const std::vector<types::global_dof_index> &column_dofs,
      const FullMatrix<double>                   &block,
      const Vector<double>                       &rhs)
    {
      // A square local system over rows and columns, so that the
      // inhomogeneities of constrained columns move to the right-hand side.
      std::vector<types::global_dof_index> dofs = row_dofs;
      std::vector<unsigned int>            position(column_dofs.size());
      for (unsigned int b = 0; b < column_dofs.size(); ++b)
        {
          position[b] =
            std::find(dofs.begin(), dofs.end(), column_dofs[b]) - dofs.begin();
          if (position[b] == dofs.size())
            dofs.push_back(column_dofs[b]);
        }
      FullMatrix<double> cell_matrix(dofs.size(), dofs.size());
      Vector<double>     cell_rhs(dofs.size());
      for (unsigned int a = 0; a < row_dofs.size(); ++a)
        {
          for (unsigned int b = 0; b < column_dofs.size(); ++b)
            cell_matrix(a, position[b]) += block(a, b);
          cell_rhs(a) = rhs(a);
        }
      constraints.distribute_local_to_global(cell_matrix,
                                             cell_rhs,
                                             dofs,
                                             system_matrix,
                                             system_rhs,
                                             true);
    }



    template <int dim>
    bool
    ContactNewtonProblem<dim>::closed_gap_derivatives(
      const bool                                                owned_only,
      typename Contact::NormalEnforcement<dim>::GapDerivatives &derivatives)
      const
    {
      if (!geometry.is_current_configuration())
        return false;
      const auto &coupling = geometry.coupling();
      const auto &rows     = contact_enforcement->rows();
      derivatives.assign(coupling.n_rows(), {});
      std::vector<bool> closed(coupling.n_rows(), false);
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        closed[j] = (owned_only ? rows.is_owned(j) : rows.is_held(j)) &&
                    contact_enforcement->is_active(j);
      return geometry.weighted_gap_derivative(
        closed,
        solution,
        [&](const unsigned int            j,
            const types::global_dof_index dof,
            const double value) { derivatives[j].emplace_back(dof, value); });
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::add_trial_corrections()
    {
      // Collective: every rank takes part in the products.
      if (Utilities::MPI::max(static_cast<unsigned int>(
                                trial_corrections.all().size()),
                              mpi_communicator) == 0)
        return;
      // P_G - P_B as a matrix (rows: the corrected DoFs this rank owns),
      // and its inhomogeneities as a vector.
      DynamicSparsityPattern        dsp(dof_handler.n_dofs(),
                                 dof_handler.n_dofs(),
                                 locally_owned_dofs);
      TrilinosWrappers::MPI::Vector inhomogeneities(locally_owned_dofs,
                                                    mpi_communicator);
      for (const auto &correction : trial_corrections.all())
        if (locally_owned_dofs.is_element(correction.dof))
          {
            for (const auto &entry : correction.entries)
              dsp.add(correction.dof, entry.first);
            inhomogeneities(correction.dof) = correction.inhomogeneity;
          }
      inhomogeneities.compress(VectorOperation::insert);
      TrilinosWrappers::SparseMatrix difference;
      difference.reinit(locally_owned_dofs,
                        locally_owned_dofs,
                        dsp,
                        mpi_communicator);
      for (const auto &correction : trial_corrections.all())
        if (locally_owned_dofs.is_element(correction.dof))
          for (const auto &[q, value] : correction.entries)
            difference.set(correction.dof, q, value);
      difference.compress(VectorOperation::insert);

      // The bulk tangent times both, row by row through the constraints
      // (P_B^T).
      TrilinosWrappers::SparseMatrix product;
      bulk_matrix.mmult(product, difference);
      TrilinosWrappers::MPI::Vector shift(locally_owned_dofs, mpi_communicator);
      bulk_matrix.vmult(shift, inhomogeneities);
      std::vector<types::global_dof_index> row(1), columns;
      FullMatrix<double>                   block;
      Vector<double>                       rhs(1);
      for (const auto i : locally_owned_dofs)
        {
          columns.clear();
          std::vector<double> values;
          if (product.row_length(i) > 0)
            {
              const auto end = product.end(i);
              for (auto entry = product.begin(i); entry != end; ++entry)
                if (entry->value() != 0.)
                  {
                    columns.push_back(entry->column());
                    values.push_back(entry->value());
                  }
            }
          if (columns.empty() && shift(i) == 0.)
            continue;
          row[0] = i;
          rhs(0) = -shift(i);
          block.reinit(1, columns.size());
          for (unsigned int b = 0; b < columns.size(); ++b)
            block(0, b) = values[b];
          distribute_block(row, columns, block, rhs);
        }
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::apply_trial_corrections()
    {
      TrilinosWrappers::MPI::Vector update(locally_owned_dofs,
                                           locally_relevant_dofs,
                                           mpi_communicator);
      update = newton_update;
      for (const auto &correction : trial_corrections.all())
        if (locally_owned_dofs.is_element(correction.dof))
          {
            double change = correction.inhomogeneity;
            for (const auto &[q, coefficient] : correction.entries)
              change += coefficient * update(q);
            newton_update(correction.dof) += change;
          }
      newton_update.compress(VectorOperation::add);
    }



    template <int dim>
    bool
    ContactNewtonProblem<dim>::is_nonlinear() const
    {
      return !solid_operator.is_linear() || geometry.is_current_configuration();
    }



    template <int dim>
    bool
    ContactNewtonProblem<dim>::uses_linearized_tractions() const
    {
      return contact_parameters.enforcement ==
               Contact::Enforcement::lagrange_multiplier &&
             is_nonlinear();
    }



    template <int dim>
    TrilinosWrappers::MPI::Vector
    ContactNewtonProblem<dim>::bulk_residual_at(
      const TrilinosWrappers::MPI::Vector &u,
      const Solvers::LoadState            &state,
      const ExternalLoad                  &load)
    {
      // f_ext - f_int condensed as the linear system is: hanging-node
      // forces on their parents (a secondary node may be one), Dirichlet
      // rows zero (support reactions are no contact tractions).
      TrilinosWrappers::MPI::Vector f(locally_owned_dofs, mpi_communicator);
      solid_operator.assemble_internal_force(
        dof_handler,
        constraints_dirichlet_and_hanging_nodes,
        u,
        f);
      return bulk_residual_from(f, u, state, load);
    }



    template <int dim>
    TrilinosWrappers::MPI::Vector
    ContactNewtonProblem<dim>::bulk_residual_from(
      TrilinosWrappers::MPI::Vector       &internal_force,
      const TrilinosWrappers::MPI::Vector &u,
      const Solvers::LoadState            &state,
      const ExternalLoad                  &load)
    {
      TrilinosWrappers::MPI::Vector &r = internal_force;
      r.compress(VectorOperation::add);
      r *= -1.;
      load.add(state, constraints_dirichlet_and_hanging_nodes, r);
      r.compress(VectorOperation::add);
      if (stabilized)
        add_stabilization_forces(u, constraints_dirichlet_and_hanging_nodes, r);
      return r;
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::setup_stabilization()
    {
      if (stabilization_stiffness.size() > 0)
        return;
      // k_i = factor E int N_i dV / h^2 per cell, h the cell's smallest
      // vertex distance: a spring that moves a cell's nodes together by
      // its size takes factor times the force that strains it by 1.
      const double factor = nonlinear_solver_parameters.stabilization_factor;
      const auto  &fe     = dof_handler.get_fe();
      const QGauss<dim> quadrature(fe.degree + 1);
      FEValues<dim>     fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_JxW_values);
      stabilization_stiffness.reinit(locally_owned_dofs, mpi_communicator);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      double smallest = std::numeric_limits<double>::infinity();
      // Every rank holds every cell of a shared triangulation; each adds
      // to its own DoFs.
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const double h = cell->minimum_vertex_distance();
          smallest       = std::min(smallest, h);
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (locally_owned_dofs.is_element(dofs[i]))
              {
                double integral = 0.;
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  integral += fe_values.shape_value(i, q) * fe_values.JxW(q);
                stabilization_stiffness(dofs[i]) +=
                  factor * reference_modulus * integral / (h * h);
              }
        }
      stabilization_stiffness.compress(VectorOperation::add);
      smallest_cell = smallest;
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::add_stabilization_forces(
      const TrilinosWrappers::MPI::Vector &u,
      const AffineConstraints<double>     &constraints,
      TrilinosWrappers::MPI::Vector       &r) const
    {
      for (const auto i : locally_owned_dofs)
        if (!constraints.is_constrained(i))
          r(i) -= stabilization_scale * stabilization_stiffness(i) *
                  (u(i) - stabilization_anchor(i));
      r.compress(VectorOperation::add);
    }



    template <int dim>
    TrilinosWrappers::MPI::Vector
    ContactNewtonProblem<dim>::compute_bulk_residual(
      const Solvers::LoadState &state,
      const ExternalLoad       &load)
    {
      TrilinosWrappers::MPI::Vector r = bulk_residual_at(solution, state, load);
      residual_vector                 = r;
      return r;
    }



    // Residuals of the updated state, relative to the load: equilibrium
    // including the contact forces of the recovered tractions, and the
    // normal and tangential complementarity functions.
    template <int dim>
    Solvers::NewtonResidual
    ContactNewtonProblem<dim>::evaluate_residual(
      const Solvers::LoadState &state,
      const ExternalLoad       &load)
    {
      const auto start = std::chrono::steady_clock::now();
      // A compressed vector: contact forces are added on the ranks that own
      // contact nodes only, and the final compress() is the one collective
      // step.
      TrilinosWrappers::MPI::Vector r = compute_bulk_residual(state, load);

      contact_enforcement->update_pressures(solution, residual_vector);
      // After a Newton update of a nonlinear problem, a closed node opens
      // only if the multiplier of the linearised step is tensile too.
      if (linearized_residual_current)
        contact_enforcement->keep_linearized_compression(solution,
                                                         linearized_residual);
      linearized_residual_current = false;
      contact_enforcement->add_contact_forces(
        constraints_dirichlet_and_hanging_nodes,
        locally_owned_dofs,
        r);
      r.compress(VectorOperation::add);
      constraints_dirichlet_and_hanging_nodes.set_zero(r);

      const double            scale = load.magnitude(state);
      Solvers::NewtonResidual residual;
      residual.equilibrium = r.l2_norm() / scale;
      residual.complementarity =
        contact_enforcement->complementarity_norm(solution) / scale;
      solve_times.residual += IO::seconds_since(start);
      return residual;
    }



    template <int dim>
    Solvers::NewtonStatistics
    ContactNewtonProblem<dim>::solve(const Solvers::LoadState &state,
                                     const ExternalLoad       &load,
                                     ConditionalOStream       &verbose)
    {
      const auto   start     = std::chrono::steady_clock::now();
      const double cpu_start = IO::process_cpu_seconds();
      // Extrapolate within a stage (pseudo-time: stage index plus the
      // fraction of the stage, the stage's end included).
      solved_time = state.time;
      if (nonlinear_solver_parameters.extrapolate_initial_guess &&
          std::isfinite(previous_accepted_time))
        {
          const auto stage_of = [](const double t) {
            return std::ceil(t - 1e-12) - 1.;
          };
          const double dt_last = accepted_time - previous_accepted_time;
          if (stage_of(state.time) == stage_of(accepted_time) &&
              stage_of(accepted_time) == stage_of(previous_accepted_time) &&
              dt_last > 0.)
            {
              const double ratio =
                std::min(1., (state.time - accepted_time) / dt_last);
              solution_owned = accepted_solution;
              solution_owned.add(ratio, accepted_solution);
              solution_owned.add(-ratio, previous_accepted_solution);
              for (const auto dof : held_dofs)
                if (locally_owned_dofs.is_element(dof))
                  solution_owned(dof) = accepted_solution(dof);
              solution_owned.compress(VectorOperation::insert);
              solution = solution_owned;
            }
        }
      geometry.set_load_state(state);
      update_geometry();
      contact_enforcement->begin_step();
      Solvers::NewtonCallbacks callbacks;
      // A Newton iteration may solve the contact problem of its own
      // linearisation: each solve from the same state, the first update of
      // the set semismooth, the later ones one point each (a pivoting
      // method; see NonlinearSolverParameters). The first iteration
      // carries the load increment and has its own limit.
      unsigned int n_extra_first_iteration_solves = 0;
      unsigned int n_extra_later_iteration_solves = 0;
      bool         first_iteration                = true;
      callbacks.assemble_solve_and_update = [&](const double tolerance) {
        const bool is_first = first_iteration;
        first_iteration     = false;
        const unsigned int max_solves =
          uses_linearized_tractions() ?
            (is_first ?
               nonlinear_solver_parameters.max_first_iteration_solves :
               nonlinear_solver_parameters.max_later_iteration_solves) :
            1;
        if (max_solves <= 1)
          return assemble_and_solve(state, load, tolerance);
        const TrilinosWrappers::MPI::Vector start     = solution_owned;
        double                              increment = 0.;
        // The sets of these solves are judged on one linearisation: only
        // they count as seen while it lasts.
        contact_enforcement->begin_linearisation();
        for (unsigned int i = 1;; ++i)
          {
            increment = assemble_and_solve(state, load, tolerance);
            if (i == max_solves)
              break;
            // The pressures of the linearised step and the gaps at its end.
            contact_enforcement->update_pressures(solution,
                                                  linearized_residual);
            const auto         t = std::chrono::steady_clock::now();
            const unsigned int n_changed =
              contact_enforcement->update_active_set(solution, -1., i > 1);
            solve_times.active_set_update += IO::seconds_since(t);
            verbose << "      Solve " << i << " of the iteration: " << n_changed
                    << " active-set changes" << std::endl;
            if (n_changed == 0 || contact_enforcement->is_cycling())
              break;
            ++(is_first ? n_extra_first_iteration_solves :
                          n_extra_later_iteration_solves);
            solution_owned = start;
            solution       = solution_owned;
            update_geometry();
          }
        contact_enforcement->end_linearisation();
        return increment;
      };
      // In a nonlinear problem the iterate depends on the iteration's
      // progress, and a set revisited after it is no cycle.
      double last_residual        = -1.;
      callbacks.evaluate_residual = [&]() {
        // Debug builds throw at the first non-finite value; the iteration
        // sees it as the non-finite residual of a Release build.
        Solvers::NewtonResidual residual;
        try
          {
            residual = evaluate_residual(state, load);
          }
        catch (const StandardExceptions::ExcNumberNotFinite &)
          {
            residual.equilibrium     = std::numeric_limits<double>::quiet_NaN();
            residual.complementarity = residual.equilibrium;
            return residual;
          }
        if (is_nonlinear())
          last_residual =
            std::max(residual.equilibrium, residual.complementarity);
        return residual;
      };
      const auto update_set = [&](const bool one_point) {
        const auto         t = std::chrono::steady_clock::now();
        const unsigned int n_changed =
          contact_enforcement->update_active_set(solution,
                                                 last_residual,
                                                 one_point);
        solve_times.active_set_update += IO::seconds_since(t);
        return n_changed;
      };
      callbacks.update_active_set = [&]() {
        return update_set(false);
      };
      callbacks.is_cycling = [&]() {
        return contact_enforcement->is_cycling();
      };
      // A nonlinear problem may hold a cycling set until equilibrium.
      if (is_nonlinear())
        {
          callbacks.restart_cycle_detection = [&]() {
            contact_enforcement->restart_cycle_detection();
          };
          callbacks.update_one_point = [&]() {
            return update_set(true);
          };
          callbacks.revisits_held_set = [&]() {
            return contact_enforcement->revisits_held_set();
          };
        }

      // The solid's multipliers (augmented Lagrangian) follow the iterate
      // within each solve, at most max_multiplier_updates() times; the
      // loop after the solve below then finds them converged, or fails the
      // step once that many updates have not sufficed.
      unsigned int n_solve_augmentations = 0;
      if (solid_operator.max_multiplier_updates() > 0)
        callbacks.update_multipliers = [&]() {
          if (n_solve_augmentations >= solid_operator.max_multiplier_updates())
            return false;
          if (!solid_operator.update_multipliers(dof_handler, solution))
            return false;
          ++n_solve_augmentations;
          return true;
        };

      // A diverging iterate may produce a non-finite value: Release builds
      // see it in the residual, Debug builds at deal.II's check, which
      // throws. Either way the step fails and is cut back. An iterate far
      // from equilibrium may give a matrix that cannot be factorised: in a
      // nonlinear problem that is a failed step like any other, cut back;
      // in a linear one the model is at fault.
      const auto newton = [&]() {
        Solvers::NewtonStatistics result;
        first_iteration       = true;
        n_solve_augmentations = 0;
        try
          {
            result = Solvers::solve_newton(nonlinear_solver_parameters,
                                           callbacks,
                                           verbose);
          }
        catch (const StandardExceptions::ExcNumberNotFinite &)
          {
            linear_solver.reset();
            result.converged = false;
            result.failure   = "non-finite value in an iterate";
            result.diverged  = true;
          }
        catch (const Solvers::ExcFactorisationFailed &failure)
          {
            if (!is_nonlinear())
              throw;
            linear_solver.reset();
            result.converged = false;
            result.failure   = IO::one_line_message(failure);
            result.diverged  = true;
          }
        return result;
      };
      Solvers::NewtonStatistics statistics = newton();
      // Statistics of a further solve of the same step join the step's.
      const auto append = [&statistics](const Solvers::NewtonStatistics &more) {
        statistics.n_iterations += more.n_iterations;
        statistics.n_augmentations += more.n_augmentations;
        statistics.max_iterations_per_solve =
          std::max(statistics.max_iterations_per_solve,
                   more.max_iterations_per_solve);
        statistics.residuals.insert(statistics.residuals.end(),
                                    more.residuals.begin(),
                                    more.residuals.end());
        statistics.active_set_changes.insert(
          statistics.active_set_changes.end(),
          more.active_set_changes.begin(),
          more.active_set_changes.end());
      };

      // Pseudo-transient continuation: a failed step is solved again from
      // its start with springs to the last solution, anchored anew at each
      // one, until a solve moves nothing; then without them. A step whose
      // iteration diverged is cut back first: its increment was too large
      // for Newton, and a smaller one may converge at once; the retried
      // step takes the stabilized path if it fails too.
      if (!statistics.converged &&
          nonlinear_solver_parameters.stabilization_factor > 0. &&
          (!statistics.diverged || state.after_cutback))
        {
          verbose << "  The step failed (" << statistics.failure
                  << "); stabilized solves from its start" << std::endl;
          const std::string first_failure = statistics.failure;
          restore();
          geometry.set_load_state(state);
          update_geometry();
          contact_enforcement->begin_step();
          setup_stabilization();
          stabilized          = true;
          stabilization_scale = 1.;
          bulk_matrix_current = false;
          // The springs soften by half after each solve that moves less
          // than the one before: they carry the state past where it has no
          // equilibrium, then let it settle. A solve that fails starts
          // again from its anchor with springs four times as stiff.
          constexpr unsigned int max_solves = 100;
          double                 moved      = 0.;
          double       last_moved = std::numeric_limits<double>::infinity();
          unsigned int n_solves   = 0;
          Solvers::NewtonStatistics again;
          while (n_solves < max_solves)
            {
              stabilization_anchor = solution_owned;
              again                = newton();
              append(again);
              ++n_solves;
              if (!again.converged)
                {
                  verbose << "  Stabilized solve " << n_solves << " (springs x "
                          << IO::Console::format(stabilization_scale)
                          << ") failed" << std::endl;
                  if (stabilization_scale >= 1.)
                    break;
                  solution_owned = stabilization_anchor;
                  solution       = solution_owned;
                  update_geometry();
                  stabilization_scale = std::min(1., 4. * stabilization_scale);
                  continue;
                }
              TrilinosWrappers::MPI::Vector change = solution_owned;
              change -= stabilization_anchor;
              moved = change.linfty_norm();
              // The springs' work as dashpots: sum_i s k_i d_i^2 over the
              // DoFs that carry a spring.
              double dissipated = 0.;
              for (const auto i : locally_owned_dofs)
                if (!constraints_dirichlet_and_hanging_nodes.is_constrained(i))
                  dissipated += stabilization_scale *
                                stabilization_stiffness(i) * change(i) *
                                change(i);
              dissipated = Utilities::MPI::sum(dissipated, mpi_communicator);
              statistics.stabilization_energy += dissipated;
              verbose << "  Stabilized solve " << n_solves << " (springs x "
                      << IO::Console::format(stabilization_scale)
                      << "): largest motion " << IO::Console::format(moved)
                      << " mm, dissipated " << IO::Console::format(dissipated)
                      << " N mm" << std::endl;
              if (moved <= 1e-6 * smallest_cell)
                break;
              if (moved < last_moved)
                stabilization_scale *= 0.5;
              last_moved = moved;
            }
          if (again.converged && moved > 1e-6 * smallest_cell)
            {
              again.converged = false;
              again.failure =
                "still moving after " + std::to_string(max_solves) + " solves";
            }
          statistics.n_stabilized_solves = n_solves;
          stabilized                     = false;
          bulk_matrix_current            = false;
          if (again.converged)
            {
              again = newton();
              append(again);
              statistics.converged         = again.converged;
              statistics.converged_on_step = again.converged_on_step;
              statistics.failure           = again.converged ?
                                               std::string() :
                                               first_failure + "; after " +
                                       std::to_string(n_solves) +
                                       " stabilized solves: " + again.failure;
            }
          else
            statistics.failure = first_failure +
                                 "; a stabilized solve failed too (" +
                                 again.failure + ")";
        }

      // Constraints of the solid enforced by an augmented Lagrangian: update
      // the multipliers at the converged state and solve again until the
      // constraints hold.
      while (statistics.converged &&
             solid_operator.update_multipliers(dof_handler, solution))
        {
          if (statistics.n_augmentations >=
              solid_operator.max_multiplier_updates())
            {
              statistics.converged = false;
              statistics.failure =
                "the solid's constraints (incompressibility) still violated "
                "after " +
                std::to_string(statistics.n_augmentations) +
                " multiplier updates";
              break;
            }
          verbose << "  Multiplier update " << statistics.n_augmentations + 1
                  << std::endl;
          const auto again = newton();
          append(again);
          statistics.converged         = again.converged;
          statistics.converged_on_step = again.converged_on_step;
          statistics.failure           = again.failure;
          ++statistics.n_augmentations;
        }
      // An equilibrium in which a node has passed through a tool, where the
      // contact no longer sees it, is not a solution.
      if (statistics.converged)
        {
          const std::string why = geometry.inadmissible_state();
          if (!why.empty())
            {
              statistics.converged = false;
              statistics.failure   = why;
            }
        }
      solve_times.newton += IO::seconds_since(start);
      solve_times.contact_cpu += IO::process_cpu_seconds() - cpu_start;
      statistics.n_extra_first_iteration_solves =
        n_extra_first_iteration_solves;
      statistics.n_extra_later_iteration_solves =
        n_extra_later_iteration_solves;
      return statistics;
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::commit()
    {
      previous_accepted_solution = accepted_solution;
      previous_accepted_time     = accepted_time;
      accepted_solution          = solution_owned;
      accepted_time              = solved_time;
      solid_operator.commit(dof_handler, solution);
      geometry.commit();
      contact_enforcement->commit(solution);
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::restore()
    {
      solution_owned      = accepted_solution;
      solution            = solution_owned;
      bulk_matrix_current = bulk_matrix_current && solid_operator.is_linear();
      solid_operator.restore();
      contact_enforcement->restore();
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::hold_dofs(
      const std::vector<types::global_dof_index> &dofs)
    {
      const auto &surface = geometry.coupling().secondary_surface();
      for (unsigned int j = 0; j < surface.n_nodes(); ++j)
        for (const auto dof : surface.node(j).dofs)
          AssertThrow(std::find(dofs.begin(), dofs.end(), dof) == dofs.end(),
                      ExcMessage("A held DoF belongs to a node of the "
                                 "secondary contact surface."));
      held_dofs.insert(held_dofs.end(), dofs.begin(), dofs.end());
      // The direct solver refers to the matrix it factorised, and the bulk
      // tangent is condensed with the new constraints.
      linear_solver.reset();
      setup_stored_dofs(*base_constraints);
      setup_matrices();
    }



    template <int dim>
    void
    ContactNewtonProblem<dim>::release_dofs(
      const std::vector<types::global_dof_index> &dofs)
    {
      held_dofs.erase(std::remove_if(held_dofs.begin(),
                                     held_dofs.end(),
                                     [&](const types::global_dof_index dof) {
                                       return std::find(dofs.begin(),
                                                        dofs.end(),
                                                        dof) != dofs.end();
                                     }),
                      held_dofs.end());
      linear_solver.reset();
      setup_stored_dofs(*base_constraints);
      setup_matrices();
    }



    template <int dim>
    double
    ContactNewtonProblem<dim>::time_fixed_active_set_solve(
      const Solvers::LoadState &state,
      const ExternalLoad       &load,
      const unsigned int        n_repeats)
    {
      const TrilinosWrappers::MPI::Vector converged = solution_owned;
      const ContactSolveTimes             kept      = solve_times;
      std::vector<double>                 times;
      for (unsigned int i = 0; i < std::max(1u, n_repeats); ++i)
        {
          solid_operator.clear();
          linear_solver.reset();
          const double start = IO::process_cpu_seconds();
          assemble_and_solve(state, load, 0.);
          times.push_back(IO::process_cpu_seconds() - start);
          solution_owned = converged;
          solution       = solution_owned;
          update_geometry();
        }
      solve_times = kept;
      std::nth_element(times.begin(),
                       times.begin() + times.size() / 2,
                       times.end());
      return times[times.size() / 2];
    }



    // Unconstrained nodal forces: every DoF keeps its own, hanging nodes
    // included, so that the sum over a boundary is the total force.
    template <int dim>
    TrilinosWrappers::MPI::Vector
    ContactNewtonProblem<dim>::nodal_reactions(const Solvers::LoadState &state,
                                               const ExternalLoad       &load)
    {
      AffineConstraints<double> none;
      none.close();
      TrilinosWrappers::MPI::Vector f(locally_owned_dofs, mpi_communicator);
      solid_operator.assemble_internal_force(dof_handler, none, solution, f);
      f.compress(VectorOperation::add);
      TrilinosWrappers::MPI::Vector f_ext(locally_owned_dofs, mpi_communicator);
      load.add(state, none, f_ext);
      f_ext.compress(VectorOperation::add);
      f -= f_ext;
      return f;
    }



    template <int dim>
    double
    ContactNewtonProblem<dim>::reaction_force(
      const std::vector<types::global_dof_index> &dofs,
      const Solvers::LoadState                   &state,
      const ExternalLoad                         &load)
    {
      const TrilinosWrappers::MPI::Vector f      = nodal_reactions(state, load);
      double                              result = 0.;
      for (const auto dof : dofs)
        if (locally_owned_dofs.is_element(dof))
          result += f(dof);
      return Utilities::MPI::sum(result, mpi_communicator);
    }



    template <int dim>
    std::vector<Tensor<1, dim>>
    ContactNewtonProblem<dim>::reaction_forces(
      const std::vector<types::boundary_id> &boundary_ids,
      const Solvers::LoadState              &state,
      const ExternalLoad                    &load)
    {
      const TrilinosWrappers::MPI::Vector f = nodal_reactions(state, load);
      std::vector<Tensor<1, dim>>         reactions(boundary_ids.size());
      for (unsigned int b = 0; b < boundary_ids.size(); ++b)
        {
          for (unsigned int c = 0; c < dim; ++c)
            {
              ComponentMask mask(dim, false);
              mask.set(c, true);
              const IndexSet dofs =
                DoFTools::extract_boundary_dofs(dof_handler,
                                                mask,
                                                {boundary_ids[b]});
              for (const auto dof : dofs)
                if (locally_owned_dofs.is_element(dof))
                  reactions[b][c] += f(dof);
            }
          reactions[b] = Utilities::MPI::sum(reactions[b], mpi_communicator);
        }
      return reactions;
    }



    template <int dim>
    const TrilinosWrappers::MPI::Vector &
    ContactNewtonProblem<dim>::displacement() const
    {
      return solution;
    }



    template <int dim>
    const TrilinosWrappers::MPI::Vector &
    ContactNewtonProblem<dim>::bulk_residual() const
    {
      return residual_vector;
    }



    template <int dim>
    const Contact::MortarCoupling<dim> &
    ContactNewtonProblem<dim>::coupling() const
    {
      return geometry.coupling();
    }



    template <int dim>
    const Contact::ContactGeometry<dim> &
    ContactNewtonProblem<dim>::contact_geometry() const
    {
      return geometry;
    }



    template <int dim>
    const Physics::SolidOperator<dim> &
    ContactNewtonProblem<dim>::solid() const
    {
      return solid_operator;
    }



    template <int dim>
    const Contact::ContactEnforcement<dim> &
    ContactNewtonProblem<dim>::enforcement() const
    {
      return *contact_enforcement;
    }



    template <int dim>
    const Contact::ContactSurface<dim> &
    ContactNewtonProblem<dim>::secondary_surface() const
    {
      return geometry.coupling().secondary_surface();
    }



    template <int dim>
    const StoredDoFs &
    ContactNewtonProblem<dim>::stored_dofs() const
    {
      return stored_dof_counts;
    }



    template <int dim>
    const ContactSolveTimes &
    ContactNewtonProblem<dim>::times() const
    {
      return solve_times;
    }

    template <int dim>
    const Solvers::LinearSolver::Statistics &
    ContactNewtonProblem<dim>::linear_solver_statistics() const
    {
      return linear_solver.statistics();
    }

    template class ContactNewtonProblem<2>;
    template class ContactNewtonProblem<3>;
  } // namespace Problems
} // namespace Common
