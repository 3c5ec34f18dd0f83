#include <common/contact/contact_assembly.h>
#include <common/contact/normal_contact_law.h>
#include <common/contact/normal_enforcement.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    namespace
    {
      /**
       * Hold secondary node j by the rows of @p A (m x dim, orthonormal
       * directions): A du_j = A (sum_k M_jk du_k / D + target_defect),
       * solved for the m components @p solved of du_j, the increments of
       * the @p other components moving to the right-hand side,
       * du_S = S (sum_k M_jk du_k / D + target_defect) - S_X du_X with
       * S = A_S^-1 A. Adds nothing and returns false if
       * |det A_S| <= 1e-6.
       */
      template <int dim>
      bool
      hold_node(const MortarCoupling<dim>       &coupling,
                const unsigned int               j,
                const FullMatrix<double>        &A,
                const std::vector<unsigned int> &solved,
                const std::vector<unsigned int> &other,
                const Tensor<1, dim>            &target_defect,
                AffineConstraints<double>       &constraints)
      {
        const MortarRow<dim> &row  = coupling.row(j);
        const auto           &node = coupling.secondary_surface().node(j);
        const unsigned int    m    = solved.size();
        FullMatrix<double>    A_S(m, m), A_S_inverse(m, m);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int f = 0; f < m; ++f)
            A_S(i, f) = A(i, solved[f]);
        if (!(std::abs(A_S.determinant()) > 1e-6))
          return false;
        A_S_inverse.invert(A_S);
        FullMatrix<double> S(m, dim); // A_S^-1 A
        A_S_inverse.mmult(S, A);
        for (unsigned int f = 0; f < m; ++f)
          {
            std::vector<std::pair<types::global_dof_index, double>> entries;
            double inhomogeneity = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                inhomogeneity += S(f, d) * target_defect[d];
                if (std::abs(S(f, d)) < 1e-14)
                  continue;
                for (const auto &[k, M] : row.primary_weights)
                  if (std::abs(M) > 1e-14 * row.weight)
                    entries.emplace_back(coupling.primary_node(k).dofs[d],
                                         S(f, d) * M / row.weight);
              }
            for (const unsigned int x : other)
              if (std::abs(S(f, x)) > 1e-14)
                entries.emplace_back(node.dofs[x], -S(f, x));
            const auto dof = node.dofs[solved[f]];
            constraints.add_line(dof);
            constraints.add_entries(dof, entries);
            constraints.set_inhomogeneity(dof, inhomogeneity);
          }
        return true;
      }



      /**
       * Hold secondary node j along its free tangents alone (hold_node()
       * with A = the free tangents), solved for as many of its free
       * components as there are tangents: the choice with the largest
       * |det A_S|. False if there is none.
       */
      template <int dim>
      bool
      hold_free_tangents(const MortarCoupling<dim>         &coupling,
                         const unsigned int                 j,
                         const std::vector<Tensor<1, dim>> &free_tangents,
                         const std::vector<unsigned int>   &free_components,
                         const std::vector<unsigned int>   &fixed_components,
                         const Tensor<1, dim>              &target_defect,
                         AffineConstraints<double>         &constraints)
      {
        const unsigned int k = free_tangents.size();
        FullMatrix<double> A(k, dim);
        for (unsigned int i = 0; i < k; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            A(i, d) = free_tangents[i][d];
        std::vector<unsigned int> best;
        double                    best_determinant = 0.;
        // Every subset of k free components (there are at most dim).
        for (unsigned int mask = 0; mask < (1u << free_components.size());
             ++mask)
          {
            std::vector<unsigned int> solved;
            for (unsigned int f = 0; f < free_components.size(); ++f)
              if (mask & (1u << f))
                solved.push_back(free_components[f]);
            if (solved.size() != k)
              continue;
            FullMatrix<double> A_S(k, k);
            for (unsigned int i = 0; i < k; ++i)
              for (unsigned int f = 0; f < k; ++f)
                A_S(i, f) = A(i, solved[f]);
            const double determinant = std::abs(A_S.determinant());
            if (determinant > best_determinant)
              {
                best             = solved;
                best_determinant = determinant;
              }
          }
        if (best.empty())
          return false;
        std::vector<unsigned int> other = fixed_components;
        for (const unsigned int f : free_components)
          if (std::find(best.begin(), best.end(), f) == best.end())
            other.push_back(f);
        return hold_node(coupling,
                         j,
                         A,
                         best,
                         other,
                         target_defect,
                         constraints);
      }



      /**
       * The TrialCorrection of secondary node j, whose normal condition was
       * written to @p constraints from the fixed rows, solved for its
       * component @p c: from the full derivative @p derivative of its
       * weighted gap @p gap, du_c = -(gap + sum_q dg/du_q du_q) / (dg/du_c)
       * over the node's other components and its primary partners' DoFs,
       * less the constraint written. None if |dg/du_c| is less than half
       * the fixed rows' |D n_c|, which a valid linearisation of a closed
       * node does not give.
       */
      template <int dim>
      void
      add_trial_correction(
        const MortarCoupling<dim> &coupling,
        const unsigned int         j,
        const unsigned int         c,
        const double               gap,
        const std::vector<std::pair<types::global_dof_index, double>>
                                        &derivative,
        const AffineConstraints<double> &constraints,
        TrialCorrections                &corrections)
      {
        const MortarRow<dim> &row  = coupling.row(j);
        const auto           &node = coupling.secondary_surface().node(j);
        std::map<types::global_dof_index, double> own_and_primary;
        for (unsigned int d = 0; d < dim; ++d)
          own_and_primary[node.dofs[d]] = 0.;
        for (const auto &entry : row.primary_weights)
          for (unsigned int d = 0; d < dim; ++d)
            own_and_primary[coupling.primary_node(entry.first).dofs[d]] = 0.;
        for (const auto &[dof, value] : derivative)
          {
            const auto it = own_and_primary.find(dof);
            if (it != own_and_primary.end())
              it->second += value;
          }
        const types::global_dof_index dof   = node.dofs[c];
        const double                  pivot = own_and_primary[dof];
        if (!(std::abs(pivot) >= 0.5 * row.weight * std::abs(row.normal[c])))
          return;

        std::map<types::global_dof_index, double> difference;
        for (const auto &[q, value] : own_and_primary)
          if (q != dof)
            difference[q] = -value / pivot;
        const auto *written = constraints.get_constraint_entries(dof);
        Assert(written != nullptr, ExcInternalError());
        for (const auto &[q, value] : *written)
          difference[q] -= value;
        TrialCorrection correction;
        correction.dof = dof;
        correction.inhomogeneity =
          -gap / pivot - constraints.get_inhomogeneity(dof);
        for (const auto &[q, value] : difference)
          if (value != 0.)
            correction.entries.emplace_back(q, value);
        corrections.add(std::move(correction));
      }



      /** "(x, y)" or "(x, y, z)": the position of secondary node j (mm). */
      template <int dim>
      std::string
      position_text(const MortarCoupling<dim> &coupling, const unsigned int j)
      {
        std::ostringstream text;
        text << '(' << coupling.secondary_surface().node(j).position << ')';
        return text.str();
      }



      /** One line on the standard error stream, from the first rank. */
      void
      warn(const std::string &text)
      {
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cerr << "Warning: " << text << std::endl;
      }
    } // namespace



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
      const MortarCoupling<dim>                             &coupling,
      const ContactState<dim>                               &state,
      const VectorType                                      &u,
      AffineConstraints<double>                             &constraints,
      const typename NormalEnforcement<dim>::GapDerivatives *gap_derivatives,
      TrialCorrections                                      *corrections) const
    {
      const FreeDirections<dim> &directions = state.directions();
      last_diagnostics                      = ConstraintDiagnostics();
      unsigned int example_stick            = numbers::invalid_unsigned_int,
                   example_unconstrained    = numbers::invalid_unsigned_int;
      // The rows this rank holds: its own and the ghost rows of its cells.
      // The diagnostics count the owned ones, summed over the ranks.
      const RowPartition &rows = state.rows();
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          if (!rows.is_held(j))
            continue;
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

          std::vector<unsigned int> free_components, fixed_components;
          for (unsigned int d = 0; d < dim; ++d)
            (constraints.is_constrained(node.dofs[d]) ? fixed_components :
                                                        free_components)
              .push_back(d);
          if (status == PointStatus::stick && !free_tangents.empty())
            {
              // A stick node with some DoFs fixed (a symmetry plane): the
              // normal condition and stick along the free tangents, solved
              // for the free components.
              const unsigned int m = 1 + free_tangents.size();
              if (free_components.size() == m)
                {
                  FullMatrix<double> A(m, dim);
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      A(0, d) = row.normal[d];
                      for (unsigned int i = 1; i < m; ++i)
                        A(i, d) = free_tangents[i - 1][d];
                    }
                  if (hold_node(coupling,
                                j,
                                A,
                                free_components,
                                fixed_components,
                                target_defect,
                                constraints))
                    continue;
                }
              // That system is singular (or not square) where the normal
              // has no free component: the Dirichlet conditions fix the
              // node's normal displacement, and its normal condition
              // cannot act on the node. Its stick condition can: hold it
              // along the free tangents alone, solved for the free
              // components that give the best-conditioned system, rather
              // than lose its friction force.
              if (hold_free_tangents(coupling,
                                     j,
                                     free_tangents,
                                     free_components,
                                     fixed_components,
                                     target_defect,
                                     constraints))
                {
                  if (rows.is_owned(j))
                    {
                      ++last_diagnostics.n_stick_without_normal;
                      if (example_stick == numbers::invalid_unsigned_int)
                        example_stick = j;
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
            {
              // Every component fixed, or none along the normal: no
              // constraint can act on the node.
              if (rows.is_owned(j))
                {
                  ++last_diagnostics.n_unconstrained;
                  if (example_unconstrained == numbers::invalid_unsigned_int)
                    example_unconstrained = j;
                }
              continue;
            }

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
          const double gap = coupling.weighted_gap(j, u);
          constraints.add_line(node.dofs[c]);
          constraints.add_entries(node.dofs[c], entries);
          constraints.set_inhomogeneity(node.dofs[c], gap * scale);
          if (corrections != nullptr && gap_derivatives != nullptr &&
              !(*gap_derivatives)[j].empty())
            add_trial_correction(coupling,
                                 j,
                                 c,
                                 gap,
                                 (*gap_derivatives)[j],
                                 constraints,
                                 *corrections);
        }

      if (rows.is_distributed())
        {
          const MPI_Comm comm = rows.communicator();
          last_diagnostics.n_stick_without_normal =
            Utilities::MPI::sum(last_diagnostics.n_stick_without_normal, comm);
          last_diagnostics.n_unconstrained =
            Utilities::MPI::sum(last_diagnostics.n_unconstrained, comm);
          // The first node, as in serial: the smallest index of any rank.
          example_stick = Utilities::MPI::min(example_stick, comm);
          example_unconstrained =
            Utilities::MPI::min(example_unconstrained, comm);
        }
      if (last_diagnostics.n_stick_without_normal > 0 && !warned_stick)
        {
          warned_stick = true;
          warn(std::to_string(last_diagnostics.n_stick_without_normal) +
               " sticking contact node(s), the first at " +
               position_text(coupling, example_stick) +
               ", have their normal displacement fixed by a Dirichlet "
               "condition: stick is held along the free tangents only, and "
               "the normal condition is left to the support.");
        }
      if (last_diagnostics.n_unconstrained > 0 && !warned_unconstrained)
        {
          warned_unconstrained = true;
          warn(std::to_string(last_diagnostics.n_unconstrained) +
               " closed contact node(s), the first at " +
               position_text(coupling, example_unconstrained) +
               ", take no contact constraint: every displacement component, "
               "or every one along the normal, is fixed by other constraints "
               "(Dirichlet conditions, a rigid-body tie). Their contact "
               "condition is not enforced.");
        }
    }



    template <int dim>
    const ConstraintDiagnostics &
    DualLagrangeEnforcement<dim>::diagnostics() const
    {
      return last_diagnostics;
    }



    template <int dim>
    void
    DualLagrangeEnforcement<dim>::assemble(
      const MortarCoupling<dim> &,
      const ContactState<dim> &,
      const AffineConstraints<double> &,
      const VectorType &,
      const IndexSet &,
      MatrixType &,
      VectorType &,
      const typename NormalEnforcement<dim>::GapDerivatives *) const
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
          if (!state.rows().is_held(j))
            continue;
          const MortarRow<dim> &row  = coupling.row(j);
          NodeState<dim>       &node = state.node(j);
          node.tangential_traction   = Tensor<1, dim>();
          // A closed node that has lost its partner (a tool moved beyond
          // the search distance) carries no traction; the next update opens
          // it.
          if (node.status == PointStatus::open || !(row.weight > 0.))
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
                                             const double) const
    {
      // update_tractions(): a closed node carries -k g, an open one 0. A
      // closed node that pulls (g > 0) or an open one that penetrates
      // (g < 0) departs from the penalty law by k |g|.
      if (pressure < 0.)
        return pressure;
      if (pressure == 0. && gap < 0.)
        return stiffness * gap;
      return 0.;
    }



    template <int dim>
    void
    PenaltyEnforcement<dim>::add_constraints(
      const MortarCoupling<dim> &,
      const ContactState<dim> &,
      const VectorType &,
      AffineConstraints<double> &,
      const typename NormalEnforcement<dim>::GapDerivatives *,
      TrialCorrections *) const
    {}



    template <int dim>
    void
    PenaltyEnforcement<dim>::assemble(
      const MortarCoupling<dim>                             &coupling,
      const ContactState<dim>                               &state,
      const AffineConstraints<double>                       &constraints,
      const VectorType                                      &u,
      const IndexSet                                        &locally_owned,
      MatrixType                                            &matrix,
      VectorType                                            &residual,
      const typename NormalEnforcement<dim>::GapDerivatives *gap_derivatives)
      const
    {
      std::vector<types::global_dof_index> dofs;
      Vector<double>                       B;
      FullMatrix<double>                   K;
      Vector<double>                       r;
      std::vector<double>                  G;
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
          // iteration of a body held only by contact is singular. Its force
          // then pulls, in the residual too (update_tractions()), so that
          // the iteration converges to the equilibrium of the set it holds;
          // the active-set update opens the node. At convergence the set
          // agrees with the sign of the gap and p = k max(0, -g).
          const double gap     = coupling.weighted_gap(j, u) / row.weight;
          const double dp_dgap = -stiffness;
          const double p       = dp_dgap * gap;

          gap_gradient(coupling, j, row.normal, dofs, B);
          // G: the gradient of the weighted gap on the DoFs of B followed
          // by the others it depends on.
          const unsigned int n_force_dofs = dofs.size();
          G.assign(B.begin(), B.end());
          if (gap_derivatives != nullptr && !(*gap_derivatives)[j].empty())
            {
              std::fill(G.begin(), G.end(), 0.);
              for (const auto &[dof, value] : (*gap_derivatives)[j])
                {
                  const auto it = std::find(dofs.begin(), dofs.end(), dof);
                  if (it == dofs.end())
                    {
                      dofs.push_back(dof);
                      G.push_back(value);
                    }
                  else
                    G[it - dofs.begin()] += value;
                }
            }
          K.reinit(dofs.size(), dofs.size());
          r.reinit(dofs.size());
          // Residual f_ext - f_int + p B; tangent -(dp/dg~) B G^T.
          for (unsigned int a = 0; a < n_force_dofs; ++a)
            {
              r(a) = p * B(a);
              for (unsigned int b = 0; b < dofs.size(); ++b)
                K(a, b) = -dp_dgap / row.weight * B(a) * G[b];
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
          if (!state.rows().is_held(j))
            continue;
          const MortarRow<dim> &row  = coupling.row(j);
          NodeState<dim>       &node = state.node(j);
          node.tangential_traction   = Tensor<1, dim>();
          // The force of the spring that assemble() puts on a closed
          // node, a pull where its gap has turned positive: the residual
          // of the iterate then belongs to its linearisation, and the
          // active-set update opens the node.
          node.pressure =
            node.status == PointStatus::open ?
              0. :
              -stiffness * coupling.weighted_gap(j, u) / row.weight;
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
