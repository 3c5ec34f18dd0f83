#include <common/contact/contact_assembly.h>
#include <common/contact/contact_enforcement.h>
#include <common/contact/coulomb_law.h>

#include <deal.II/lac/full_matrix.h>

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
      return parameters.friction_law == FrictionLaw::coulomb &&
             parameters.friction_coefficient > 0.;
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
          // A touching node has no slip history: it starts in stick.
          status[j] = (!touching      ? PointStatus::open :
                       has_friction() ? PointStatus::stick :
                                        PointStatus::slip);
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
        status[nearest] =
          has_friction() ? PointStatus::stick : PointStatus::slip;
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
      if (!has_friction())
        return;
      const double                         mu = parameters.friction_coefficient;
      std::vector<types::global_dof_index> B_dofs;
      Vector<double>                       B;
      std::map<types::global_dof_index, double> stiffness_row;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const auto &node = coupling.secondary_surface().node(j);
          if (contact_state.node(j).status != PointStatus::slip ||
              directions.free_tangents(j).empty() ||
              !locally_owned.is_element(node.dofs[0]))
            continue;
          const MortarRow<dim> &row = coupling.row(j);

          // lambda_j(u) = n.r_j(u)/D_j and its gradient -n^T K_j / D_j.
          double rn = 0.;
          stiffness_row.clear();
          for (unsigned int c = 0; c < dim; ++c)
            {
              Assert(locally_owned.is_element(node.dofs[c]),
                     ExcInternalError());
              rn += bulk_residual(node.dofs[c]) * row.normal[c];
              if (row.normal[c] == 0.)
                continue;
              // end() once: a Trilinos row iterator copies its row when
              // it is made.
              const auto end = bulk_matrix.end(node.dofs[c]);
              for (auto entry = bulk_matrix.begin(node.dofs[c]); entry != end;
                   ++entry)
                stiffness_row[entry->column()] +=
                  row.normal[c] * entry->value();
            }
          const double pressure = rn / row.weight;

          // Force -mu lambda B_e: D mu lambda e on the secondary node, its
          // reaction on the primary nodes. Tangent -(mu/D) B_e (n^T K_j).
          const Tensor<1, dim> &e = contact_state.node(j).slip_direction;
          gap_gradient(coupling, j, e, B_dofs, B);
          std::vector<types::global_dof_index> dofs = B_dofs;
          for (const auto &entry : stiffness_row)
            if (std::find(B_dofs.begin(), B_dofs.end(), entry.first) ==
                B_dofs.end())
              dofs.push_back(entry.first);
          // Only the rows of B's DoFs are non-zero: a rectangular block.
          FullMatrix<double> K(B_dofs.size(), dofs.size());
          Vector<double>     r(B_dofs.size());
          for (unsigned int a = 0; a < B_dofs.size(); ++a)
            {
              r(a) = -mu * pressure * B(a);
              for (unsigned int b = 0; b < dofs.size(); ++b)
                {
                  const auto it = stiffness_row.find(dofs[b]);
                  if (it != stiffness_row.end())
                    K(a, b) = -mu / row.weight * B(a) * it->second;
                }
            }
          // In 3D the traction turns: across e, along t2 = n x e, the
          // traction of the next iterate is k v.t2 (slip_linearisation()),
          // a force -k (v.t2) B_t2 with v.t2 = B_t2 . u / D + const and
          // tangent (k/D) B_t2 B_t2^T. (In 2D the tangent line holds e
          // alone.)
          if constexpr (dim == 3)
            if (contact_state.node(j).turning_stiffness > 0.)
              {
                Tensor<1, dim> t2 = cross_product_3d(row.normal, e);
                t2 /= t2.norm();
                std::vector<types::global_dof_index> t2_dofs;
                Vector<double>                       B_t2;
                gap_gradient(coupling, j, t2, t2_dofs, B_t2);
                Assert(t2_dofs == B_dofs, ExcInternalError());
                const double k = contact_state.node(j).turning_stiffness;
                const double traction_t2 = k * (slip_increment(j, u) * t2);
                for (unsigned int a = 0; a < B_t2.size(); ++a)
                  {
                    r(a) -= traction_t2 * B_t2(a);
                    for (unsigned int b = 0; b < B_t2.size(); ++b)
                      K(a, b) += k / row.weight * B_t2(a) * B_t2(b);
                  }
              }
          // As the square distribute_local_to_global() with matrix and
          // vector: the inhomogeneities of constrained columns move to the
          // right-hand side, then rows and columns are condensed.
          for (unsigned int b = 0; b < dofs.size(); ++b)
            if (constraints.is_inhomogeneously_constrained(dofs[b]))
              {
                const double g = constraints.get_inhomogeneity(dofs[b]);
                for (unsigned int a = 0; a < B_dofs.size(); ++a)
                  r(a) -= K(a, b) * g;
              }
          constraints.distribute_local_to_global(K, B_dofs, dofs, matrix);
          constraints.distribute_local_to_global(r, B_dofs, residual);
        }
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
      Tensor<1, dim> C_t;
      if (has_friction() && !directions.free_tangents(j).empty())
        C_t = CoulombLaw::complementarity(
          contact_state.node(j).tangential_traction,
          slip_increment(j, u),
          parameters.friction_coefficient *
            std::max(0., contact_state.node(j).pressure - c * gap),
          tangential_ncp_constant(j));
      return {C_n, C_t};
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
          if (!has_friction())
            {
              proposed[j].status = PointStatus::slip;
              continue;
            }
          if (directions.free_tangents(j).empty())
            {
              proposed[j].status = PointStatus::stick;
              continue;
            }
          const MortarRow<dim> &row = coupling.row(j);
          const double          c   = ncp_constant(j);
          const double          bound =
            parameters.friction_coefficient *
            std::max(0.,
                     contact_state.node(j).pressure -
                       c * coupling.weighted_gap(j, u) / row.weight);
          const Tensor<1, dim> v   = slip_increment(j, u);
          const double         c_t = tangential_ncp_constant(j);
          if (CoulombLaw::is_sticking(contact_state.node(j).tangential_traction,
                                      v,
                                      bound,
                                      c_t))
            proposed[j].status = PointStatus::stick;
          else
            {
              proposed[j].status = PointStatus::slip;
              const auto step    = CoulombLaw::slip_linearisation(
                contact_state.node(j).tangential_traction,
                v,
                bound,
                c_t);
              proposed[j].slip_direction = step.direction;
              // Bounded, so that a point just past the stick limit does not
              // make the tangent ill-conditioned; the converged state does
              // not depend on k.
              // Only a node free to slip in the whole tangent plane turns.
              if (directions.free_tangents(j).size() == dim - 1)
                proposed[j].turning_stiffness =
                  std::min(step.turning_stiffness, 1e3 * c_t);
            }
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

    template class ContactEnforcement<2>;
    template class ContactEnforcement<3>;
  } // namespace Contact
} // namespace Common
