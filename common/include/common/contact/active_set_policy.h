/**
 * @file active_set_policy.h
 * The active-set update of the semismooth Newton (primal-dual active set)
 * method and its safeguards: the initial active set, the normal rule of
 * the enforcement followed by the stick/slip rule of the friction model,
 * an extrapolated release of an oversized contact zone, and single-point
 * changes when the set cycles. Also the norm of the complementarity
 * functions that measures convergence, and the complementarity constants.
 *
 * The rule sees the nodes as plain data (NodeKinematics, ContactState) and
 * the laws through their interfaces (NormalEnforcement, FrictionModel): it
 * needs no mesh.
 *
 * With MPI (ContactState::rows()) each rank decides the nodes it owns; the
 * counts of changed nodes, the choice of the nearest node of the initial
 * set, the extrapolated release, the cycling test and the norm are
 * collectives over the rows' communicator, and give the serial results.
 *
 * Reference: S. Hueeber, B. Wohlmuth, CMAME 194 (2005) 3147-3166;
 * S. Hueeber, G. Stadler, B. Wohlmuth, SIAM J. Sci. Comput. 30 (2008)
 * 572-596.
 */
#ifndef common_contact_active_set_policy_h
#define common_contact_active_set_policy_h

#include <common/contact/contact_parameters.h>
#include <common/contact/contact_state.h>
#include <common/contact/friction_model.h>
#include <common/contact/mortar_coupling.h>
#include <common/contact/normal_enforcement.h>

#include <deal.II/base/tensor.h>

#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief Semismooth Newton active-set rule with its safeguards.
     */
    template <int dim>
    class ActiveSetPolicy
    {
    public:
      /**
       * @param[in] parameters Contact parameters: the factors of the
       * complementarity constants and "Accelerate active set release".
       * @param[in] reference_modulus Young's modulus used to scale the
       * complementarity constants (MPa).
       */
      ActiveSetPolicy(const ContactParameters &parameters,
                      const double             reference_modulus);

      /** @brief Normal complementarity constant \f$c_N E/h\f$ of a node
       * with mesh size @p mesh_size (mm), in MPa/mm. */
      double
      ncp_constant(const double mesh_size) const;

      /** @brief Tangential complementarity constant \f$c_T E/h\f$
       * (MPa/mm), used in the stick/slip decision. */
      double
      tangential_ncp_constant(const double mesh_size) const;

      /**
       * @brief Start the active set from the geometry: nodes that touch
       * (pointwise gap <= 1e-8 h) are closed, with
       * FrictionModel::status_on_contact(). A body that only touches its
       * partner is thereby held from the first iteration on, and the
       * first linear system is not singular. If no touching node carries
       * a multiplier (positive weight; e.g. a sphere that touches at the
       * axis node of an axisymmetric Q2 mesh, which has no ring measure),
       * the paired node of positive weight with the smallest gap closes
       * too; the iteration opens it if it carries no pressure. With
       * "Initial active set = nearest per body" only the paired node of
       * positive weight nearest to each primary body closes
       * (NodeKinematics::partner; the first in the surface's order on
       * ties), and in 3D the nodes of positive weight on its line along z
       * (same x and y to 1e-8 of their faces). Resets
       * @p state (ContactState::reset()); sets the nodes this rank holds
       * (collective).
       */
      void
      initialize(const std::vector<NodeKinematics<dim>> &nodes,
                 const FrictionModel<dim>               &friction,
                 ContactState<dim>                      &state) const;

      /** @brief Forget the active-set history used to detect cycling and
       * re-enable the extrapolation; call at the start of each load step. */
      void
      begin_step(const ContactState<dim> &state);

      /** @brief Forget the active-set history used to detect cycling: the
       * current set of @p state and the sets of the step's earlier calls
       * are the only ones seen. For a Newton iteration that has held a
       * cycling set until equilibrium, whose intermediate sets were judged
       * on states out of equilibrium; the sets of earlier equilibria, each
       * with a node on the wrong side, are never the solution. */
      void
      restart_history(const ContactState<dim> &state);

      /** @brief Set the history aside for an active-set iteration on one
       * linearisation: the sets seen on it alone count, from the current
       * set on, until end_linearisation(). */
      void
      begin_linearisation(const ContactState<dim> &state);

      /** @brief Restore the history set aside by begin_linearisation(),
       * with the current set as the one that produced the iterate. */
      void
      end_linearisation(const ContactState<dim> &state);

      /**
       * @brief Apply the active-set rule to every paired node: the normal
       * rule NormalEnforcement::is_closed(), then for closed nodes the
       * stick/slip rule FrictionModel::closed_status() with the normal
       * pressure \f$\max(0, \lambda - c\,g)\f$ and the tangential constant.
       *
       * If the rule only opens points, the opened band is extrapolated
       * (unless switched off): a closed node j is opened too if an opened
       * node r lies within twice r's distance to the closed set. Near a
       * smooth contact edge the pressure of an oversized zone of width b is
       * negative over a band of about half the excess b - a, so mirroring
       * the band about its inner end lands on the edge a. Only where the
       * closed nodes lie on one primary body (one contact zone). If a later
       * iteration of the step must close points again, the extrapolation
       * stays off for the rest of the step.
       *
       * If the rule returns to an active set seen earlier in the step
       * (ping-pong between open and closed, or stick and slip), only the
       * point with the largest complementarity violation is changed,
       * choosing one that leads to an unseen set. With friction, if none
       * exists, the changes that take a node from or to slip (opening it,
       * closing it, or reversing its slip) are tried with stick in their
       * place, the state between them; is_cycling() reports the case where
       * none of these leads to an unseen set either, and the set is then
       * left unchanged.
       *
       * In a nonlinear problem the iterate depends on where the iteration
       * stands, not on the set alone, and a set revisited after the
       * iteration has made progress is no cycle: with @p residual given, a
       * set seen earlier counts as seen only while @p residual is at least
       * a tenth of the residual that the set's last use produced. A true
       * cycle produces the same residuals again and is still caught, one
       * iteration later at most.
       *
       * Updates the nodes this rank owns (the ghost nodes follow with
       * ContactState::update_ghosts()); collective.
       * @param[in] nodes Kinematics of the nodes at the current iterate.
       * @param[in] residual Newton residual of the current iterate (the
       * larger of equilibrium and complementarity, the same on every
       * rank), which the current set produced; negative (the default):
       * every set seen in the step counts (a linear problem, whose iterate
       * depends on the set alone).
       * @param[in] one_point Change only the point with the largest
       * complementarity violation that leads to an unseen set, as after a
       * cycle (for an iteration that judges its sets on equilibria).
       * @return Number of nodes (over all ranks) whose status (or slip
       * sense) changed.
       */
      unsigned int
      update(const std::vector<NodeKinematics<dim>> &nodes,
             const NormalEnforcement<dim>           &normal,
             const FrictionModel<dim>               &friction,
             ContactState<dim>                      &state,
             const double                            residual  = -1.,
             const bool                              one_point = false);

      /** @brief True if the last update could only return to an active
       * set seen earlier in this step. */
      bool
      is_cycling() const;

      /** @brief True if the last update changed one point and thereby went
       * back to a set held at an earlier call of restart_history() in this
       * step, every other change leading to a set seen before. */
      bool
      revisits_held_set() const;

      /** @brief Norm of the normal and tangential complementarity
       * functions weighted by D_j (N) over the paired nodes of all ranks;
       * with a penalty, of the nodes' departures from the penalty law
       * (PenaltyEnforcement::complementarity()), the forces that the
       * active set misplaces. Collective. */
      double
      complementarity_norm(const std::vector<NodeKinematics<dim>> &nodes,
                           const NormalEnforcement<dim>           &normal,
                           const FrictionModel<dim>               &friction,
                           const ContactState<dim>                &state) const;

      /** @brief True if a closed node of @p state neighbours (shares a
       * face with) an unpaired node of positive weight: the contact zone
       * has reached the edge of the search region. Collective. */
      static bool
      touches_search_edge(const MortarCoupling<dim> &coupling,
                          const ContactState<dim>   &state);

    private:
      /** Active-set code of every node this rank owns, in order: status
       * and, along a single free tangent, the sense of the slip direction.
       * Used to detect cycling. */
      std::vector<int>
      codes(const ContactState<dim>           &state,
            const std::vector<NodeState<dim>> &nodes) const;

      /** The codes of the nodes' current states in @p state. */
      std::vector<int>
      codes(const ContactState<dim> &state) const;

      /** The extrapolated release of update(): clears @p next of the
       * owned closed nodes within twice the band of an opened node, unless
       * that would open the whole zone (collective). */
      void
      extrapolate_release(const std::vector<NodeKinematics<dim>> &nodes,
                          const RowPartition                     &rows,
                          const std::vector<bool>                &closed,
                          std::vector<bool>                      &next);

      /** The node whose change alone, of those that change from
       * @p current_codes to @p next_codes, leads to a set not in the
       * history (the entries that count, see update()) and has the
       * largest complementarity violation (the same on every rank);
       * numbers::invalid_unsigned_int if there is none (collective). If
       * every change leads to a seen set, the one that leads back to a set
       * of an earlier restart_history() instead; the second value is then
       * true. */
      std::pair<unsigned int, bool>
      single_change(const std::vector<NodeKinematics<dim>> &nodes,
                    const NormalEnforcement<dim>           &normal,
                    const FrictionModel<dim>               &friction,
                    const ContactState<dim>                &state,
                    const std::vector<int>                 &current_codes,
                    const std::vector<int>                 &next_codes) const;

      /** Normal (MPa) and tangential (MPa) complementarity functions of
       * node j. */
      std::pair<double, dealii::Tensor<1, dim>>
      complementarity(const unsigned int                      j,
                      const std::vector<NodeKinematics<dim>> &nodes,
                      const NormalEnforcement<dim>           &normal,
                      const FrictionModel<dim>               &friction,
                      const ContactState<dim>                &state) const;

      const double           ncp_factor;
      const double           tangential_ncp_factor;
      const double           reference_modulus;
      const bool             accelerate_release;
      const InitialActiveSet initial_active_set;
      /** The active sets of the step, in order (the owned nodes' codes). */
      std::vector<std::vector<int>> history;
      /** Newton residual that each entry of the history produced; infinite
       * until known. */
      std::vector<double> history_residual;
      /** The sets at which restart_history() was called in this step: the
       * equilibria of held sets. */
      std::vector<std::vector<int>> equilibrium_sets;
      /** Which entries of the history count as seen in the current update
       * (all, unless the iteration progressed since their use). */
      std::vector<bool> history_counts;
      /** The history set aside by begin_linearisation(). */
      std::vector<std::vector<int>> saved_history;
      std::vector<double>           saved_history_residual;
      std::vector<std::vector<int>> saved_equilibrium_sets;
      bool                          cycling;
      /** See revisits_held_set(). */
      bool revisited_held_set;
      bool last_update_extrapolated;
      bool extrapolation_enabled;
    };
  } // namespace Contact
} // namespace Common

#endif
