/**
 * @file normal_enforcement.h
 * Enforcement of the normal contact condition on the closed secondary
 * nodes of a contact pair: an interface and its two implementations,
 * condensed dual Lagrange multipliers and penalty.
 *
 * Dual Lagrange multipliers (DualLagrangeEnforcement): with dual
 * multipliers D is diagonal, so a closed node's constraint
 * \f$\tilde g_j(u) = 0\f$ can be solved for one displacement component of
 * the node: the multiplier is condensed out locally and the linear system
 * keeps the size and structure of a problem without contact. A sticking
 * node's relative tangential displacement is held at its value of the last
 * accepted load step as well; together with the normal condition that
 * fixes the whole node to the mean motion of its primary partners,
 * \f$D_j u_j = \sum_k M_{jk} u_k - w_j\f$. The multiplier follows
 * afterwards from the residual of the node, \f$\lambda_j = r_j\cdot n_j /
 * D_j\f$, and with friction the tangential traction too,
 * \f$t_j = -(I - n_j n_j^T) r_j / D_j\f$.
 *
 * Penalty (PenaltyEnforcement): a closed node is a spring of stiffness
 * epsilon D_j on its normal gap \f$g_j = \tilde g_j / D_j\f$,
 * \f$\lambda_j = \epsilon\max(0, -g_j)\f$.
 *
 * Reference: S. Hueeber, B. Wohlmuth, CMAME 194 (2005) 3147-3166;
 * A. Popp et al., IJNME 83 (2010) 1428-1465.
 */
#ifndef common_contact_normal_enforcement_h
#define common_contact_normal_enforcement_h

#include <common/contact/contact_parameters.h>
#include <common/contact/contact_state.h>
#include <common/contact/mortar_coupling.h>
#include <common/contact/trial_corrections.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief How the normal condition acts on the closed nodes: the
     * normal active-set rule, the terms of the linear system, and the
     * pressures of an iterate.
     */
    template <int dim>
    class NormalEnforcement
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;
      using MatrixType = dealii::TrilinosWrappers::SparseMatrix;
      /** Per row of a coupling: the full derivative of its weighted gap
       * (ContactGeometry::weighted_gap_derivative()) as (DoF, value in
       * mm^(dim-1)) pairs; empty where the fixed rows' gradient
       * (gap_gradient()) is exact. */
      using GapDerivatives = std::vector<
        std::vector<std::pair<dealii::types::global_dof_index, double>>>;

      /** @brief Virtual destructor of the interface. */
      virtual ~NormalEnforcement() = default;

      /**
       * @brief True if the pressures are Lagrange multipliers, unknowns
       * whose complementarity with the gap the Newton iteration must
       * satisfy; false if they follow from the gap (penalty), so that
       * equilibrium alone measures convergence.
       */
      virtual bool
      has_multipliers() const = 0;

      /**
       * @brief The normal active-set rule: true if a node with pressure
       * @p pressure (MPa) and gap @p gap (mm, negative when penetrating)
       * is closed in the next iteration. Evaluable without a mesh.
       * @param[in] c Complementarity constant (MPa/mm), > 0.
       */
      virtual bool
      is_closed(const double pressure,
                const double gap,
                const double c) const = 0;

      /**
       * @brief Normal complementarity function
       * NormalContactLaw::complementarity() of @p pressure and @p gap
       * (MPa): its norm measures convergence with multipliers, and ranks
       * the nodes when the active set cycles. Evaluable without a mesh.
       */
      virtual double
      complementarity(const double pressure,
                      const double gap,
                      const double c) const = 0;

      /**
       * @brief Add the constraints of the closed nodes of @p state on the
       * Newton increment to @p constraints, which must already hold the
       * Dirichlet constraints (it is not closed here): for the nodes this
       * rank holds (ContactState::rows()). Nothing for a penalty. May be
       * collective (the diagnostics are summed over the ranks).
       * @param[in] u Current displacement (ghosted).
       * @param[in] gap_derivatives The full derivatives of the weighted
       * gaps where the rows follow the configuration; null, or an empty
       * entry, where the fixed rows' gradient is exact.
       * @param[out] corrections If not null, receives the TrialCorrection
       * of every constrained DoF whose condition the full derivative
       * changes.
       */
      virtual void
      add_constraints(const MortarCoupling<dim>         &coupling,
                      const ContactState<dim>           &state,
                      const VectorType                  &u,
                      dealii::AffineConstraints<double> &constraints,
                      const GapDerivatives              *gap_derivatives,
                      TrialCorrections                  *corrections) const = 0;

      /**
       * @brief Add tangent and residual of the terms of the closed nodes
       * whose first DoF is in @p locally_owned. Matrix and vector are not
       * compressed here. Nothing with multipliers (they are condensed
       * into the constraints).
       * @param[in] gap_derivatives The full derivatives of the weighted
       * gaps where the rows follow the configuration; null, or an empty
       * entry, where the fixed rows' gradient is used.
       */
      virtual void
      assemble(const MortarCoupling<dim>               &coupling,
               const ContactState<dim>                 &state,
               const dealii::AffineConstraints<double> &constraints,
               const VectorType                        &u,
               const dealii::IndexSet                  &locally_owned,
               MatrixType                              &matrix,
               VectorType                              &residual,
               const GapDerivatives *gap_derivatives) const = 0;

      /**
       * @brief Set the pressures of the current iterate in @p state (zero
       * on open nodes), and with @p with_friction the tangential tractions
       * (zero otherwise), at the nodes this rank holds.
       * @param[in] u Current displacement (ghosted).
       * @param[in] bulk_residual f_ext - f_int at @p u (N, ghosted),
       * condensed with the Dirichlet and hanging-node constraints.
       */
      virtual void
      update_tractions(const MortarCoupling<dim> &coupling,
                       const VectorType          &u,
                       const VectorType          &bulk_residual,
                       const bool                 with_friction,
                       ContactState<dim>         &state) const = 0;
    };



    /**
     * @brief Closed nodes whose constraints the last
     * DualLagrangeEnforcement::add_constraints() could not set up in full
     * (over all ranks).
     */
    struct ConstraintDiagnostics
    {
      /** Sticking nodes whose normal has no free component (a Dirichlet
       * condition fixes their normal displacement): held along their free
       * tangents only, the normal condition left to the support. */
      unsigned int n_stick_without_normal = 0;
      /** Closed nodes on which no constraint can act: every component
       * fixed, or every one along the normal while the node slips or has
       * no free tangent. Their contact condition is not enforced. */
      unsigned int n_unconstrained = 0;
    };



    /**
     * @brief Condensed dual Lagrange multipliers: the affine constraints of
     * the closed nodes, and the multipliers recovered from the residual.
     */
    template <int dim>
    class DualLagrangeEnforcement : public NormalEnforcement<dim>
    {
    public:
      using typename NormalEnforcement<dim>::VectorType;
      using typename NormalEnforcement<dim>::MatrixType;

      /** @brief True. */
      bool
      has_multipliers() const override;

      /** @brief NormalContactLaw::is_active(): \f$\lambda - c\,g > 0\f$. */
      bool
      is_closed(const double pressure,
                const double gap,
                const double c) const override;

      /** @brief NormalContactLaw::complementarity(). */
      double
      complementarity(const double pressure,
                      const double gap,
                      const double c) const override;

      /**
       * @brief One constraint per closed node such that the weighted gap
       * of the updated displacement vanishes, solved for the free
       * component with the largest normal share. A sticking node is fixed
       * to the mean motion of its primary partners plus its relative
       * displacement at the last accepted step: the whole node where no
       * component is fixed, the normal and its free tangent directions
       * (solved for its free components) where some are (a symmetry
       * plane). Where that system is singular because the normal has no
       * free component (a Dirichlet condition fixes the normal
       * displacement), the sticking node is held along its free tangents
       * alone, so that it keeps its friction force; such nodes are
       * counted (diagnostics()) and reported once on the standard error
       * stream. So is a closed node on which no constraint can act (every
       * component fixed, or every one along the normal while it slips).
       *
       * Where @p gap_derivatives holds a node's full derivative, a node
       * held by its normal condition alone (slip, or no free tangent) gets
       * a TrialCorrection: its linearised condition
       * \f$g_j + \sum_q \partial g_j/\partial u_q\,\Delta u_q = 0\f$
       * over its own DoFs and its primary partners' (the terms of the other
       * secondary nodes, which the fixed rows' gradient leaves out as well,
       * are left out), less the constraint written here. A sticking node's
       * constraint stays that of the fixed rows: with its normal condition
       * from the full derivative and its tangential ones from the fixed
       * rows, the rigid turn of tests/common/current_contact_objectivity_01
       * took 5 Newton iterations per step instead of 4.
       */
      void
      add_constraints(
        const MortarCoupling<dim>                             &coupling,
        const ContactState<dim>                               &state,
        const VectorType                                      &u,
        dealii::AffineConstraints<double>                     &constraints,
        const typename NormalEnforcement<dim>::GapDerivatives *gap_derivatives,
        TrialCorrections *corrections) const override;

      /** @brief Nothing: the multipliers are condensed. */
      void
      assemble(const MortarCoupling<dim>               &coupling,
               const ContactState<dim>                 &state,
               const dealii::AffineConstraints<double> &constraints,
               const VectorType                        &u,
               const dealii::IndexSet                  &locally_owned,
               MatrixType                              &matrix,
               VectorType                              &residual,
               const typename NormalEnforcement<dim>::GapDerivatives
                 *gap_derivatives) const override;

      /**
       * @brief Equilibrium of closed node j, \f$r_j + D_j(-\lambda_j n_j +
       * t_j) = 0\f$: \f$\lambda_j = n_j\cdot r_j/D_j\f$ and, with friction,
       * \f$t_j = -P r_j/D_j\f$ with P the projection onto the node's free
       * tangents.
       */
      void
      update_tractions(const MortarCoupling<dim> &coupling,
                       const VectorType          &u,
                       const VectorType          &bulk_residual,
                       const bool                 with_friction,
                       ContactState<dim>         &state) const override;

      /** @brief Counts of the closed nodes that the last
       * add_constraints() could not constrain in full. */
      const ConstraintDiagnostics &
      diagnostics() const;

    private:
      mutable ConstraintDiagnostics last_diagnostics;
      /** True once a kind of ConstraintDiagnostics has been reported. */
      mutable bool warned_stick         = false;
      mutable bool warned_unconstrained = false;
    };



    /**
     * @brief Penalty: a closed node carries
     * \f$\lambda = \epsilon\max(0, -g)\f$.
     */
    template <int dim>
    class PenaltyEnforcement : public NormalEnforcement<dim>
    {
    public:
      using typename NormalEnforcement<dim>::VectorType;
      using typename NormalEnforcement<dim>::MatrixType;

      /** @param[in] stiffness Penalty stiffness epsilon (MPa/mm), > 0. */
      explicit PenaltyEnforcement(const double stiffness);

      /** @brief False. */
      bool
      has_multipliers() const override;

      /** @brief Closed where NormalContactLaw::penalty_derivative() is not
       * zero: penetrating or touching (g <= 0). */
      bool
      is_closed(const double pressure,
                const double gap,
                const double c) const override;

      /** @brief The departure of the node's force from the penalty law,
       * given @p pressure from update_tractions(): -k g on a closed node
       * whose gap is positive (it pulls), k g on an open node that
       * penetrates, 0 otherwise (MPa). Its norm measures how far the
       * active set is from the law, in the units of the equilibrium
       * residual; it ranks the nodes when the active set cycles. */
      double
      complementarity(const double pressure,
                      const double gap,
                      const double c) const override;

      /** @brief Nothing: a penalty adds no constraints. */
      void
      add_constraints(
        const MortarCoupling<dim>                             &coupling,
        const ContactState<dim>                               &state,
        const VectorType                                      &u,
        dealii::AffineConstraints<double>                     &constraints,
        const typename NormalEnforcement<dim>::GapDerivatives *gap_derivatives,
        TrialCorrections *corrections) const override;

      /**
       * @brief Residual \f$p B\f$ and tangent
       * \f$\epsilon/D_j\,B G^T\f$ of every closed node, B the gradient of
       * its weighted gap with the rows fixed (gap_gradient()), which
       * distributes the force, G the full gradient where the rows follow
       * the configuration (@p gap_derivatives; B otherwise), p = -epsilon g.
       * A closed node is a spring for the whole iteration, also where its
       * gap has turned positive.
       */
      void
      assemble(const MortarCoupling<dim>               &coupling,
               const ContactState<dim>                 &state,
               const dealii::AffineConstraints<double> &constraints,
               const VectorType                        &u,
               const dealii::IndexSet                  &locally_owned,
               MatrixType                              &matrix,
               VectorType                              &residual,
               const typename NormalEnforcement<dim>::GapDerivatives
                 *gap_derivatives) const override;

      /** @brief Pressures of the springs of assemble(), -epsilon g on a
       * closed node (a pull where its gap has turned positive, which the
       * active-set update then opens; at convergence
       * NormalContactLaw::penalty_pressure()), zero on an open one; no
       * tangential tractions. */
      void
      update_tractions(const MortarCoupling<dim> &coupling,
                       const VectorType          &u,
                       const VectorType          &bulk_residual,
                       const bool                 with_friction,
                       ContactState<dim>         &state) const override;

    private:
      const double stiffness;
    };



    /**
     * @brief The enforcement that @p parameters select ("Enforcement" in
     * subsection "Contact").
     */
    template <int dim>
    std::unique_ptr<NormalEnforcement<dim>>
    create_normal_enforcement(const ContactParameters &parameters);
  } // namespace Contact
} // namespace Common

#endif
