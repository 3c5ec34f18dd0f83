/**
 * @file contact_enforcement.h
 * Enforcement of the normal contact condition on the mortar rows of a
 * contact pair: the active set of the semismooth Newton method, its
 * condensation into affine constraints (dual Lagrange multipliers), the
 * penalty alternative, and the recovery of the nodal pressures.
 *
 * With dual multipliers D is diagonal, so an active node's constraint
 * \f$\tilde g_j(u) = 0\f$ can be solved for one displacement component of
 * the node: the multiplier is condensed out locally and the linear system
 * keeps the size and structure of a problem without contact. The
 * multiplier follows afterwards from the residual of that node,
 * \f$\lambda_j = r_j\cdot n_j / D_j\f$.
 *
 * Reference: S. Hueeber, B. Wohlmuth, CMAME 194 (2005) 3147-3166;
 * A. Popp et al., IJNME 83 (2010) 1428-1465.
 */
#ifndef common_contact_contact_enforcement_h
#define common_contact_contact_enforcement_h

#include <common/contact/contact_parameters.h>
#include <common/contact/mortar_coupling.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief Normal contact enforcement on the rows of a MortarCoupling.
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
       * @brief Start the active set from the geometry of the coupling:
       * nodes that touch (pointwise gap <= 1e-8 h) are active. A body that
       * only touches its partner is thereby held from the first iteration
       * on, and the first linear system is not singular.
       */
      void
      initialize_active_set();

      /** @brief Keep the current active set and pressures as the state of
       * the last accepted load step. */
      void
      commit();

      /** @brief Return to the state of the last accepted load step (after a
       * failed step, before a cutback). */
      void
      restore();

      /** @brief Forget the active-set history used to detect cycling; call
       * at the start of each load step. */
      void
      begin_step();

      /**
       * @brief Add to @p dsp every coupling that contact can create, for
       * any active set and either enforcement: for each locally owned cell,
       * its DoFs together with the primary DoFs of every paired secondary
       * node of the cell, all coupled with each other, and distributed
       * through @p constraints (hanging nodes, Dirichlet conditions).
       */
      void
      add_sparsity_entries(const dealii::DoFHandler<dim>           &dof_handler,
                           const dealii::AffineConstraints<double> &constraints,
                           dealii::DynamicSparsityPattern          &dsp) const;

      /**
       * @brief Lagrange multipliers: add one constraint per active node on
       * the Newton increment, such that the weighted gap of the updated
       * displacement vanishes. @p constraints must already hold the
       * Dirichlet constraints (it is not closed here).
       * @param[in] u Current displacement (ghosted).
       */
      void
      add_constraints(dealii::AffineConstraints<double> &constraints,
                      const VectorType                  &u) const;

      /**
       * @brief Penalty: add tangent and residual of the penalty terms for
       * the nodes whose first DoF is in @p locally_owned. Matrix and vector
       * are not compressed here.
       */
      void
      assemble_penalty(const dealii::AffineConstraints<double> &constraints,
                       const VectorType                        &u,
                       const dealii::IndexSet                  &locally_owned,
                       MatrixType                              &matrix,
                       VectorType                              &residual) const;

      /**
       * @brief Update the nodal pressures: from the residual force
       * @p bulk_residual = f_ext - f_int (N, ghosted) for Lagrange
       * multipliers, from the penalty law otherwise.
       */
      void
      update_pressures(const VectorType &u, const VectorType &bulk_residual);

      /**
       * @brief Add the contact forces \f$\sum_j\lambda_j\,\partial\tilde
       * g_j/\partial u\f$ to @p residual (N) for the nodes whose first DoF
       * is in @p locally_owned. Not compressed here.
       */
      void
      add_contact_forces(const dealii::IndexSet &locally_owned,
                         VectorType             &residual) const;

      /**
       * @brief Apply the active-set rule to every paired node.
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
       * (ping-pong), only the point with the largest complementarity
       * violation is changed, choosing one that leads to an unseen set;
       * is_cycling() reports the case where none exists.
       * @return Number of nodes whose status changed.
       */
      unsigned int
      update_active_set(const VectorType &u);

      /** @brief True if the last update could only return to an active
       * set seen earlier in this step. */
      bool
      is_cycling() const;

      /** @brief Norm of the complementarity function weighted by D_j (N). */
      double
      complementarity_norm(const VectorType &u) const;

      /** @brief Pressure lambda_j of secondary node j (MPa). */
      double
      pressure(const unsigned int j) const;

      /** @brief True if node j is active (closed). */
      bool
      is_active(const unsigned int j) const;

      /** @brief Number of active nodes. */
      unsigned int
      n_active() const;

      /** @brief True if an active node neighbours an unpaired node: the
       * contact zone has reached the edge of the search region. */
      bool
      touches_search_edge() const;

      /** @brief Complementarity constant of node j (MPa/mm). */
      double
      ncp_constant(const unsigned int j) const;

    private:
      const ContactParameters        parameters;
      const MortarCoupling<dim>     &coupling;
      const double                   reference_modulus;
      std::vector<bool>              active;
      std::vector<double>            pressures;
      std::vector<bool>              accepted_active;
      std::vector<double>            accepted_pressures;
      std::vector<std::vector<bool>> history;
      bool                           cycling;
      bool                           last_update_extrapolated;
      bool                           extrapolation_enabled;
    };
  } // namespace Contact
} // namespace Common

#endif
