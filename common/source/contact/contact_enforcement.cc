#include <common/contact/contact_assembly.h>
#include <common/contact/contact_enforcement.h>

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    ContactEnforcement<dim>::ContactEnforcement(
      const ContactParameters   &parameters,
      const MortarCoupling<dim> &coupling,
      const double               reference_modulus)
      : parameters(parameters)
      , coupling(coupling)
      , reference_modulus(reference_modulus)
      , directions(nodal_normals(coupling))
      , contact_state(directions)
      , normal(create_normal_enforcement<dim>(parameters))
      , friction(create_friction_model<dim>(parameters))
      , cycling(false)
      , last_update_extrapolated(false)
      , extrapolation_enabled(parameters.accelerate_release)
    {}



    template <int dim>
    void
    ContactEnforcement<dim>::mark_constrained_nodes(
      const AffineConstraints<double> &constraints)
    {
      directions.fix_constrained_components(coupling.secondary_surface(),
                                            constraints);
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::has_friction() const
    {
      return friction->has_friction();
    }



    template <int dim>
    double
    ContactEnforcement<dim>::ncp_constant(const unsigned int j) const
    {
      return parameters.ncp_factor * reference_modulus /
             coupling.row(j).mesh_size;
    }



    template <int dim>
    double
    ContactEnforcement<dim>::tangential_ncp_constant(const unsigned int j) const
    {
      return parameters.tangential_ncp_factor * reference_modulus /
             coupling.row(j).mesh_size;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::initialize_active_set()
    {
      const unsigned int       n = coupling.n_rows();
      std::vector<PointStatus> status(n, PointStatus::open);
      for (unsigned int j = 0; j < n; ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          // The weighted gap averages over the node's support and is not
          // zero at a touching node; the pointwise gap is, up to round-off.
          const bool touching =
            row.has_partner && row.nodal_gap <= 1e-8 * row.mesh_size;
          status[j] =
            touching ? friction->status_on_contact() : PointStatus::open;
        }
      // Close the nearest node that carries a multiplier if no touching
      // one does (every rank holds every row, so all decide alike).
      unsigned int nearest = numbers::invalid_unsigned_int;
      bool         held    = false;
      for (unsigned int j = 0; j < n; ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner || row.weight <= 0.)
            continue;
          held = held || status[j] != PointStatus::open;
          if (nearest == numbers::invalid_unsigned_int ||
              row.nodal_gap < coupling.row(nearest).nodal_gap)
            nearest = j;
        }
      if (!held && nearest != numbers::invalid_unsigned_int)
        status[nearest] = friction->status_on_contact();
      contact_state.reset(status);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::commit(const VectorType &u)
    {
      contact_state.commit(node_kinematics(coupling, u));
    }



    template <int dim>
    void
    ContactEnforcement<dim>::restore()
    {
      contact_state.restore();
    }



    template <int dim>
    void
    ContactEnforcement<dim>::begin_step()
    {
      std::vector<NodeState<dim>> nodes(coupling.n_rows());
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        nodes[j] = contact_state.node(j);
      history.clear();
      history.push_back(codes(nodes));
      cycling                  = false;
      last_update_extrapolated = false;
      extrapolation_enabled    = parameters.accelerate_release;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_sparsity_entries(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      DynamicSparsityPattern          &dsp) const
    {
      add_contact_sparsity(coupling, dof_handler, constraints, dsp);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_constraints(
      AffineConstraints<double> &constraints,
      const VectorType          &u) const
    {
      normal->add_constraints(coupling, contact_state, u, constraints);
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
      VectorType                      &residual) const
    {
      friction->assemble(coupling,
                         contact_state,
                         constraints,
                         u,
                         bulk_matrix,
                         bulk_residual,
                         locally_owned,
                         matrix,
                         residual);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::assemble_penalty(
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      const IndexSet                  &locally_owned,
      MatrixType                      &matrix,
      VectorType                      &residual) const
    {
      normal->assemble(coupling,
                       contact_state,
                       constraints,
                       u,
                       locally_owned,
                       matrix,
                       residual);
    }



    template <int dim>
    void
    ContactEnforcement<dim>::update_pressures(const VectorType &u,
                                              const VectorType &bulk_residual)
    {
      normal->update_tractions(coupling,
                               u,
                               bulk_residual,
                               has_friction(),
                               contact_state);
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
    Tensor<1, dim>
    ContactEnforcement<dim>::slip_increment(const unsigned int j,
                                            const VectorType  &u) const
    {
      return contact_state.slip_increment(j,
                                          coupling.relative_displacement(j, u));
    }



    template <int dim>
    std::pair<double, Tensor<1, dim>>
    ContactEnforcement<dim>::complementarity(const unsigned int j,
                                             const VectorType  &u) const
    {
      const MortarRow<dim> &row = coupling.row(j);
      const double          gap = coupling.weighted_gap(j, u) / row.weight;
      const double          c   = ncp_constant(j);
      const double          C_n =
        directions.normally_free(j) ?
                   normal->complementarity(contact_state.node(j).pressure, gap, c) :
                   0.;
      FrictionPoint<dim> point;
      point.traction       = contact_state.node(j).tangential_traction;
      point.slip_increment = slip_increment(j, u);
      point.normal_pressure =
        std::max(0., contact_state.node(j).pressure - c * gap);
      point.c               = tangential_ncp_constant(j);
      point.n_free_tangents = directions.free_tangents(j).size();
      return {C_n, friction->complementarity(point)};
    }



    template <int dim>
    double
    ContactEnforcement<dim>::violation(const unsigned int j,
                                       const VectorType  &u) const
    {
      const auto [C_n, C_t] = complementarity(j, u);
      return (std::abs(C_n) + C_t.norm()) * coupling.row(j).weight;
    }



    template <int dim>
    std::vector<int>
    ContactEnforcement<dim>::codes(
      const std::vector<NodeState<dim>> &nodes) const
    {
      std::vector<int> result(nodes.size());
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          const NodeState<dim> &s             = nodes[j];
          const auto           &free_tangents = directions.free_tangents(j);
          result[j]                           = static_cast<int>(s.status);
          // Along a single free tangent (2D, or a symmetry plane in 3D)
          // the slip direction is one of its two senses.
          if (free_tangents.size() == 1 && s.status == PointStatus::slip &&
              s.slip_direction.norm() > 0.)
            result[j] += (s.slip_direction * free_tangents[0] < 0. ? 10 : 0);
        }
      return result;
    }



    template <int dim>
    unsigned int
    ContactEnforcement<dim>::update_active_set(const VectorType &u)
    {
      const unsigned int n = coupling.n_rows();
      std::vector<bool>  closed(n, false), next(n, false);
      unsigned int       n_closed = 0, n_opened = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          closed[j] = (contact_state.node(j).status != PointStatus::open);
          if (!row.has_partner)
            continue;
          const double gap = coupling.weighted_gap(j, u) / row.weight;
          next[j]          = normal->is_closed(contact_state.node(j).pressure,
                                      gap,
                                      ncp_constant(j));
          n_closed += (next[j] && !closed[j]);
          n_opened += (!next[j] && closed[j]);
        }

      if (n_closed > 0 && last_update_extrapolated)
        extrapolation_enabled = false;
      last_update_extrapolated = false;

      if (extrapolation_enabled && n_closed == 0 && n_opened > 0)
        {
          const auto               &surface = coupling.secondary_surface();
          std::vector<unsigned int> opened, kept;
          for (unsigned int j = 0; j < n; ++j)
            if (closed[j] && !next[j])
              opened.push_back(j);
            else if (next[j])
              kept.push_back(j);
          // Distance of each opened node to the closed set.
          std::vector<double> band(opened.size(),
                                   std::numeric_limits<double>::max());
          for (unsigned int r = 0; r < opened.size(); ++r)
            for (const unsigned int j : kept)
              band[r] = std::min(band[r],
                                 surface.node(opened[r]).position.distance(
                                   surface.node(j).position));
          std::vector<unsigned int> also_opened;
          for (const unsigned int j : kept)
            for (unsigned int r = 0; r < opened.size(); ++r)
              if (surface.node(j).position.distance(
                    surface.node(opened[r]).position) <
                  2. * band[r] * (1. - 1e-10))
                {
                  also_opened.push_back(j);
                  break;
                }
          // Never open the whole zone: keep the plain step then.
          if (!kept.empty() && also_opened.size() < kept.size())
            {
              for (const unsigned int j : also_opened)
                next[j] = false;
              last_update_extrapolated = !also_opened.empty();
            }
        }

      // Stick or slip for the closed nodes.
      std::vector<NodeState<dim>> current(n);
      for (unsigned int j = 0; j < n; ++j)
        current[j] = contact_state.node(j);
      std::vector<NodeState<dim>> proposed = current;
      for (unsigned int j = 0; j < n; ++j)
        {
          proposed[j].slip_direction    = Tensor<1, dim>();
          proposed[j].turning_stiffness = 0.;
          if (!next[j])
            {
              proposed[j].status = PointStatus::open;
              continue;
            }
          const MortarRow<dim> &row = coupling.row(j);
          const double          c   = ncp_constant(j);
          FrictionPoint<dim>    point;
          point.traction       = contact_state.node(j).tangential_traction;
          point.slip_increment = slip_increment(j, u);
          point.normal_pressure =
            std::max(0.,
                     contact_state.node(j).pressure -
                       c * coupling.weighted_gap(j, u) / row.weight);
          point.c               = tangential_ncp_constant(j);
          point.n_free_tangents = directions.free_tangents(j).size();
          const FrictionStatus<dim> tangential = friction->closed_status(point);
          proposed[j].status                   = tangential.status;
          proposed[j].slip_direction           = tangential.slip_direction;
          proposed[j].turning_stiffness        = tangential.turning_stiffness;
        }

      // A set seen before in this step means ping-pong (typically a corner
      // and a mid-side node of a Q2 face trading places at the contact
      // edge, or a node at the stick-slip boundary). Then change only the
      // point with the largest complementarity violation whose change
      // leads to a set not seen yet.
      const std::vector<int> current_codes = codes(current);
      std::vector<int>       next_codes    = codes(proposed);
      const auto             seen = [this](const std::vector<int> &set) {
        return std::find(history.begin(), history.end(), set) != history.end();
      };
      cycling = false;
      if (next_codes != current_codes && seen(next_codes))
        {
          extrapolation_enabled = false;
          std::vector<std::pair<double, unsigned int>> violations;
          for (unsigned int j = 0; j < n; ++j)
            if (next_codes[j] != current_codes[j])
              violations.emplace_back(violation(j, u), j);
          std::sort(violations.rbegin(), violations.rend());
          cycling = true;
          for (const auto &[size, j] : violations)
            {
              std::vector<int> single = current_codes;
              single[j]               = next_codes[j];
              if (!seen(single))
                {
                  std::vector<NodeState<dim>> one = current;
                  one[j].status                   = proposed[j].status;
                  one[j].slip_direction           = proposed[j].slip_direction;
                  one[j].turning_stiffness = proposed[j].turning_stiffness;
                  proposed                 = one;
                  next_codes               = single;
                  cycling                  = false;
                  break;
                }
            }
        }

      unsigned int n_changed = 0;
      for (unsigned int j = 0; j < n; ++j)
        n_changed += (next_codes[j] != current_codes[j]);
      // In 3D a slip direction may turn without changing the code.
      for (unsigned int j = 0; j < n; ++j)
        {
          NodeState<dim> &node   = contact_state.node(j);
          node.status            = proposed[j].status;
          node.slip_direction    = proposed[j].slip_direction;
          node.turning_stiffness = proposed[j].turning_stiffness;
        }
      history.push_back(next_codes);
      return n_changed;
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::is_cycling() const
    {
      return cycling;
    }



    template <int dim>
    double
    ContactEnforcement<dim>::complementarity_norm(const VectorType &u) const
    {
      if (!normal->has_multipliers())
        return 0.;
      double sum = 0.;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner)
            continue;
          const auto [C_n, C_t] = complementarity(j, u);
          sum += (C_n * C_n + C_t.norm_square()) * row.weight * row.weight;
        }
      return std::sqrt(sum);
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
      return contact_state.node(j).status != PointStatus::open;
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
    const Tensor<1, dim> &
    ContactEnforcement<dim>::accumulated_slip(const unsigned int j) const
    {
      return contact_state.accumulated_slip(j);
    }



    template <int dim>
    unsigned int
    ContactEnforcement<dim>::n_active() const
    {
      return contact_state.n_closed();
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::touches_search_edge() const
    {
      const auto &surface = coupling.secondary_surface();
      for (unsigned int f = 0; f < surface.n_faces(); ++f)
        {
          bool any_active = false, any_unpaired = false;
          for (const unsigned int j : surface.face(f).nodes)
            {
              any_active =
                any_active || contact_state.node(j).status != PointStatus::open;
              // A node without measure (on the axis) bounds no search.
              any_unpaired = any_unpaired || (!coupling.row(j).has_partner &&
                                              coupling.row(j).weight > 0.);
            }
          if (any_active && any_unpaired)
            return true;
        }
      return false;
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

    template class ContactEnforcement<2>;
    template class ContactEnforcement<3>;
  } // namespace Contact
} // namespace Common
