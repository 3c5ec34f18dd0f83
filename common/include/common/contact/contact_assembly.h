/**
 * @file contact_assembly.h
 * Global operations on the mortar rows of a contact pair, shared by the
 * enforcement, the friction model and the active-set policy: gathering the
 * nodal kinematics (gaps, relative displacements) from a displacement
 * vector, and scattering contact terms into the global system (the
 * sparsity of every coupling contact can create, the gradient of a row,
 * the forces of the nodal tractions). No law and no active-set rule.
 */
#ifndef common_contact_contact_assembly_h
#define common_contact_contact_assembly_h

#include <common/contact/contact_state.h>
#include <common/contact/mortar_coupling.h>
#include <common/contact/row_partition.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace Common
{
  namespace Contact
  {
    /** @brief The nodal normal of every row of @p coupling. */
    template <int dim>
    std::vector<dealii::Tensor<1, dim>>
    nodal_normals(const MortarCoupling<dim> &coupling);

    /**
     * @brief Kinematics of every secondary node at zero displacement: the
     * gaps of the geometry the rows were integrated on, no relative
     * displacement.
     */
    template <int dim>
    std::vector<NodeKinematics<dim>>
    node_kinematics(const MortarCoupling<dim> &coupling);

    /**
     * @brief Kinematics of the secondary nodes for the displacement
     * @p u (mm, ghosted): weighted gap (paired nodes only) and relative
     * displacement, evaluated at the rows this rank holds (@p rows; @p u
     * must be readable at their DoFs and those of their primary nodes),
     * the geometry at every row.
     */
    template <int dim, typename VectorType>
    std::vector<NodeKinematics<dim>>
    node_kinematics(const MortarCoupling<dim> &coupling,
                    const RowPartition        &rows,
                    const VectorType          &u);

    /**
     * @brief DoFs of secondary node j followed by the DoFs of its primary
     * nodes, and the gradient B of
     * \f$d\cdot(\sum_k M_{jk}x_k - D_j x_j)\f$ with respect to them:
     * \f$-D_j d\f$ on the secondary node, \f$M_{jk} d\f$ on primary node k.
     * With d = n_j this is the gradient of the weighted gap; with a unit
     * tangent, D_j times that of the relative tangential displacement.
     */
    template <int dim>
    void
    gap_gradient(const MortarCoupling<dim>                    &coupling,
                 const unsigned int                            j,
                 const dealii::Tensor<1, dim>                 &direction,
                 std::vector<dealii::types::global_dof_index> &dofs,
                 dealii::Vector<double>                       &B);

    /**
     * @brief The cells, of any rank, that hold a DoF of a node of
     * @p secondary whose first DoF is in @p owned_dofs, marked by active
     * cell index. The
     * friction tangent of such a node is its row of the bulk stiffness,
     * which these cells assemble: the rank needs their DoFs, the rows of
     * their secondary nodes and the couplings they create.
     */
    template <int dim>
    std::vector<bool>
    cells_around_owned_nodes(const ContactSurface<dim>     &secondary,
                             const dealii::IndexSet        &owned_dofs,
                             const dealii::DoFHandler<dim> &dof_handler);

    /**
     * @brief Add to @p dsp every coupling that contact can create, for
     * any active set, either enforcement and friction: for each locally
     * owned cell, and each cell marked in @p extra_cells (by active cell
     * index; may be empty), its DoFs together with the primary DoFs of
     * every paired secondary node of the cell, all coupled with each
     * other, and distributed through @p constraints (hanging nodes,
     * Dirichlet conditions). Reads the rows this rank holds (@p rows),
     * which cover the secondary nodes of its cells.
     */
    template <int dim>
    void
    add_contact_sparsity(const MortarCoupling<dim>               &coupling,
                         const RowPartition                      &rows,
                         const dealii::DoFHandler<dim>           &dof_handler,
                         const dealii::AffineConstraints<double> &constraints,
                         const std::vector<bool>                 &extra_cells,
                         dealii::DynamicSparsityPattern          &dsp);

    /**
     * @brief Add the contact forces of the nodal tractions
     * \f$-\lambda_j n_j + t_j\f$ of @p state to @p residual (N):
     * \f$D_j\f$ times the traction on secondary node j, \f$-M_{jk}\f$
     * times it on primary node k, for the nodes whose first DoF is in
     * @p locally_owned, distributed through @p constraints (forces on
     * constrained DoFs, such as hanging nodes or the nodes of a rigid body,
     * move to the DoFs they depend on). Not compressed here.
     */
    template <int dim>
    void
    add_traction_forces(const MortarCoupling<dim>               &coupling,
                        const ContactState<dim>                 &state,
                        const dealii::AffineConstraints<double> &constraints,
                        const dealii::IndexSet                  &locally_owned,
                        dealii::TrilinosWrappers::MPI::Vector   &residual);
  } // namespace Contact
} // namespace Common

#endif
