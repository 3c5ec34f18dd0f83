/**
 * @file friction_model.h
 * Tangential contact: an interface for friction laws in the semismooth
 * Newton method with condensed multipliers, and its frictionless and
 * Coulomb implementations. A law answers, without a mesh, for a closed
 * node with given traction, slip increment and normal pressure: does it
 * stick or slip in the next iteration, in which direction and with which
 * turning stiffness, and what is its tangential complementarity function;
 * and it assembles the terms its slipping nodes add to the linear system.
 * Another law is added as another implementation, without touching the
 * normal enforcement or the active-set policy.
 *
 * Coulomb friction (exact, primal-dual active set = semismooth Newton on
 * CoulombLaw::complementarity()): a closed node either sticks or slips. A
 * sticking node is held by the constraints of the normal enforcement. A
 * slipping node carries the tangential traction \f$\mu\lambda_j e_j\f$
 * along the slip direction e_j of the active set, where \f$\lambda_j =
 * n_j\cdot r_j(u)/D_j\f$ is linear in u through the bulk stiffness rows
 * of the node; this term makes the system non-symmetric. In 2D the tangent
 * plane is a line, e_j is constant within an iteration, and the iteration
 * is the exact semismooth Newton method; in 3D the direction is updated by
 * the active-set loop, with the turning stiffness across it.
 *
 * Reference: S. Hueeber, G. Stadler, B. Wohlmuth, SIAM J. Sci. Comput. 30
 * (2008) 572-596; A. Gitterle et al., IJNME 84 (2010) 543-571.
 */
#ifndef common_contact_friction_model_h
#define common_contact_friction_model_h

#include <common/contact/contact_parameters.h>
#include <common/contact/contact_state.h>
#include <common/contact/mortar_coupling.h>
#include <common/contact/trial_corrections.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief What a friction law is evaluated with at a closed node.
     */
    template <int dim>
    struct FrictionPoint
    {
      /** Tangential traction t of the current iterate on the secondary
       * surface (MPa). */
      dealii::Tensor<1, dim> traction;
      /** Slip increment v since the last accepted load step, along the
       * free tangents (mm). */
      dealii::Tensor<1, dim> slip_increment;
      /** Normal pressure that the normal complementarity function predicts
       * for the next iterate, \f$\max(0, \lambda - c_N g)\f$ (MPa). */
      double normal_pressure = 0.;
      /** Tangential complementarity constant (MPa/mm), > 0. */
      double c = 1.;
      /** Number of free tangent directions of the node (0 to dim - 1). */
      unsigned int n_free_tangents = dim - 1;
    };

    /**
     * @brief Tangential state of a closed node for the next iteration.
     */
    template <int dim>
    struct FrictionStatus
    {
      /** stick or slip. */
      PointStatus status = PointStatus::slip;
      /** Unit direction of the traction of a slipping node; zero
       * otherwise. */
      dealii::Tensor<1, dim> slip_direction;
      /** Turning stiffness across the slip direction (MPa/mm); 0 where
       * the node does not slip or cannot turn. */
      double turning_stiffness = 0.;
    };

    /**
     * @brief A friction law in the semismooth Newton method.
     */
    template <int dim>
    class FrictionModel
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;
      using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

      /** @brief Virtual destructor of the interface. */
      virtual ~FrictionModel() = default;

      /** @brief True if the law can produce a tangential traction (and
       * then a non-symmetric system). */
      virtual bool
      has_friction() const = 0;

      /** @brief Status of a node that closes without slip history (at the
       * start of a computation). */
      virtual PointStatus
      status_on_contact() const = 0;

      /** @brief The stick/slip rule: the tangential state of a closed node
       * in the next iteration. Evaluable without a mesh. */
      virtual FrictionStatus<dim>
      closed_status(const FrictionPoint<dim> &point) const = 0;

      /** @brief Tangential complementarity function (MPa), zero exactly
       * where the law holds. Evaluable without a mesh. */
      virtual dealii::Tensor<1, dim>
      complementarity(const FrictionPoint<dim> &point) const = 0;

      /**
       * @brief Add the tangential terms of the slipping nodes of @p state
       * whose first DoF is in @p locally_owned, and their linearisation.
       * Matrix and vector are not compressed here.
       * @param[in] u Current displacement (ghosted).
       * @param[in] bulk_matrix Tangent of the bulk residual, condensed with
       * the Dirichlet and hanging-node constraints only; supplies the rows
       * of the slipping nodes (which must be locally owned).
       * @param[in] bulk_residual f_ext - f_int at @p u (N, ghosted),
       * condensed like @p bulk_matrix.
       * @param[in] corrections If not null, the iteration's trial
       * corrections: the tangent's columns move to the full linearisation
       * of the contact conditions (TrialCorrections::extend_columns()).
       */
      virtual void
      assemble(const MortarCoupling<dim>               &coupling,
               const ContactState<dim>                 &state,
               const dealii::AffineConstraints<double> &constraints,
               const VectorType                        &u,
               const MatrixType                        &bulk_matrix,
               const VectorType                        &bulk_residual,
               const dealii::IndexSet                  &locally_owned,
               MatrixType                              &matrix,
               VectorType                              &residual,
               const TrialCorrections                  *corrections) const = 0;
    };



    /**
     * @brief No tangential traction: every closed node slips freely.
     */
    template <int dim>
    class Frictionless : public FrictionModel<dim>
    {
    public:
      using typename FrictionModel<dim>::VectorType;
      using typename FrictionModel<dim>::MatrixType;

      /** @brief False. */
      bool
      has_friction() const override;

      /** @brief slip. */
      PointStatus
      status_on_contact() const override;

      /** @brief slip, without direction. */
      FrictionStatus<dim>
      closed_status(const FrictionPoint<dim> &point) const override;

      /** @brief Zero. */
      dealii::Tensor<1, dim>
      complementarity(const FrictionPoint<dim> &point) const override;

      /** @brief Nothing. */
      void
      assemble(const MortarCoupling<dim>               &coupling,
               const ContactState<dim>                 &state,
               const dealii::AffineConstraints<double> &constraints,
               const VectorType                        &u,
               const MatrixType                        &bulk_matrix,
               const VectorType                        &bulk_residual,
               const dealii::IndexSet                  &locally_owned,
               MatrixType                              &matrix,
               VectorType                              &residual,
               const TrialCorrections *corrections) const override;
    };



    /**
     * @brief Exact Coulomb friction: stick while
     * \f$|t + c\,v| \le \mu p\f$, slip with \f$|t| = \mu p\f$ along the
     * trial direction otherwise (CoulombLaw). With mu = 0 it is
     * frictionless.
     */
    template <int dim>
    class CoulombFriction : public FrictionModel<dim>
    {
    public:
      using typename FrictionModel<dim>::VectorType;
      using typename FrictionModel<dim>::MatrixType;

      /** @param[in] friction_coefficient mu (dimensionless), >= 0. */
      explicit CoulombFriction(const double friction_coefficient);

      /** @brief True if mu > 0. */
      bool
      has_friction() const override;

      /** @brief stick if mu > 0 (no slip history), else slip. */
      PointStatus
      status_on_contact() const override;

      /**
       * @brief CoulombLaw::is_sticking() with the bound
       * \f$s = \mu p\f$ (p = @p point.normal_pressure); a node without a
       * free tangent sticks. A slipping node takes the direction and the
       * turning stiffness of CoulombLaw::slip_linearisation(), the latter
       * only if no tangent direction of the node is fixed (it acts in 3D
       * only) and bounded by 1e3 c, so that a node just past the
       * stick limit does not make the tangent ill-conditioned (the
       * converged state does not depend on it).
       */
      FrictionStatus<dim>
      closed_status(const FrictionPoint<dim> &point) const override;

      /** @brief CoulombLaw::complementarity() with \f$s = \mu p\f$; zero
       * for a node without a free tangent. */
      dealii::Tensor<1, dim>
      complementarity(const FrictionPoint<dim> &point) const override;

      /**
       * @brief The tangential traction
       * \f$\mu\lambda_j(u)e_j + k_j (v_j(u)\cdot e_{\perp j}) e_{\perp j}\f$
       * of every slipping node with a free tangent, and its linearisation,
       * which couples the node's bulk stiffness row into its primary
       * partners' rows (CoulombLaw::slip_linearisation(); the second term
       * exists in 3D only and vanishes at convergence).
       */
      void
      assemble(const MortarCoupling<dim>               &coupling,
               const ContactState<dim>                 &state,
               const dealii::AffineConstraints<double> &constraints,
               const VectorType                        &u,
               const MatrixType                        &bulk_matrix,
               const VectorType                        &bulk_residual,
               const dealii::IndexSet                  &locally_owned,
               MatrixType                              &matrix,
               VectorType                              &residual,
               const TrialCorrections *corrections) const override;

    private:
      const double mu;
    };



    /**
     * @brief The friction model that @p parameters select ("Friction law"
     * and "Friction coefficient" in subsection "Contact").
     */
    template <int dim>
    std::unique_ptr<FrictionModel<dim>>
    create_friction_model(const ContactParameters &parameters);
  } // namespace Contact
} // namespace Common

#endif
