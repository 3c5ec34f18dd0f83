#include <common/io/timer.h>
#include <common/physics/rigid_body.h>
#include <common/problems/small_strain_contact_problem.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <chrono>

namespace Common
{
  namespace Problems
  {
    using namespace dealii;

    template <int dim>
    SmallStrainContactProblem<dim>::SmallStrainContactProblem(
      const DoFHandler<dim>                    &dof_handler,
      const Mapping<dim>                       &mapping,
      Physics::SmallStrainElasticity<dim>      &physics,
      const Contact::ContactParameters         &contact,
      const Solvers::LinearSolverParameters    &linear_solver,
      const Solvers::NonlinearSolverParameters &nonlinear_solver,
      const double                              reference_modulus,
      const MPI_Comm                            mpi_communicator)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , physics(physics)
      , contact_parameters(contact)
      , nonlinear_solver_parameters(nonlinear_solver)
      , reference_modulus(reference_modulus)
      , mpi_communicator(mpi_communicator)
      , linear_solver(linear_solver)
    {}



    // Small strain: the contact geometry is evaluated once, in the
    // reference configuration. One sparsity pattern serves every active
    // set: it holds the couplings that any closed node's constraint (or
    // penalty term) can create.
    template <int dim>
    void
    SmallStrainContactProblem<dim>::setup(
      const AffineConstraints<double> &base_constraints)
    {
      locally_owned_dofs    = dof_handler.locally_owned_dofs();
      locally_relevant_dofs = complete_index_set(dof_handler.n_dofs());
      constraints_dirichlet_and_hanging_nodes.clear();
      constraints_dirichlet_and_hanging_nodes.reinit(locally_relevant_dofs);
      constraints_dirichlet_and_hanging_nodes.merge(base_constraints);
      constraints_dirichlet_and_hanging_nodes.close();

      solution.reinit(locally_owned_dofs,
                      locally_relevant_dofs,
                      mpi_communicator);
      solution_owned.reinit(locally_owned_dofs, mpi_communicator);
      accepted_solution.reinit(locally_owned_dofs, mpi_communicator);
      newton_update.reinit(locally_owned_dofs, mpi_communicator);
      system_rhs.reinit(locally_owned_dofs, mpi_communicator);
      residual_vector.reinit(locally_owned_dofs,
                             locally_relevant_dofs,
                             mpi_communicator);

      const auto start = std::chrono::steady_clock::now();
      secondary        = std::make_unique<Contact::ContactSurface<dim>>(
        dof_handler,
        mapping,
        contact_parameters.secondary_boundary_id);
      primary = std::make_unique<Contact::ContactSurface<dim>>(
        dof_handler,
        mapping,
        contact_parameters.primary_boundary_id);
      search = std::make_unique<Contact::ContactSearch<dim>>(*primary, 0.);
      mortar.reinit(*secondary,
                    *primary,
                    *search,
                    contact_parameters.search_distance,
                    physics.kinematics() == Physics::Kinematics::axisymmetric);
      mortar.condense_hanging_nodes(constraints_dirichlet_and_hanging_nodes);
      contact_enforcement =
        std::make_unique<Contact::ContactEnforcement<dim>>(contact_parameters,
                                                           mortar,
                                                           reference_modulus);
      contact_enforcement->mark_constrained_nodes(
        constraints_dirichlet_and_hanging_nodes);
      contact_enforcement->initialize_active_set();
      solve_times.contact_setup = IO::seconds_since(start);

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
        dsp);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 locally_owned_dofs,
                                                 mpi_communicator,
                                                 locally_relevant_dofs);
      system_matrix.reinit(locally_owned_dofs,
                           locally_owned_dofs,
                           dsp,
                           mpi_communicator);
      linear_solver.reset();
      if (linear_solver.uses_multigrid())
        linear_solver.set_near_null_space(
          Physics::rigid_body_modes(mapping,
                                    dof_handler,
                                    physics.kinematics() !=
                                      Physics::Kinematics::axisymmetric),
          dim);

      if (contact_enforcement->has_friction())
        {
          bulk_matrix.reinit(system_matrix);
          TrilinosWrappers::MPI::Vector unused(locally_owned_dofs,
                                               mpi_communicator);
          physics.assemble_system(dof_handler,
                                  constraints_dirichlet_and_hanging_nodes,
                                  solution,
                                  bulk_matrix,
                                  unused);
          bulk_matrix.compress(VectorOperation::add);
        }
    }



    // One semismooth Newton iteration: Dirichlet and hanging-node
    // constraints and, for Lagrange multipliers, one condensed constraint
    // per closed node (two for a sticking one); bulk tangent and residual;
    // external load; friction or penalty terms if selected.
    template <int dim>
    double
    SmallStrainContactProblem<dim>::assemble_and_solve(const double load_factor,
                                                       const ExternalLoad &load)
    {
      const auto start = std::chrono::steady_clock::now();
      if (contact_enforcement->has_friction())
        compute_bulk_residual(load_factor, load);
      constraints.clear();
      constraints.reinit(locally_relevant_dofs);
      constraints.merge(constraints_dirichlet_and_hanging_nodes);
      if (load.prescribed_displacements)
        {
          std::map<types::global_dof_index, double> values;
          load.prescribed_displacements(load_factor, values);
          for (const auto &[dof, value] : values)
            {
              AssertThrow(constraints.is_constrained(dof),
                          ExcMessage("A prescribed displacement acts on a "
                                     "DoF without a Dirichlet constraint."));
              constraints.set_inhomogeneity(dof, value - solution(dof));
            }
        }
      if (contact_parameters.enforcement ==
          Contact::Enforcement::lagrange_multiplier)
        contact_enforcement->add_constraints(constraints, solution);
      constraints.close();

      system_matrix = 0.;
      system_rhs    = 0.;
      physics.assemble_system(dof_handler,
                              constraints,
                              solution,
                              system_matrix,
                              system_rhs);
      load.add(load_factor, constraints, system_rhs);
      if (contact_parameters.enforcement == Contact::Enforcement::penalty)
        contact_enforcement->assemble_penalty(constraints,
                                              solution,
                                              locally_owned_dofs,
                                              system_matrix,
                                              system_rhs);
      contact_enforcement->assemble_friction(constraints,
                                             solution,
                                             bulk_matrix,
                                             residual_vector,
                                             locally_owned_dofs,
                                             system_matrix,
                                             system_rhs);
      system_matrix.compress(VectorOperation::add);
      system_rhs.compress(VectorOperation::add);
      solve_times.assembly += IO::seconds_since(start);

      const auto solve_start = std::chrono::steady_clock::now();
      newton_update          = 0.;
      linear_solver.solve(system_matrix, newton_update, system_rhs);
      constraints.distribute(newton_update);
      solve_times.linear_solve += IO::seconds_since(solve_start);
      solution_owned += newton_update;
      solution                  = solution_owned;
      const double update_norm  = newton_update.l2_norm();
      const double current_norm = solution_owned.l2_norm();
      return current_norm > 0. ? update_norm / current_norm :
                                 (update_norm > 0. ? 1. : 0.);
    }



    template <int dim>
    TrilinosWrappers::MPI::Vector
    SmallStrainContactProblem<dim>::compute_bulk_residual(
      const double        load_factor,
      const ExternalLoad &load)
    {
      // f_ext - f_int condensed as the linear system is: hanging-node
      // forces on their parents (a secondary node may be one), Dirichlet
      // rows zero (support reactions are no contact tractions).
      TrilinosWrappers::MPI::Vector r(locally_owned_dofs, mpi_communicator);
      physics.assemble_internal_force(dof_handler,
                                      constraints_dirichlet_and_hanging_nodes,
                                      solution,
                                      r);
      r.compress(VectorOperation::add);
      r *= -1.;
      load.add(load_factor, constraints_dirichlet_and_hanging_nodes, r);
      r.compress(VectorOperation::add);
      residual_vector = r;
      return r;
    }



    // Residuals of the updated state, relative to the load: equilibrium
    // including the contact forces of the recovered tractions, and the
    // normal and tangential complementarity functions.
    template <int dim>
    Solvers::NewtonResidual
    SmallStrainContactProblem<dim>::evaluate_residual(const double load_factor,
                                                      const ExternalLoad &load)
    {
      const auto start = std::chrono::steady_clock::now();
      // A compressed vector: contact forces are added on the ranks that own
      // contact nodes only, and the final compress() is the one collective
      // step.
      TrilinosWrappers::MPI::Vector r =
        compute_bulk_residual(load_factor, load);

      contact_enforcement->update_pressures(solution, residual_vector);
      contact_enforcement->add_contact_forces(
        constraints_dirichlet_and_hanging_nodes,
        locally_owned_dofs,
        r);
      r.compress(VectorOperation::add);
      constraints_dirichlet_and_hanging_nodes.set_zero(r);

      const double            scale = load.magnitude(load_factor);
      Solvers::NewtonResidual residual;
      residual.equilibrium = r.l2_norm() / scale;
      residual.complementarity =
        contact_enforcement->complementarity_norm(solution) / scale;
      solve_times.residual += IO::seconds_since(start);
      return residual;
    }



    template <int dim>
    Solvers::NewtonStatistics
    SmallStrainContactProblem<dim>::solve(const double        load_factor,
                                          const ExternalLoad &load,
                                          ConditionalOStream &verbose)
    {
      const auto start = std::chrono::steady_clock::now();
      contact_enforcement->begin_step();
      Solvers::NewtonCallbacks callbacks;
      callbacks.assemble_solve_and_update = [&]() {
        return assemble_and_solve(load_factor, load);
      };
      callbacks.evaluate_residual = [&]() {
        return evaluate_residual(load_factor, load);
      };
      callbacks.update_active_set = [&]() {
        const auto         t = std::chrono::steady_clock::now();
        const unsigned int n_changed =
          contact_enforcement->update_active_set(solution);
        solve_times.active_set_update += IO::seconds_since(t);
        return n_changed;
      };
      callbacks.is_cycling = [&]() {
        return contact_enforcement->is_cycling();
      };

      const auto statistics =
        Solvers::solve_newton(nonlinear_solver_parameters, callbacks, verbose);
      solve_times.newton += IO::seconds_since(start);
      return statistics;
    }



    template <int dim>
    void
    SmallStrainContactProblem<dim>::commit()
    {
      accepted_solution = solution_owned;
      contact_enforcement->commit(solution);
    }



    template <int dim>
    void
    SmallStrainContactProblem<dim>::restore()
    {
      solution_owned = accepted_solution;
      solution       = solution_owned;
      contact_enforcement->restore();
    }



    template <int dim>
    double
    SmallStrainContactProblem<dim>::time_fixed_active_set_solve(
      const double        load_factor,
      const ExternalLoad &load)
    {
      const TrilinosWrappers::MPI::Vector converged = solution_owned;
      const ContactSolveTimes             kept      = solve_times;
      physics.clear();
      linear_solver.reset();
      const auto start = std::chrono::steady_clock::now();
      assemble_and_solve(load_factor, load);
      const double time = IO::seconds_since(start);
      solution_owned    = converged;
      solution          = solution_owned;
      solve_times       = kept;
      return time;
    }



    template <int dim>
    const TrilinosWrappers::MPI::Vector &
    SmallStrainContactProblem<dim>::displacement() const
    {
      return solution;
    }



    template <int dim>
    const TrilinosWrappers::MPI::Vector &
    SmallStrainContactProblem<dim>::bulk_residual() const
    {
      return residual_vector;
    }



    template <int dim>
    const Contact::MortarCoupling<dim> &
    SmallStrainContactProblem<dim>::coupling() const
    {
      return mortar;
    }



    template <int dim>
    const Contact::ContactEnforcement<dim> &
    SmallStrainContactProblem<dim>::enforcement() const
    {
      return *contact_enforcement;
    }



    template <int dim>
    const Contact::ContactSurface<dim> &
    SmallStrainContactProblem<dim>::secondary_surface() const
    {
      return *secondary;
    }



    template <int dim>
    const ContactSolveTimes &
    SmallStrainContactProblem<dim>::times() const
    {
      return solve_times;
    }

    template class SmallStrainContactProblem<2>;
    template class SmallStrainContactProblem<3>;
  } // namespace Problems
} // namespace Common
