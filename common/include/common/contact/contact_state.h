/**
 * @file contact_state.h
 * The state of the secondary nodes of a contact pair: for the current
 * iterate, each node's status (open, stick, slip), pressure, tangential
 * traction, slip direction and turning stiffness; for the last accepted
 * load step, a copy of these, the relative displacement from which the
 * next step's slip increments are measured, and the slip accumulated while
 * in contact. commit() keeps an accepted step, restore() returns to it
 * before a cutback.
 *
 * No mesh: the nodal kinematics come in as plain data (NodeKinematics),
 * gathered from the mortar rows by node_kinematics()
 * (contact_assembly.h), so a finite-strain contact, whose rows change with
 * the configuration, can keep its history here too.
 *
 * With MPI the nodes are distributed (RowPartition): the entries of the
 * rows a rank holds are valid there, those of its owned rows are decided
 * there, and the state of its ghost rows is copied from their owners
 * (update_ghosts()).
 */
#ifndef common_contact_contact_state_h
#define common_contact_contact_state_h

#include <common/contact/free_directions.h>
#include <common/contact/row_partition.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <limits>
#include <string>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /** State of a secondary node in the active set; the values are
     * those of the "contact_status" output field. */
    enum class PointStatus
    {
      /** Not in contact. */
      open = 0,
      /** In contact, no relative tangential motion in the step. */
      stick = 1,
      /** In contact and sliding (every closed node without friction). */
      slip = 2
    };

    /** @brief "open", "stick" or "slip". */
    std::string
    to_string(const PointStatus status);

    /**
     * @brief Kinematics of one secondary node at an iterate, as the
     * mortar rows give them: what the contact laws and the active-set rule
     * are evaluated with.
     */
    template <int dim>
    struct NodeKinematics
    {
      /** True if the node has primary partners and a measure (only such
       * nodes can come into contact). */
      bool paired = false;
      /** Mortar weight D_j (mm^(dim-1), or mm^2 if axisymmetric). */
      double weight = 0.;
      /** Size of the largest face around the node (mm). */
      double mesh_size = 0.;
      /** Gap at the node itself when the rows were integrated (mm). */
      double nodal_gap = std::numeric_limits<double>::infinity();
      /** Position of the node (mm). */
      dealii::Point<dim> position;
      /** The primary body the node is paired with: for rigid tools the
       * first DoF of the reference node of the tool that carries most of
       * its mortar weight; 0 for a meshed primary surface (one body). */
      dealii::types::global_dof_index partner = 0;
      /** Weighted gap \f$\tilde g_j\f$ (D_j times mm); 0 for an unpaired
       * node. The normal gap is weighted_gap / weight (mm). */
      double weighted_gap = 0.;
      /** Mean relative displacement of the primary surface with respect
       * to the node, \f$(\sum_k M_{jk}u_k - D_j u_j)/D_j\f$ (mm). */
      dealii::Tensor<1, dim> relative_displacement;
    };

    /**
     * @brief What an iterate knows about one secondary node.
     */
    template <int dim>
    struct NodeState
    {
      /** Open, stick or slip. */
      PointStatus status = PointStatus::open;
      /** Normal pressure lambda (MPa), >= 0 at convergence. */
      double pressure = 0.;
      /** Tangential traction on the secondary surface (MPa), a vector of
       * the free tangent directions. */
      dealii::Tensor<1, dim> tangential_traction;
      /** Unit direction of the traction of a slipping node; zero
       * otherwise. */
      dealii::Tensor<1, dim> slip_direction;
      /** Turning stiffness of a slipping node (MPa/mm,
       * CoulombLaw::slip_linearisation()); 0 where the node does not slip
       * or cannot turn. */
      double turning_stiffness = 0.;
    };

    /**
     * @brief Per-node contact state of the current iterate and of the last
     * accepted load step, with the friction history.
     */
    template <int dim>
    class ContactState
    {
    public:
      /**
       * @brief Every node open, no history.
       * @param[in] directions Free directions of the nodes, along which
       * slip is measured; must outlive this object.
       */
      explicit ContactState(const FreeDirections<dim> &directions);

      /** @brief Number of nodes. */
      unsigned int
      n_nodes() const;

      /** @brief The free directions of the nodes. */
      const FreeDirections<dim> &
      directions() const;

      /** @brief Distribute the nodes over the MPI ranks as @p rows says
       * (by default every node is owned: serial). */
      void
      distribute(const RowPartition &rows);

      /** @brief The rows this rank owns and holds. */
      const RowPartition &
      rows() const;

      /**
       * @brief Copy status, slip direction and turning stiffness of each
       * ghost row from the rank that owns it (collective; nothing in
       * serial).
       */
      void
      update_ghosts();

      /** @brief State of node @p j in the current iterate. */
      const NodeState<dim> &
      node(const unsigned int j) const;

      /** @brief State of node @p j in the current iterate, for the parts
       * that update it (enforcement, active-set policy). */
      NodeState<dim> &
      node(const unsigned int j);

      /** @brief State of node @p j at the last accepted load step. */
      const NodeState<dim> &
      accepted_node(const unsigned int j) const;

      /** @brief True if node @p j is closed (stick or slip). */
      bool
      is_closed(const unsigned int j) const;

      /** @brief Number of closed nodes among those this rank owns (all
       * in serial). */
      unsigned int
      n_closed() const;

      /** @brief Relative displacement of node @p j at the last accepted
       * load step (mm). */
      const dealii::Tensor<1, dim> &
      accepted_relative_displacement(const unsigned int j) const;

      /** @brief Relative tangential displacement accumulated at node @p j
       * while in contact, over the accepted steps (mm). */
      const dealii::Tensor<1, dim> &
      accumulated_slip(const unsigned int j) const;

      /**
       * @brief Slip increment of node @p j: the part along its free
       * tangents of the change of @p relative_displacement (mm) since the
       * last accepted load step (mm).
       */
      dealii::Tensor<1, dim>
      slip_increment(const unsigned int            j,
                     const dealii::Tensor<1, dim> &relative_displacement) const;

      /**
       * @brief Start afresh: node j gets @p status[j], zero tractions,
       * no slip direction, and the result is also the accepted state, with
       * zero relative displacement and accumulated slip.
       */
      void
      reset(const std::vector<PointStatus> &status);

      /**
       * @brief Keep the current state as that of the last accepted load
       * step, and with it the friction history: the relative displacement
       * of every node, from which the next step's slip increments are
       * measured, and the slip accumulated while in contact. A node that
       * closed during the step is credited with the fraction of its
       * increment after the contact edge passed it; the edge is taken
       * midway between the last closed and the first open node at the
       * start and at the end of the step, and assumed to move uniformly
       * within the step. Updates the rows this rank holds; the distances
       * to the nearest nodes are minima over the ranks (collective).
       * @param[in] nodes Kinematics of every node at the converged
       * displacement of the step (valid at the rows this rank holds;
       * positions and pairing at every row).
       */
      void
      commit(const std::vector<NodeKinematics<dim>> &nodes);

      /** @brief Return to the state of the last accepted load step (after
       * a failed step, before a cutback). */
      void
      restore();

      /**
       * @brief Measure the friction history with new mortar rows (current
       * configuration): node j's relative displacement at the last
       * accepted load step becomes @p accepted_relative[j], the relative
       * displacement of the accepted configuration evaluated with the rows
       * of the current one, so that slip increments are differences of
       * one set of rows and a rigid motion of the pair is no slip
       * (ContactGeometry::accepted_relative_displacement()). Entries of
       * rows this rank does not hold are ignored.
       */
      void
      rebase(const std::vector<dealii::Tensor<1, dim>> &accepted_relative);

    private:
      const FreeDirections<dim>          &free_directions;
      RowPartition                        partition;
      std::vector<NodeState<dim>>         current;
      std::vector<NodeState<dim>>         accepted;
      std::vector<dealii::Tensor<1, dim>> accepted_relative;
      std::vector<dealii::Tensor<1, dim>> slip_accumulated;
    };
  } // namespace Contact
} // namespace Common

#endif
