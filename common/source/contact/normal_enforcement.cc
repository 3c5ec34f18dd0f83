#include <common/contact/contact_assembly.h>
#include <common/contact/normal_contact_law.h>
#include <common/contact/normal_enforcement.h>

#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    bool
    DualLagrangeEnforcement<dim>::has_multipliers() const
    {
      return true;
    }



    template <int dim>
    bool
    DualLagrangeEnforcement<dim>::is_closed(const double pressure,
                                            const double gap,
                                            const double c) const
    {
      return NormalContactLaw::is_active(pressure, gap, c);
    }



    template <int dim>
    double
    DualLagrangeEnforcement<dim>::complementarity(const double pressure,
                                                  const double gap,
                                                  const double c) const
    {
      return NormalContactLaw::complementarity(pressure, gap, c);
    }



    template <int dim>
    void
    DualLagrangeEnforcement<dim>::add_constraints(
      const MortarCoupling<dim> &coupling,
      const ContactState<dim>   &state,
      const VectorType          &u,
      AffineConstraints<double> &constraints) const
    {
      const FreeDirections<dim> &directions = state.directions();
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const PointStatus status = state.node(j).status;
          if (status == PointStatus::open)
            continue;
          const MortarRow<dim> &row  = coupling.row(j);
          const auto           &node = coupling.secondary_surface().node(j);
          const auto           &free_tangents = directions.free_tangents(j);

          bool all_free = true;
          for (unsigned int d = 0; d < dim; ++d)
            all_free = all_free && !constraints.is_constrained(node.dofs[d]);

          // Stick: D du_j = sum_k M_jk du_k + g~ n + D P(w(u) - w_old):
          // after the increment the weighted gap vanishes and the relative
          // tangential displacement is that of the last accepted step.
          const Tensor<1, dim> target_defect =
            status == PointStatus::stick ?
              coupling.weighted_gap(j, u) / row.weight * row.normal +
                state.slip_increment(j, coupling.relative_displacement(j, u)) :
              Tensor<1, dim>();
          if (status == PointStatus::stick && all_free)
            {
              for (unsigned int d = 0; d < dim; ++d)
                {
                  std::vector<std::pair<types::global_dof_index, double>>
                    entries;
                  for (const auto &[k, M] : row.primary_weights)
                    if (std::abs(M) > 1e-14 * row.weight)
                      entries.emplace_back(coupling.primary_node(k).dofs[d],
                                           M / row.weight);
                  constraints.add_line(node.dofs[d]);
                  constraints.add_entries(node.dofs[d], entries);
                  constraints.set_inhomogeneity(node.dofs[d], target_defect[d]);
                }
              continue;
            }

          // A stick node with some DoFs fixed (a symmetry plane): the
          // normal condition and stick along the free tangents, A du_j =
          // A (sum_k M_jk du_k / D + target_defect) with the rows of A the
          // normal and the free tangents, solved for the free components F:
          // du_F = A_F^-1 (A (sum_k M_jk du_k / D + target_defect) - A_X
          // du_X).
          std::vector<unsigned int> free_components, fixed_components;
          for (unsigned int d = 0; d < dim; ++d)
            (constraints.is_constrained(node.dofs[d]) ? fixed_components :
                                                        free_components)
              .push_back(d);
          const unsigned int m = 1 + free_tangents.size();
          if (status == PointStatus::stick && !free_tangents.empty() &&
              free_components.size() == m)
            {
              FullMatrix<double> A(m, dim), A_F(m, m), A_F_inverse(m, m);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  A(0, d) = row.normal[d];
                  for (unsigned int i = 1; i < m; ++i)
                    A(i, d) = free_tangents[i - 1][d];
                }
              for (unsigned int i = 0; i < m; ++i)
                for (unsigned int f = 0; f < m; ++f)
                  A_F(i, f) = A(i, free_components[f]);
              if (std::abs(A_F.determinant()) > 1e-6)
                {
                  A_F_inverse.invert(A_F);
                  FullMatrix<double> S(m, dim); // A_F^-1 A
                  A_F_inverse.mmult(S, A);
                  for (unsigned int f = 0; f < m; ++f)
                    {
                      std::vector<std::pair<types::global_dof_index, double>>
                             entries;
                      double inhomogeneity = 0.;
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          inhomogeneity += S(f, d) * target_defect[d];
                          if (std::abs(S(f, d)) < 1e-14)
                            continue;
                          for (const auto &[k, M] : row.primary_weights)
                            if (std::abs(M) > 1e-14 * row.weight)
                              entries.emplace_back(
                                coupling.primary_node(k).dofs[d],
                                S(f, d) * M / row.weight);
                        }
                      for (const unsigned int x : fixed_components)
                        if (std::abs(S(f, x)) > 1e-14)
                          entries.emplace_back(node.dofs[x], -S(f, x));
                      const auto dof = node.dofs[free_components[f]];
                      constraints.add_line(dof);
                      constraints.add_entries(dof, entries);
                      constraints.set_inhomogeneity(dof, inhomogeneity);
                    }
                  continue;
                }
            }

          // Normal condition only (slip, or a node without a free tangent
          // direction): solve the linearised condition for the free
          // component with the largest normal share.
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
                entries.emplace_back(coupling.primary_node(k).dofs[e],
                                     M * row.normal[e] * scale);
          constraints.add_line(node.dofs[c]);
          constraints.add_entries(node.dofs[c], entries);
          constraints.set_inhomogeneity(node.dofs[c],
                                        coupling.weighted_gap(j, u) * scale);
        }
    }



    template <int dim>
    void
    DualLagrangeEnforcement<dim>::assemble(const MortarCoupling<dim> &,
                                           const ContactState<dim> &,
                                           const AffineConstraints<double> &,
                                           const VectorType &,
                                           const IndexSet &,
                                           MatrixType &,
                                           VectorType &) const
    {}



    template <int dim>
    void
    DualLagrangeEnforcement<dim>::update_tractions(
      const MortarCoupling<dim> &coupling,
      const VectorType &,
      const VectorType  &bulk_residual,
      const bool         with_friction,
      ContactState<dim> &state) const
    {
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row  = coupling.row(j);
          NodeState<dim>       &node = state.node(j);
          node.tangential_traction   = Tensor<1, dim>();
          if (node.status == PointStatus::open)
            {
              node.pressure = 0.;
              continue;
            }
          // Equilibrium of node j: r_j + D_j(-lambda n + t) = 0.
          const auto    &dofs = coupling.secondary_surface().node(j).dofs;
          Tensor<1, dim> r;
          for (unsigned int c = 0; c < dim; ++c)
            r[c] = bulk_residual(dofs[c]);
          node.pressure = (r * row.normal) / row.weight;
          if (with_friction)
            node.tangential_traction =
              -state.directions().free_tangential_part(j, r) / row.weight;
        }
    }



    template <int dim>
    PenaltyEnforcement<dim>::PenaltyEnforcement(const double stiffness)
      : stiffness(stiffness)
    {}



    template <int dim>
    bool
    PenaltyEnforcement<dim>::has_multipliers() const
    {
      return false;
    }



    template <int dim>
    bool
    PenaltyEnforcement<dim>::is_closed(const double,
                                       const double gap,
                                       const double) const
    {
      return NormalContactLaw::penalty_derivative(gap, stiffness) != 0.;
    }



    template <int dim>
    double
    PenaltyEnforcement<dim>::complementarity(const double pressure,
                                             const double gap,
                                             const double c) const
    {
      return NormalContactLaw::complementarity(pressure, gap, c);
    }



    template <int dim>
    void
    PenaltyEnforcement<dim>::add_constraints(const MortarCoupling<dim> &,
                                             const ContactState<dim> &,
                                             const VectorType &,
                                             AffineConstraints<double> &) const
    {}



    template <int dim>
    void
    PenaltyEnforcement<dim>::assemble(
      const MortarCoupling<dim>       &coupling,
      const ContactState<dim>         &state,
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
          if (!state.is_closed(j) ||
              !locally_owned.is_element(
                coupling.secondary_surface().node(j).dofs[0]))
            continue;
          // A closed node is a spring for the whole iteration, also where
          // its gap has turned positive (a touching node's weighted gap is
          // positive when the surfaces curve apart): without it the first
          // iteration of a body held only by contact is singular. The
          // active-set update then opens the node; at convergence the
          // set agrees with the sign of the gap and p = k max(0, -g).
          const double gap     = coupling.weighted_gap(j, u) / row.weight;
          const double dp_dgap = -stiffness;
          const double p       = dp_dgap * gap;

          gap_gradient(coupling, j, row.normal, dofs, B);
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
    PenaltyEnforcement<dim>::update_tractions(
      const MortarCoupling<dim> &coupling,
      const VectorType          &u,
      const VectorType &,
      const bool,
      ContactState<dim> &state) const
    {
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row  = coupling.row(j);
          NodeState<dim>       &node = state.node(j);
          node.tangential_traction   = Tensor<1, dim>();
          node.pressure =
            node.status == PointStatus::open ?
              0. :
              NormalContactLaw::penalty_pressure(coupling.weighted_gap(j, u) /
                                                   row.weight,
                                                 stiffness);
        }
    }



    template <int dim>
    std::unique_ptr<NormalEnforcement<dim>>
    create_normal_enforcement(const ContactParameters &parameters)
    {
      if (parameters.enforcement == Enforcement::penalty)
        return std::make_unique<PenaltyEnforcement<dim>>(
          parameters.penalty_stiffness);
      return std::make_unique<DualLagrangeEnforcement<dim>>();
    }

    template class DualLagrangeEnforcement<2>;
    template class DualLagrangeEnforcement<3>;
    template class PenaltyEnforcement<2>;
    template class PenaltyEnforcement<3>;
    template std::unique_ptr<NormalEnforcement<2>>
    create_normal_enforcement<2>(const ContactParameters &);
    template std::unique_ptr<NormalEnforcement<3>>
    create_normal_enforcement<3>(const ContactParameters &);
  } // namespace Contact
} // namespace Common
