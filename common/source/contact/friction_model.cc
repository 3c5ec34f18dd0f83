#include <common/contact/contact_assembly.h>
#include <common/contact/coulomb_law.h>
#include <common/contact/friction_model.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <map>
#include <vector>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    bool
    Frictionless<dim>::has_friction() const
    {
      return false;
    }



    template <int dim>
    PointStatus
    Frictionless<dim>::status_on_contact() const
    {
      return PointStatus::slip;
    }



    template <int dim>
    FrictionStatus<dim>
    Frictionless<dim>::closed_status(const FrictionPoint<dim> &) const
    {
      return FrictionStatus<dim>();
    }



    template <int dim>
    Tensor<1, dim>
    Frictionless<dim>::complementarity(const FrictionPoint<dim> &) const
    {
      return Tensor<1, dim>();
    }



    template <int dim>
    void
    Frictionless<dim>::assemble(const MortarCoupling<dim> &,
                                const ContactState<dim> &,
                                const AffineConstraints<double> &,
                                const VectorType &,
                                const MatrixType &,
                                const VectorType &,
                                const IndexSet &,
                                MatrixType &,
                                VectorType &,
                                const TrialCorrections *) const
    {}



    template <int dim>
    CoulombFriction<dim>::CoulombFriction(const double friction_coefficient)
      : mu(friction_coefficient)
    {}



    template <int dim>
    bool
    CoulombFriction<dim>::has_friction() const
    {
      return mu > 0.;
    }



    template <int dim>
    PointStatus
    CoulombFriction<dim>::status_on_contact() const
    {
      // A touching node has no slip history: it starts in stick.
      return has_friction() ? PointStatus::stick : PointStatus::slip;
    }



    template <int dim>
    FrictionStatus<dim>
    CoulombFriction<dim>::closed_status(const FrictionPoint<dim> &point) const
    {
      FrictionStatus<dim> result;
      if (!has_friction())
        return result;
      if (point.n_free_tangents == 0)
        {
          // No direction to slip along (an axis, or every tangent fixed).
          result.status = PointStatus::stick;
          return result;
        }
      const double bound = mu * point.normal_pressure;
      if (CoulombLaw::is_sticking(point.traction,
                                  point.slip_increment,
                                  bound,
                                  point.c))
        result.status = PointStatus::stick;
      else
        {
          result.status         = PointStatus::slip;
          const auto step       = CoulombLaw::slip_linearisation(point.traction,
                                                           point.slip_increment,
                                                           bound,
                                                           point.c);
          result.slip_direction = step.direction;
          // Bounded, so that a point just past the stick limit does not
          // make the tangent ill-conditioned; the converged state does
          // not depend on k. Only a node free to slip in the whole tangent
          // plane turns.
          if (point.n_free_tangents == dim - 1)
            result.turning_stiffness =
              std::min(step.turning_stiffness, 1e3 * point.c);
        }
      return result;
    }



    template <int dim>
    Tensor<1, dim>
    CoulombFriction<dim>::complementarity(const FrictionPoint<dim> &point) const
    {
      if (!has_friction() || point.n_free_tangents == 0)
        return Tensor<1, dim>();
      return CoulombLaw::complementarity(point.traction,
                                         point.slip_increment,
                                         mu * point.normal_pressure,
                                         point.c);
    }



    template <int dim>
    void
    CoulombFriction<dim>::assemble(const MortarCoupling<dim>       &coupling,
                                   const ContactState<dim>         &state,
                                   const AffineConstraints<double> &constraints,
                                   const VectorType                &u,
                                   const MatrixType                &bulk_matrix,
                                   const VectorType       &bulk_residual,
                                   const IndexSet         &locally_owned,
                                   MatrixType             &matrix,
                                   VectorType             &residual,
                                   const TrialCorrections *corrections) const
    {
      if (!has_friction())
        return;
      std::vector<types::global_dof_index>      B_dofs;
      Vector<double>                            B;
      std::map<types::global_dof_index, double> stiffness_row;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const auto           &node = coupling.secondary_surface().node(j);
          const NodeState<dim> &node_state = state.node(j);
          if (node_state.status != PointStatus::slip ||
              state.directions().free_tangents(j).empty() ||
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
              // it is made. The bulk matrix shares the sparsity pattern of
              // the contact system: the entries of its row beyond the
              // node's cells are structural zeros, and their columns may be
              // DoFs this rank does not store.
              const auto end = bulk_matrix.end(node.dofs[c]);
              for (auto entry = bulk_matrix.begin(node.dofs[c]); entry != end;
                   ++entry)
                if (entry->value() != 0.)
                  stiffness_row[entry->column()] +=
                    row.normal[c] * entry->value();
            }
          const double pressure = rn / row.weight;

          // Force -mu lambda B_e: D mu lambda e on the secondary node, its
          // reaction on the primary nodes. Tangent -(mu/D) B_e (n^T K_j).
          const Tensor<1, dim> &e = node_state.slip_direction;
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
            if (node_state.turning_stiffness > 0.)
              {
                Tensor<1, dim> t2 = cross_product_3d(row.normal, e);
                t2 /= t2.norm();
                std::vector<types::global_dof_index> t2_dofs;
                Vector<double>                       B_t2;
                gap_gradient(coupling, j, t2, t2_dofs, B_t2);
                Assert(t2_dofs == B_dofs, ExcInternalError());
                const double k = node_state.turning_stiffness;
                const double traction_t2 =
                  k *
                  (state.slip_increment(j,
                                        coupling.relative_displacement(j, u)) *
                   t2);
                for (unsigned int a = 0; a < B_t2.size(); ++a)
                  {
                    r(a) -= traction_t2 * B_t2(a);
                    for (unsigned int b = 0; b < B_t2.size(); ++b)
                      K(a, b) += k / row.weight * B_t2(a) * B_t2(b);
                  }
              }
          if (corrections != nullptr)
            corrections->extend_columns(dofs, K, r);
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
    std::unique_ptr<FrictionModel<dim>>
    create_friction_model(const ContactParameters &parameters)
    {
      if (parameters.friction_law == FrictionLaw::coulomb)
        return std::make_unique<CoulombFriction<dim>>(
          parameters.friction_coefficient);
      return std::make_unique<Frictionless<dim>>();
    }

    template class Frictionless<2>;
    template class Frictionless<3>;
    template class CoulombFriction<2>;
    template class CoulombFriction<3>;
    template std::unique_ptr<FrictionModel<2>>
    create_friction_model<2>(const ContactParameters &);
    template std::unique_ptr<FrictionModel<3>>
    create_friction_model<3>(const ContactParameters &);
  } // namespace Contact
} // namespace Common
