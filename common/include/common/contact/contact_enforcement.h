/**
 * @file contact_enforcement.h
 * Normal and frictional contact on the mortar rows of a contact pair, as
 * one object: a facade that composes the parts, each in its own file, and
 * only delegates to them:
 * - FreeDirections (free_directions.h): the directions in which each
 *   secondary node may move;
 * - ContactState (contact_state.h): status, pressure, tangential traction,
 *   slip direction and turning stiffness of every node, and the friction
 *   history of the accepted load steps;
 * - NormalEnforcement (normal_enforcement.h): condensed dual Lagrange
 *   multipliers or penalty;
 * - FrictionModel (friction_model.h): frictionless or Coulomb;
 * - ActiveSetPolicy (active_set_policy.h): the semismooth Newton
 *   active-set rule with its safeguards;
 * - contact_assembly.h: gathering nodal kinematics and scattering contact
 *   terms.
 *
 * With dual multipliers D is diagonal, so an active node's constraint
 * \f$\tilde g_j(u) = 0\f$ can be solved for one displacement component of
 * the node: the multiplier is condensed out locally and the linear system
 * keeps the size and structure of a problem without contact. The
 * multiplier follows afterwards from the residual of that node,
 * \f$\lambda_j = r_j\cdot n_j / D_j\f$.
 *
 * Coulomb friction (exact, primal-dual active set = semismooth Newton on
 * CoulombLaw::complementarity()): a closed node either sticks or slips.
 * A sticking node's relative tangential displacement is held at its value
 * of the last accepted load step; together with the normal condition that
 * fixes the whole node to the mean motion of its primary partners,
 * \f$D_j u_j = \sum_k M_{jk} u_k - w_j\f$, again a condensed
 * constraint. A slipping node carries the tangential traction
 * \f$\mu\lambda_j e_j\f$ along the slip direction e_j of the active set,
 * where \f$\lambda_j = n_j\cdot r_j(u)/D_j\f$ is linear in u through the
 * bulk stiffness rows of the node; this term makes the system
 * non-symmetric. In 2D the tangent plane is a line, e_j is constant within
 * an iteration, and the iteration is the exact semismooth Newton method;
 * in 3D the direction is updated by the active-set loop (fixed point).
 * The tangential traction follows from the residual like the pressure,
 * \f$t_j = -(I - n_j n_j^T) r_j / D_j\f$.
 *
 * With MPI the rows are distributed (distribute_rows(), RowPartition):
 * each rank decides, assembles and reports the nodes it owns, holds the
 * ghost rows its cells need for their constraints, and the per-node
 * accessors (status(), pressure(), ...) are valid at the rows it holds.
 *
 * Reference: S. Hueeber, B. Wohlmuth, CMAME 194 (2005) 3147-3166;
 * A. Popp et al., IJNME 83 (2010) 1428-1465; S. Hueeber, G. Stadler,
 * B. Wohlmuth, SIAM J. Sci. Comput. 30 (2008) 572-596.
 */
#ifndef common_contact_contact_enforcement_h
#define common_contact_contact_enforcement_h

#include <common/contact/active_set_policy.h>
#include <common/contact/contact_parameters.h>
#include <common/contact/contact_state.h>
#include <common/contact/free_directions.h>
#include <common/contact/friction_model.h>
#include <common/contact/mortar_coupling.h>
#include <common/contact/normal_enforcement.h>
#include <common/contact/row_partition.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief Normal and frictional contact enforcement on the rows of a
     * MortarCoupling.
     */
    template <int dim>
    class ContactEnforcement
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;
      using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

      /**
       * @param[in] parameters Contact parameters.
       * @param[in] coupling Mortar operators; must outlive this object.
       * @param[in] reference_modulus Young's modulus used to scale the
       * complementarity constant (MPa).
       */
      ContactEnforcement(const ContactParameters   &parameters,
                         const MortarCoupling<dim> &coupling,
                         const double               reference_modulus);

      /**
       * @brief Distribute the rows over the MPI ranks (RowPartition): this
       * rank owns the rows of the secondary nodes whose first DoF is in
       * @p owned_dofs, and holds as ghost rows those of the other nodes
       * with a DoF in @p needed_dofs (the DoFs of its cells and the
       * targets of their constraints). Without this call every row is
       * owned (serial). Call after the constructor, before
       * initialize_active_set(); collective.
       */
      void
      distribute_rows(const dealii::IndexSet &owned_dofs,
                      const dealii::IndexSet &needed_dofs,
                      const MPI_Comm          communicator);

      /** @brief The rows this rank owns and holds. */
      const RowPartition &
      rows() const;

      /**
       * @brief Start the active set from the geometry of the coupling:
       * nodes that touch (pointwise gap <= 1e-8 h) are active. A body that
       * only touches its partner is thereby held from the first iteration
       * on, and the first linear system is not singular. If no touching
       * node carries a multiplier (positive weight; e.g. a sphere that
       * touches at the axis node of an axisymmetric Q2 mesh, which has no
       * ring measure), the paired node of positive weight with the
       * smallest gap starts active too; the semismooth Newton iteration
       * opens it if it carries no pressure. Collective.
       */
      void
      initialize_active_set();

      /**
       * @brief Mark the secondary nodes with a DoF fixed by @p constraints
       * (Dirichlet conditions, e.g. a symmetry plane, or hanging nodes).
       * Friction acts only along the tangent directions orthogonal to the
       * fixed DoFs: on a symmetry plane of a 3D model, along the line
       * where plane and contact surface meet; a node without such a
       * direction (on an axis, or with every DoF fixed) counts as sticking
       * when closed. A node whose fixed DoFs hold its normal (every DoF
       * fixed, or a support along the normal) cannot take the normal
       * condition: its normal complementarity does not count, and while
       * it sticks it is held along its free tangents alone
       * (DualLagrangeEnforcement::add_constraints()). Call once, after
       * the constructor.
       */
      void
      mark_constrained_nodes(
        const dealii::AffineConstraints<double> &constraints);

      /**
       * @brief Keep the current active set and tractions as the state of
       * the last accepted load step, and with it the friction history: the
       * relative displacement of every node at @p u, from which the next
       * step's slip increments are measured, and the slip accumulated while
       * in contact. A node that closed during the step is credited with the
       * fraction of its increment after the contact edge passed it; the
       * edge is taken midway between the last closed and the first open
       * node at the start and at the end of the step, and assumed to move
       * uniformly within the step.
       * @param[in] u Converged displacement of the step (ghosted).
       */
      void
      commit(const VectorType &u);

      /** @brief Return to the state of the last accepted load step (after a
       * failed step, before a cutback). */
      void
      restore();

      /**
       * @brief Follow mortar rows that were integrated again (current
       * configuration): take the nodes' new normals into their free
       * directions and measure the friction history from
       * @p accepted_relative, the relative displacement of the last
       * accepted state with the new rows
       * (ContactGeometry::accepted_relative_displacements()).
       */
      void
      update_geometry(
        const std::vector<dealii::Tensor<1, dim>> &accepted_relative);

      /** @brief Forget the active-set history used to detect cycling; call
       * at the start of each load step. */
      void
      begin_step();

      /**
       * @brief Add to @p dsp every coupling that contact can create, for
       * any active set and either enforcement: for each locally owned cell,
       * its DoFs together with the primary DoFs of every paired secondary
       * node of the cell, all coupled with each other, and distributed
       * through @p constraints (hanging nodes, Dirichlet conditions). The
       * same for the cells marked in @p extra_cells (by active cell index;
       * may be empty): with friction under MPI, the cells around the
       * rank's own secondary nodes (cells_around_owned_nodes()).
       */
      void
      add_sparsity_entries(const dealii::DoFHandler<dim>           &dof_handler,
                           const dealii::AffineConstraints<double> &constraints,
                           const std::vector<bool>                 &extra_cells,
                           dealii::DynamicSparsityPattern          &dsp) const;

      /**
       * @brief Lagrange multipliers: add one constraint per active node on
       * the Newton increment, such that the weighted gap of the updated
       * displacement vanishes. @p constraints must already hold the
       * Dirichlet constraints (it is not closed here). Nothing with a
       * penalty (NormalEnforcement::add_constraints()).
       * @param[in] u Current displacement (ghosted).
       * @param[in] gap_derivatives The full derivatives of the weighted
       * gaps where the rows follow the configuration (null where the fixed
       * rows' gradient is exact).
       * @param[out] corrections If not null, receives the difference of
       * the nodes' full linearised conditions from their constraints
       * (TrialCorrection).
       */
      void
      add_constraints(dealii::AffineConstraints<double> &constraints,
                      const VectorType                  &u,
                      const typename NormalEnforcement<dim>::GapDerivatives
                                       *gap_derivatives = nullptr,
                      TrialCorrections *corrections     = nullptr) const;

      /**
       * @brief Coulomb friction: add the tangential traction
       * \f$\mu\lambda_j(u)e_j + k_j (v_j(u)\cdot e_{\perp j}) e_{\perp j}\f$
       * of every slipping node whose first DoF is in @p locally_owned, and
       * its linearisation, which couples the node's bulk stiffness row into
       * its primary partners' rows (CoulombLaw::slip_linearisation(); the
       * second term exists in 3D only and vanishes at convergence). Matrix
       * and vector are not compressed here. Nothing without friction
       * (FrictionModel::assemble()).
       * @param[in] u Current displacement (ghosted).
       * @param[in] bulk_matrix Tangent of the bulk residual, condensed with
       * the Dirichlet and hanging-node constraints only; supplies the rows
       * of the slipping nodes (which must be locally owned).
       * @param[in] bulk_residual f_ext - f_int at the current u (N,
       * ghosted), condensed like @p bulk_matrix.
       * @param[in] corrections If not null, the iteration's trial
       * corrections (FrictionModel::assemble()).
       */
      void
      assemble_friction(const dealii::AffineConstraints<double> &constraints,
                        const VectorType                        &u,
                        const MatrixType                        &bulk_matrix,
                        const VectorType                        &bulk_residual,
                        const dealii::IndexSet                  &locally_owned,
                        MatrixType                              &matrix,
                        VectorType                              &residual,
                        const TrialCorrections *corrections = nullptr) const;

      /** @brief True if Coulomb friction with mu > 0 is enforced. */
      bool
      has_friction() const;

      /**
       * @brief Penalty: add tangent and residual of the penalty terms for
       * the nodes whose first DoF is in @p locally_owned. Matrix and vector
       * are not compressed here. Nothing with Lagrange multipliers
       * (NormalEnforcement::assemble()).
       * @param[in] gap_derivatives The full derivatives of the weighted gaps
       * where the rows follow the configuration, or null.
       */
      void
      assemble_penalty(const dealii::AffineConstraints<double> &constraints,
                       const VectorType                        &u,
                       const dealii::IndexSet                  &locally_owned,
                       MatrixType                              &matrix,
                       VectorType                              &residual,
                       const typename NormalEnforcement<dim>::GapDerivatives
                         *gap_derivatives = nullptr) const;

      /**
       * @brief Update the nodal pressures and tangential tractions: from
       * the residual force @p bulk_residual = f_ext - f_int (N, ghosted)
       * for Lagrange multipliers, pressures from the penalty law otherwise.
       */
      void
      update_pressures(const VectorType &u, const VectorType &bulk_residual);

      /**
       * @brief Lagrange multipliers only: where the pressure recovered by
       * update_pressures() at a closed node is tensile, but the multiplier
       * of the linearised Newton step, \f$n_j\cdot r^{lin}_j/D_j\f$ with
       * @p linearized_residual = r(u_k) + r'(u_k) du (N, ghosted), is
       * larger, take the latter. The residual at a new iterate also holds
       * the step's nonlinear error, which is no contact traction; on a
       * slender body held at a few nodes by small forces it would open a
       * supporting node. A node then opens only if both say tension; the
       * two agree at convergence.
       *
       * The same holds for friction: a sticking node whose recovered
       * tractions lie outside the Coulomb cone, but whose linearised ones
       * (the tangential part of \f$r^{lin}_j/D_j\f$) lie inside, keeps the
       * linearised tractions and so keeps sticking. A node then starts to
       * slip only if both say so. @p u is the new iterate (ghosted).
       */
      void
      keep_linearized_compression(const VectorType &u,
                                  const VectorType &linearized_residual);

      /**
       * @brief Add the contact forces of the nodal tractions
       * \f$-\lambda_j n_j + t_j\f$ (pressure and tangential traction) to
       * @p residual (N): \f$D_j\f$ times the traction on secondary node j,
       * \f$-M_{jk}\f$ times it on primary node k, for the nodes whose
       * first DoF is in @p locally_owned, distributed through
       * @p constraints (forces on constrained DoFs, such as hanging nodes
       * or the nodes of a rigid body, move to the DoFs they depend on).
       * Not compressed here.
       */
      void
      add_contact_forces(const dealii::AffineConstraints<double> &constraints,
                         const dealii::IndexSet                  &locally_owned,
                         VectorType &residual) const;

      /**
       * @brief Apply the active-set rule to every paired node: the normal
       * rule, then for closed nodes with friction the stick/slip rule
       * CoulombLaw::is_sticking() with the bound
       * \f$\mu\max(0, \lambda - c\,g)\f$, the tangential constant
       * tangential_ncp_constant() and the slip direction.
       *
       * If the rule only opens points, the opened band is extrapolated
       * (unless switched off): a closed node j is opened too if an opened
       * node r lies within twice r's distance to the closed set. Near a
       * smooth contact edge the pressure of an oversized zone of width b is
       * negative over a band of about half the excess b - a, so mirroring
       * the band about its inner end lands on the edge a. If a later
       * iteration of the step must close points again, the extrapolation
       * stays off for the rest of the step.
       *
       * If the rule returns to an active set seen earlier in the step
       * (ping-pong between open and closed, or stick and slip), only the
       * point with the largest complementarity violation is changed,
       * choosing one that leads to an unseen set; is_cycling() reports the
       * case where none exists.
       *
       * Each rank decides the nodes it owns and then receives the status
       * of its ghost nodes from their owners; collective.
       * @param[in] residual Newton residual of the iterate @p u in a
       * nonlinear problem, where a set revisited after a decade of progress
       * is no cycle (ActiveSetPolicy::update()); negative for a linear one.
       * @param[in] one_point Change only the point with the largest
       * complementarity violation (ActiveSetPolicy::update()).
       * @return Number of nodes (over all ranks) whose status (or slip
       * direction) changed.
       */
      unsigned int
      update_active_set(const VectorType &u,
                        const double      residual  = -1.,
                        const bool        one_point = false);

      /** @brief True if the last update changed one point and went back
       * to a set held earlier in the step
       * (ActiveSetPolicy::revisits_held_set()). */
      bool
      revisits_held_set() const;

      /** @brief True if the last update could only return to an active
       * set seen earlier in this step (the set is then left unchanged). */
      bool
      is_cycling() const;

      /** @brief Forget the active sets seen so far in the step but the
       * current one (ActiveSetPolicy::restart_history()). */
      void
      restart_cycle_detection();

      /** @brief ActiveSetPolicy::begin_linearisation(). */
      void
      begin_linearisation();

      /** @brief ActiveSetPolicy::end_linearisation(). */
      void
      end_linearisation();

      /** @brief Norm of the normal and tangential complementarity
       * functions weighted by D_j (N), over all ranks; collective. */
      double
      complementarity_norm(const VectorType &u) const;

      /** @brief Status of secondary node j. */
      PointStatus
      status(const unsigned int j) const;

      /** @brief Tangential traction on the secondary surface at node j
       * (MPa), a vector of the tangent plane. */
      const dealii::Tensor<1, dim> &
      tangential_traction(const unsigned int j) const;

      /** @brief Increment, since the last accepted step, of the relative
       * tangential displacement at node j (primary minus secondary, mm). */
      dealii::Tensor<1, dim>
      slip_increment(const unsigned int j, const VectorType &u) const;

      /** @brief Relative tangential displacement accumulated at node j
       * while in contact, over the accepted steps (mm). */
      const dealii::Tensor<1, dim> &
      accumulated_slip(const unsigned int j) const;

      /** @brief Pressure lambda_j of secondary node j (MPa). */
      double
      pressure(const unsigned int j) const;

      /** @brief True if node j is active (closed). */
      bool
      is_active(const unsigned int j) const;

      /** @brief Number of active nodes over all ranks (counted when the
       * active set was last set, so not a collective). */
      unsigned int
      n_active() const;

      /** @brief True if an active node neighbours an unpaired node: the
       * contact zone has reached the edge of the search region.
       * Collective. */
      bool
      touches_search_edge() const;

      /** @brief Complementarity constant of node j (MPa/mm). */
      double
      ncp_constant(const unsigned int j) const;

      /** @brief Tangential complementarity constant of node j, used in
       * the stick/slip decision of Coulomb friction (MPa/mm). */
      double
      tangential_ncp_constant(const unsigned int j) const;

      /** @brief The state of the nodes (ContactState). */
      const ContactState<dim> &
      state() const;

      /** @brief The normal enforcement (NormalEnforcement). */
      const NormalEnforcement<dim> &
      normal_enforcement() const;

      /** @brief The friction model (FrictionModel). */
      const FrictionModel<dim> &
      friction_model() const;

      /** @brief The active-set policy (ActiveSetPolicy). */
      const ActiveSetPolicy<dim> &
      active_set_policy() const;

    private:
      const MortarCoupling<dim>                    &coupling;
      FreeDirections<dim>                           directions;
      ContactState<dim>                             contact_state;
      const std::unique_ptr<NormalEnforcement<dim>> normal;
      const std::unique_ptr<FrictionModel<dim>>     friction;
      ActiveSetPolicy<dim>                          policy;
      /** Active nodes over all ranks, now and at the last accepted step. */
      unsigned int n_active_nodes    = 0;
      unsigned int n_accepted_active = 0;

      /** Count the active nodes over all ranks (collective). */
      void
      count_active();
    };
  } // namespace Contact
} // namespace Common

#endif
