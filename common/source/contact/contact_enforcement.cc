#include <common/contact/contact_assembly.h>
#include <common/contact/contact_enforcement.h>

#include <deal.II/base/mpi.h>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    // Every member function delegates to one of the parts; the algorithms
    // live in the parts' files.

    template <int dim>
    ContactEnforcement<dim>::ContactEnforcement(
      const ContactParameters   &parameters,
      const MortarCoupling<dim> &coupling,
      const double               reference_modulus)
      : coupling(coupling)
      , directions(nodal_normals(coupling))
      , contact_state(directions)
      , normal(create_normal_enforcement<dim>(parameters))
      , friction(create_friction_model<dim>(parameters))
      , policy(parameters, reference_modulus)
    {}



    template <int dim>
    void
    ContactEnforcement<dim>::distribute_rows(const IndexSet &owned_dofs,
                                             const IndexSet &needed_dofs,
                                             const MPI_Comm  communicator)
    {
      const unsigned int                   n = coupling.n_rows();
      std::vector<types::global_dof_index> first_dofs(n);
      std::vector<bool>                    needed(n, false);
      for (unsigned int j = 0; j < n; ++j)
        {
          const auto &dofs = coupling.secondary_surface().node(j).dofs;
          first_dofs[j]    = dofs[0];
          for (const auto dof : dofs)
            needed[j] = needed[j] || needed_dofs.is_element(dof);
        }
      contact_state.distribute(
        RowPartition(first_dofs, needed, owned_dofs, communicator));
    }



    template <int dim>
    const RowPartition &
    ContactEnforcement<dim>::rows() const
    {
      return contact_state.rows();
    }



    template <int dim>
    void
    ContactEnforcement<dim>::count_active()
    {
      n_active_nodes = contact_state.n_closed();
      if (contact_state.rows().is_distributed())
        n_active_nodes =
          Utilities::MPI::sum(n_active_nodes,
                              contact_state.rows().communicator());
    }



    template <int dim>
    void
    ContactEnforcement<dim>::initialize_active_set()
    {
      policy.initialize(node_kinematics(coupling), *friction, contact_state);
      count_active();
      n_accepted_active = n_active_nodes;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::mark_constrained_nodes(
      const AffineConstraints<double> &constraints)
    {
      directions.fix_constrained_components(coupling.secondary_surface(),
                                            constraints);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::commit(const VectorType &u)
    {
      contact_state.commit(node_kinematics(coupling, contact_state.rows(), u));
      n_accepted_active = n_active_nodes;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::update_geometry(
      const std::vector<Tensor<1, dim>> &accepted_relative)
    {
      directions.update_normals(nodal_normals(coupling));
      contact_state.rebase(accepted_relative);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::restore()
    {
      contact_state.restore();
      n_active_nodes = n_accepted_active;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::begin_step()
    {
      policy.begin_step(contact_state);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_sparsity_entries(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const std::vector<bool>         &extra_cells,
      DynamicSparsityPattern          &dsp) const
    {
      add_contact_sparsity(coupling,
                           contact_state.rows(),
                           dof_handler,
                           constraints,
                           extra_cells,
                           dsp);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_constraints(
      AffineConstraints<double>                             &constraints,
      const VectorType                                      &u,
      const typename NormalEnforcement<dim>::GapDerivatives *gap_derivatives,
      TrialCorrections                                      *corrections) const
    {
      normal->add_constraints(coupling,
                              contact_state,
                              u,
                              constraints,
                              gap_derivatives,
                              corrections);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::assemble_friction(
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      const MatrixType                &bulk_matrix,
      const VectorType                &bulk_residual,
      const IndexSet                  &locally_owned,
      MatrixType                      &matrix,
      VectorType                      &residual,
      const TrialCorrections          *corrections) const
    {
      friction->assemble(coupling,
                         contact_state,
                         constraints,
                         u,
                         bulk_matrix,
                         bulk_residual,
                         locally_owned,
                         matrix,
                         residual,
                         corrections);
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::has_friction() const
    {
      return friction->has_friction();
    }



    template <int dim>
    void
    ContactEnforcement<dim>::assemble_penalty(
      const AffineConstraints<double>                       &constraints,
      const VectorType                                      &u,
      const IndexSet                                        &locally_owned,
      MatrixType                                            &matrix,
      VectorType                                            &residual,
      const typename NormalEnforcement<dim>::GapDerivatives *gap_derivatives)
      const
    {
      normal->assemble(coupling,
                       contact_state,
                       constraints,
                       u,
                       locally_owned,
                       matrix,
                       residual,
                       gap_derivatives);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::update_pressures(const VectorType &u,
                                              const VectorType &bulk_residual)
    {
      normal->update_tractions(coupling,
                               u,
                               bulk_residual,
                               friction->has_friction(),
                               contact_state);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::keep_linearized_compression(
      const VectorType &u,
      const VectorType &linearized_residual)
    {
      if (!normal->has_multipliers())
        return;
      const bool                       with_friction = friction->has_friction();
      std::vector<NodeKinematics<dim>> nodes;
      if (with_friction)
        nodes = node_kinematics(coupling, contact_state.rows(), u);
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          if (!contact_state.rows().is_held(j))
            continue;
          NodeState<dim>       &node = contact_state.node(j);
          const MortarRow<dim> &row  = coupling.row(j);
          if (node.status == PointStatus::open || !(row.weight > 0.))
            continue;
          const auto    &dofs = coupling.secondary_surface().node(j).dofs;
          Tensor<1, dim> r;
          for (unsigned int c = 0; c < dim; ++c)
            r[c] = linearized_residual(dofs[c]);
          const double linearized_pressure = (r * row.normal) / row.weight;
          if (node.pressure < 0.)
            node.pressure = std::max(node.pressure, linearized_pressure);
          if (!with_friction || node.status != PointStatus::stick ||
              !nodes[j].paired)
            continue;
          // The stick rule of the active-set update, with either pair of
          // tractions.
          FrictionPoint<dim> point;
          point.slip_increment =
            contact_state.slip_increment(j, nodes[j].relative_displacement);
          point.c = policy.tangential_ncp_constant(nodes[j].mesh_size);
          point.n_free_tangents =
            contact_state.directions().free_tangents(j).size();
          const double gap    = nodes[j].weighted_gap / nodes[j].weight;
          const double c      = policy.ncp_constant(nodes[j].mesh_size);
          const auto   sticks = [&](const double          pressure,
                                  const Tensor<1, dim> &traction) {
            point.traction        = traction;
            point.normal_pressure = std::max(0., pressure - c * gap);
            return friction->closed_status(point).status == PointStatus::stick;
          };
          const Tensor<1, dim> linearized_traction =
            -contact_state.directions().free_tangential_part(j, r) / row.weight;
          if (!sticks(node.pressure, node.tangential_traction) &&
              sticks(linearized_pressure, linearized_traction))
            {
              node.pressure            = linearized_pressure;
              node.tangential_traction = linearized_traction;
            }
        }
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_contact_forces(
      const AffineConstraints<double> &constraints,
      const IndexSet                  &locally_owned,
      VectorType                      &residual) const
    {
      add_traction_forces(coupling,
                          contact_state,
                          constraints,
                          locally_owned,
                          residual);
    }



    template <int dim>
    unsigned int
    ContactEnforcement<dim>::update_active_set(const VectorType &u,
                                               const double      residual,
                                               const bool        one_point)
    {
      const unsigned int n_changed =
        policy.update(node_kinematics(coupling, contact_state.rows(), u),
                      *normal,
                      *friction,
                      contact_state,
                      residual,
                      one_point);
      contact_state.update_ghosts();
      count_active();
      return n_changed;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::restart_cycle_detection()
    {
      policy.restart_history(contact_state);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::begin_linearisation()
    {
      policy.begin_linearisation(contact_state);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::end_linearisation()
    {
      policy.end_linearisation(contact_state);
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::revisits_held_set() const
    {
      return policy.revisits_held_set();
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::is_cycling() const
    {
      return policy.is_cycling();
    }



    template <int dim>
    double
    ContactEnforcement<dim>::complementarity_norm(const VectorType &u) const
    {
      return policy.complementarity_norm(node_kinematics(coupling,
                                                         contact_state.rows(),
                                                         u),
                                         *normal,
                                         *friction,
                                         contact_state);
    }



    template <int dim>
    PointStatus
    ContactEnforcement<dim>::status(const unsigned int j) const
    {
      return contact_state.node(j).status;
    }



    template <int dim>
    const Tensor<1, dim> &
    ContactEnforcement<dim>::tangential_traction(const unsigned int j) const
    {
      return contact_state.node(j).tangential_traction;
    }



    template <int dim>
    Tensor<1, dim>
    ContactEnforcement<dim>::slip_increment(const unsigned int j,
                                            const VectorType  &u) const
    {
      return contact_state.slip_increment(j,
                                          coupling.relative_displacement(j, u));
    }



    template <int dim>
    const Tensor<1, dim> &
    ContactEnforcement<dim>::accumulated_slip(const unsigned int j) const
    {
      return contact_state.accumulated_slip(j);
    }



    template <int dim>
    double
    ContactEnforcement<dim>::pressure(const unsigned int j) const
    {
      return contact_state.node(j).pressure;
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::is_active(const unsigned int j) const
    {
      return contact_state.is_closed(j);
    }



    template <int dim>
    unsigned int
    ContactEnforcement<dim>::n_active() const
    {
      return n_active_nodes;
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::touches_search_edge() const
    {
      return ActiveSetPolicy<dim>::touches_search_edge(coupling, contact_state);
    }



    template <int dim>
    double
    ContactEnforcement<dim>::ncp_constant(const unsigned int j) const
    {
      return policy.ncp_constant(coupling.row(j).mesh_size);
    }



    template <int dim>
    double
    ContactEnforcement<dim>::tangential_ncp_constant(const unsigned int j) const
    {
      return policy.tangential_ncp_constant(coupling.row(j).mesh_size);
    }



    template <int dim>
    const ContactState<dim> &
    ContactEnforcement<dim>::state() const
    {
      return contact_state;
    }



    template <int dim>
    const NormalEnforcement<dim> &
    ContactEnforcement<dim>::normal_enforcement() const
    {
      return *normal;
    }



    template <int dim>
    const FrictionModel<dim> &
    ContactEnforcement<dim>::friction_model() const
    {
      return *friction;
    }



    template <int dim>
    const ActiveSetPolicy<dim> &
    ContactEnforcement<dim>::active_set_policy() const
    {
      return policy;
    }

    template class ContactEnforcement<2>;
    template class ContactEnforcement<3>;
  } // namespace Contact
} // namespace Common
