#include <common/contact/contact_enforcement.h>
#include <common/contact/normal_contact_law.h>

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <limits>
#include <map>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    namespace
    {
      /**
       * DoFs of secondary node j followed by the DoFs of its primary nodes,
       * and the gradient B of the weighted gap with respect to them:
       * -D_j n on the secondary node, M_jk n on primary node k.
       */
      template <int dim>
      void
      gap_gradient(const MortarCoupling<dim>            &coupling,
                   const unsigned int                    j,
                   std::vector<types::global_dof_index> &dofs,
                   Vector<double>                       &B)
      {
        const MortarRow<dim> &row  = coupling.row(j);
        const auto &secondary_node = coupling.secondary_surface().node(j);
        dofs.clear();
        std::vector<double> values;
        for (unsigned int c = 0; c < dim; ++c)
          {
            dofs.push_back(secondary_node.dofs[c]);
            values.push_back(-row.weight * row.normal[c]);
          }
        for (const auto &[k, M] : row.primary_weights)
          for (unsigned int c = 0; c < dim; ++c)
            {
              dofs.push_back(coupling.primary_surface().node(k).dofs[c]);
              values.push_back(M * row.normal[c]);
            }
        B.reinit(values.size());
        for (unsigned int i = 0; i < values.size(); ++i)
          B(i) = values[i];
      }
    } // namespace



    template <int dim>
    ContactEnforcement<dim>::ContactEnforcement(
      const ContactParameters   &parameters,
      const MortarCoupling<dim> &coupling,
      const double               reference_modulus)
      : parameters(parameters)
      , coupling(coupling)
      , reference_modulus(reference_modulus)
      , active(coupling.n_rows(), false)
      , pressures(coupling.n_rows(), 0.)
      , cycling(false)
      , last_update_extrapolated(false)
      , extrapolation_enabled(parameters.accelerate_release)
    {}



    template <int dim>
    double
    ContactEnforcement<dim>::ncp_constant(const unsigned int j) const
    {
      return parameters.ncp_factor * reference_modulus /
             coupling.row(j).mesh_size;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::initialize_active_set()
    {
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          // The weighted gap averages over the node's support and is not
          // zero at a touching node; the pointwise gap is, up to round-off.
          active[j] = row.has_partner && row.nodal_gap <= 1e-8 * row.mesh_size;
        }
      std::fill(pressures.begin(), pressures.end(), 0.);
      commit();
    }



    template <int dim>
    void
    ContactEnforcement<dim>::commit()
    {
      accepted_active    = active;
      accepted_pressures = pressures;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::restore()
    {
      active    = accepted_active;
      pressures = accepted_pressures;
    }



    template <int dim>
    void
    ContactEnforcement<dim>::begin_step()
    {
      history.clear();
      history.push_back(active);
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
      // Primary DoFs coupled to each DoF of a paired secondary node.
      std::map<types::global_dof_index, std::vector<types::global_dof_index>>
        partners;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner)
            continue;
          std::vector<types::global_dof_index> primary_dofs;
          for (const auto &entry : row.primary_weights)
            for (unsigned int e = 0; e < dim; ++e)
              primary_dofs.push_back(
                coupling.primary_surface().node(entry.first).dofs[e]);
          for (unsigned int d = 0; d < dim; ++d)
            partners[coupling.secondary_surface().node(j).dofs[d]] =
              primary_dofs;
        }

      // Each cell's DoFs, closed under the constraints (hanging-node
      // parents) and the contact partners, in any order of chaining: every
      // coupling any active set can create lies in that closure.
      std::vector<types::global_dof_index> cell_dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      std::vector<types::global_dof_index> closure;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(cell_dofs);
            closure.assign(cell_dofs.begin(), cell_dofs.end());
            bool touches_contact = false;
            for (unsigned int n = 0; n < closure.size(); ++n)
              {
                const types::global_dof_index i = closure[n];
                if (const auto *entries = constraints.get_constraint_entries(i))
                  for (const auto &entry : *entries)
                    if (std::find(closure.begin(),
                                  closure.end(),
                                  entry.first) == closure.end())
                      closure.push_back(entry.first);
                const auto it = partners.find(i);
                if (it != partners.end())
                  {
                    touches_contact = true;
                    for (const auto k : it->second)
                      if (std::find(closure.begin(), closure.end(), k) ==
                          closure.end())
                        closure.push_back(k);
                  }
              }
            if (!touches_contact)
              continue;
            std::sort(closure.begin(), closure.end());
            for (const auto i : closure)
              if (dsp.row_index_set().is_element(i))
                dsp.add_entries(i, closure.begin(), closure.end(), true);
          }
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_constraints(
      AffineConstraints<double> &constraints,
      const VectorType          &u) const
    {
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          if (!active[j])
            continue;
          const MortarRow<dim> &row  = coupling.row(j);
          const auto           &node = coupling.secondary_surface().node(j);

          // Solve the linearised condition for the free component with the
          // largest normal share.
          int c = -1;
          for (unsigned int d = 0; d < dim; ++d)
            if (!constraints.is_constrained(node.dofs[d]) &&
                (c < 0 || std::abs(row.normal[d]) > std::abs(row.normal[c])))
              c = d;
          if (c < 0 || std::abs(row.normal[c]) < 1e-6)
            continue;

          // n.(sum_k M_jk du_k - D du_j) = -g(u), solved for du_{j,c}.
          const double scale = 1. / (row.weight * row.normal[c]);
          std::vector<std::pair<types::global_dof_index, double>> entries;
          for (unsigned int e = 0; e < dim; ++e)
            if (e != static_cast<unsigned int>(c) &&
                std::abs(row.normal[e]) > 1e-14)
              entries.emplace_back(node.dofs[e],
                                   -row.normal[e] / row.normal[c]);
          for (const auto &[k, M] : row.primary_weights)
            for (unsigned int e = 0; e < dim; ++e)
              if (std::abs(M * row.normal[e]) > 1e-14 * row.weight)
                entries.emplace_back(coupling.primary_surface().node(k).dofs[e],
                                     M * row.normal[e] * scale);
          constraints.add_line(node.dofs[c]);
          constraints.add_entries(node.dofs[c], entries);
          constraints.set_inhomogeneity(node.dofs[c],
                                        coupling.weighted_gap(j, u) * scale);
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
      std::vector<types::global_dof_index> dofs;
      Vector<double>                       B;
      FullMatrix<double>                   K;
      Vector<double>                       r;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!active[j] || !locally_owned.is_element(
                              coupling.secondary_surface().node(j).dofs[0]))
            continue;
          const double gap = coupling.weighted_gap(j, u) / row.weight;
          const double p =
            NormalContactLaw::penalty_pressure(gap,
                                               parameters.penalty_stiffness);
          const double dp_dgap =
            NormalContactLaw::penalty_derivative(gap,
                                                 parameters.penalty_stiffness);

          gap_gradient(coupling, j, dofs, B);
          K.reinit(dofs.size(), dofs.size());
          r.reinit(dofs.size());
          // Residual f_ext - f_int + p B; tangent -(dp/dg~) B B^T.
          for (unsigned int a = 0; a < dofs.size(); ++a)
            {
              r(a) = p * B(a);
              for (unsigned int b = 0; b < dofs.size(); ++b)
                K(a, b) = -dp_dgap / row.weight * B(a) * B(b);
            }
          constraints.distribute_local_to_global(K, r, dofs, matrix, residual);
        }
    }



    template <int dim>
    void
    ContactEnforcement<dim>::update_pressures(const VectorType &u,
                                              const VectorType &bulk_residual)
    {
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!active[j])
            {
              pressures[j] = 0.;
              continue;
            }
          if (parameters.enforcement == Enforcement::penalty)
            pressures[j] =
              NormalContactLaw::penalty_pressure(coupling.weighted_gap(j, u) /
                                                   row.weight,
                                                 parameters.penalty_stiffness);
          else
            {
              const auto &node = coupling.secondary_surface().node(j);
              double      rn   = 0.;
              for (unsigned int c = 0; c < dim; ++c)
                rn += bulk_residual(node.dofs[c]) * row.normal[c];
              pressures[j] = rn / row.weight;
            }
        }
    }



    template <int dim>
    void
    ContactEnforcement<dim>::add_contact_forces(const IndexSet &locally_owned,
                                                VectorType     &residual) const
    {
      std::vector<types::global_dof_index> dofs;
      Vector<double>                       B;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        if (pressures[j] != 0. &&
            locally_owned.is_element(
              coupling.secondary_surface().node(j).dofs[0]))
          {
            gap_gradient(coupling, j, dofs, B);
            B *= pressures[j];
            residual.add(dofs, B);
          }
    }



    template <int dim>
    unsigned int
    ContactEnforcement<dim>::update_active_set(const VectorType &u)
    {
      const unsigned int n = coupling.n_rows();
      std::vector<bool>  next(n, false);
      unsigned int       n_closed = 0, n_opened = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner)
            continue;
          const double gap = coupling.weighted_gap(j, u) / row.weight;
          next[j] =
            (parameters.enforcement == Enforcement::penalty ?
               NormalContactLaw::penalty_derivative(
                 gap,
                 parameters.penalty_stiffness) != 0. :
               NormalContactLaw::is_active(pressures[j], gap, ncp_constant(j)));
          n_closed += (next[j] && !active[j]);
          n_opened += (!next[j] && active[j]);
        }

      if (n_closed > 0 && last_update_extrapolated)
        extrapolation_enabled = false;
      last_update_extrapolated = false;

      if (extrapolation_enabled && n_closed == 0 && n_opened > 0)
        {
          const auto               &surface = coupling.secondary_surface();
          std::vector<unsigned int> opened, kept;
          for (unsigned int j = 0; j < n; ++j)
            if (active[j] && !next[j])
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

      // A set seen before in this step means ping-pong (typically a corner
      // and a mid-side node of a Q2 face trading places at the contact
      // edge). Then change only the point with the largest complementarity
      // violation whose change leads to a set not seen yet.
      const auto seen = [this](const std::vector<bool> &set) {
        return std::find(history.begin(), history.end(), set) != history.end();
      };
      cycling = false;
      if (next != active && seen(next))
        {
          extrapolation_enabled = false;
          std::vector<std::pair<double, unsigned int>> violations;
          for (unsigned int j = 0; j < n; ++j)
            if (next[j] != active[j])
              {
                const MortarRow<dim> &row = coupling.row(j);
                violations.emplace_back(
                  std::abs(NormalContactLaw::complementarity(
                    pressures[j],
                    coupling.weighted_gap(j, u) / row.weight,
                    ncp_constant(j))) *
                    row.weight,
                  j);
              }
          std::sort(violations.rbegin(), violations.rend());
          cycling = true;
          for (const auto &[violation, j] : violations)
            {
              std::vector<bool> single = active;
              single[j]                = !single[j];
              if (!seen(single))
                {
                  next    = single;
                  cycling = false;
                  break;
                }
            }
        }

      unsigned int n_changed = 0;
      for (unsigned int j = 0; j < n; ++j)
        n_changed += (next[j] != active[j]);
      active = next;
      history.push_back(active);
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
      if (parameters.enforcement == Enforcement::penalty)
        return 0.;
      double sum = 0.;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner)
            continue;
          const double C =
            NormalContactLaw::complementarity(pressures[j],
                                              coupling.weighted_gap(j, u) /
                                                row.weight,
                                              ncp_constant(j));
          sum += std::pow(C * row.weight, 2);
        }
      return std::sqrt(sum);
    }



    template <int dim>
    double
    ContactEnforcement<dim>::pressure(const unsigned int j) const
    {
      return pressures[j];
    }



    template <int dim>
    bool
    ContactEnforcement<dim>::is_active(const unsigned int j) const
    {
      return active[j];
    }



    template <int dim>
    unsigned int
    ContactEnforcement<dim>::n_active() const
    {
      return std::count(active.begin(), active.end(), true);
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
              any_active   = any_active || active[j];
              any_unpaired = any_unpaired || !coupling.row(j).has_partner;
            }
          if (any_active && any_unpaired)
            return true;
        }
      return false;
    }

    template class ContactEnforcement<2>;
    template class ContactEnforcement<3>;
  } // namespace Contact
} // namespace Common
