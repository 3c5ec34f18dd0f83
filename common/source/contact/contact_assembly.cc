#include <common/contact/contact_assembly.h>

#include <algorithm>
#include <map>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    std::vector<Tensor<1, dim>>
    nodal_normals(const MortarCoupling<dim> &coupling)
    {
      std::vector<Tensor<1, dim>> normals(coupling.n_rows());
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        normals[j] = coupling.row(j).normal;
      return normals;
    }



    template <int dim>
    std::vector<NodeKinematics<dim>>
    node_kinematics(const MortarCoupling<dim> &coupling)
    {
      std::vector<NodeKinematics<dim>> nodes(coupling.n_rows());
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          nodes[j].paired           = row.has_partner;
          nodes[j].weight           = row.weight;
          nodes[j].mesh_size        = row.mesh_size;
          nodes[j].nodal_gap        = row.nodal_gap;
          nodes[j].position = coupling.secondary_surface().node(j).position;
          if (row.has_partner)
            nodes[j].weighted_gap = row.reference_weighted_gap;
          if (row.has_partner && coupling.primary_is_rigid())
            {
              double largest = -1.;
              for (const auto &[k, M] : row.primary_weights)
                if (M > largest)
                  {
                    largest          = M;
                    nodes[j].partner = coupling.primary_node(k).dofs[0];
                  }
            }
        }
      return nodes;
    }



    template <int dim, typename VectorType>
    std::vector<NodeKinematics<dim>>
    node_kinematics(const MortarCoupling<dim> &coupling,
                    const RowPartition        &rows,
                    const VectorType          &u)
    {
      std::vector<NodeKinematics<dim>> nodes = node_kinematics(coupling);
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          if (!rows.is_held(j))
            continue;
          if (nodes[j].paired)
            nodes[j].weighted_gap = coupling.weighted_gap(j, u);
          nodes[j].relative_displacement = coupling.relative_displacement(j, u);
        }
      return nodes;
    }



    template <int dim>
    void
    gap_gradient(const MortarCoupling<dim>            &coupling,
                 const unsigned int                    j,
                 const Tensor<1, dim>                 &direction,
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
          values.push_back(-row.weight * direction[c]);
        }
      for (const auto &[k, M] : row.primary_weights)
        for (unsigned int c = 0; c < dim; ++c)
          {
            dofs.push_back(coupling.primary_node(k).dofs[c]);
            values.push_back(M * direction[c]);
          }
      B.reinit(values.size());
      for (unsigned int i = 0; i < values.size(); ++i)
        B(i) = values[i];
    }



    template <int dim>
    std::vector<bool>
    cells_around_owned_nodes(const ContactSurface<dim> &secondary,
                             const IndexSet            &owned_dofs,
                             const DoFHandler<dim>     &dof_handler)
    {
      std::vector<bool> marked(dof_handler.get_triangulation().n_active_cells(),
                               false);
      std::vector<types::global_dof_index> owned_nodes;
      for (unsigned int j = 0; j < secondary.n_nodes(); ++j)
        {
          const auto dof = secondary.node(j).dofs[0];
          if (owned_dofs.is_element(dof))
            owned_nodes.push_back(dof);
        }
      std::sort(owned_nodes.begin(), owned_nodes.end());
      std::vector<types::global_dof_index> cell_dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(cell_dofs);
          marked[cell->active_cell_index()] =
            std::any_of(cell_dofs.begin(),
                        cell_dofs.end(),
                        [&](const types::global_dof_index dof) {
                          return std::binary_search(owned_nodes.begin(),
                                                    owned_nodes.end(),
                                                    dof);
                        });
        }
      return marked;
    }



    template <int dim>
    void
    add_contact_sparsity(const MortarCoupling<dim>       &coupling,
                         const RowPartition              &rows,
                         const DoFHandler<dim>           &dof_handler,
                         const AffineConstraints<double> &constraints,
                         const std::vector<bool>         &extra_cells,
                         DynamicSparsityPattern          &dsp)
    {
      // Primary DoFs coupled to each DoF of a paired secondary node.
      std::map<types::global_dof_index, std::vector<types::global_dof_index>>
        partners;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner || !rows.is_held(j))
            continue;
          std::vector<types::global_dof_index> primary_dofs;
          for (const auto &entry : row.primary_weights)
            for (unsigned int e = 0; e < dim; ++e)
              primary_dofs.push_back(
                coupling.primary_node(entry.first).dofs[e]);
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
        if (cell->is_locally_owned() ||
            (!extra_cells.empty() && extra_cells[cell->active_cell_index()]))
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
    add_traction_forces(const MortarCoupling<dim>       &coupling,
                        const ContactState<dim>         &state,
                        const AffineConstraints<double> &constraints,
                        const IndexSet                  &locally_owned,
                        TrilinosWrappers::MPI::Vector   &residual)
    {
      std::vector<types::global_dof_index> dofs;
      Vector<double>                       B;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row  = coupling.row(j);
          const NodeState<dim> &node = state.node(j);
          const Tensor<1, dim>  traction =
            -node.pressure * row.normal + node.tangential_traction;
          if (traction.norm() == 0. ||
              !locally_owned.is_element(
                coupling.secondary_surface().node(j).dofs[0]))
            continue;
          // B of d = -traction: D t on the secondary node, -M t on primary.
          gap_gradient(coupling, j, -traction, dofs, B);
          constraints.distribute_local_to_global(B, dofs, residual);
        }
    }

#define INSTANTIATE(dim)                                                          \
  template std::vector<Tensor<1, dim>> nodal_normals(                             \
    const MortarCoupling<dim> &);                                                 \
  template std::vector<NodeKinematics<dim>> node_kinematics(                      \
    const MortarCoupling<dim> &);                                                 \
  template std::vector<NodeKinematics<dim>> node_kinematics(                      \
    const MortarCoupling<dim> &,                                                  \
    const RowPartition &,                                                         \
    const Vector<double> &);                                                      \
  template std::vector<NodeKinematics<dim>> node_kinematics(                      \
    const MortarCoupling<dim> &,                                                  \
    const RowPartition &,                                                         \
    const TrilinosWrappers::MPI::Vector &);                                       \
  template void              gap_gradient(const MortarCoupling<dim> &,            \
                                          const unsigned int,                     \
                                          const Tensor<1, dim> &,                 \
                                          std::vector<types::global_dof_index> &, \
                                          Vector<double> &);                      \
  template std::vector<bool> cells_around_owned_nodes(                            \
    const ContactSurface<dim> &,                                                  \
    const IndexSet &,                                                             \
    const DoFHandler<dim> &);                                                     \
  template void add_contact_sparsity(const MortarCoupling<dim> &,                 \
                                     const RowPartition &,                        \
                                     const DoFHandler<dim> &,                     \
                                     const AffineConstraints<double> &,           \
                                     const std::vector<bool> &,                   \
                                     DynamicSparsityPattern &);                   \
  template void add_traction_forces(const MortarCoupling<dim> &,                  \
                                    const ContactState<dim> &,                    \
                                    const AffineConstraints<double> &,            \
                                    const IndexSet &,                             \
                                    TrilinosWrappers::MPI::Vector &);
    INSTANTIATE(2)
    INSTANTIATE(3)
#undef INSTANTIATE
  } // namespace Contact
} // namespace Common
