/**
 * @file current_mortar_geometry.h
 * Mortar rows in the current configuration, for finite strain and large
 * sliding: the contact surfaces follow the displacement, and the pairing,
 * the segmentation, D, M and the nodal normals are evaluated again for
 * every Newton iterate. The primary side is a meshed surface or a set of
 * analytic rigid tools (lines, arcs and their compositions in 2D;
 * cylinders, planes and die profiles extruded along z or revolved about y
 * in 3D), each translated with a reference node's DoFs (free or
 * prescribed) and turned by a rotation the load program prescribes.
 *
 * Linearisation. The weighted gap
 * \f$\tilde g_j = n_j\cdot(\sum_k M_{jk}x_k - D_j x_j)\f$ is exact at
 * every iterate (the rows are integrated where the surfaces are). The
 * tangent holds the increment of the gap with the rows fixed,
 * \f$n_j\cdot(\sum_k M_{jk}\Delta u_k - D_j\Delta u_j)\f$, and the
 * geometric stiffness of contact: the derivative of the contact forces
 * with respect to the nodal positions at fixed nodal forces, which
 * contains the change of n_j, D and M (pairing and segmentation
 * included), by difference quotients (contact_force_derivative()). With
 * it the semismooth Newton method converges quadratically also where the
 * faces slide under pressure (tests/common/current_contact_*).
 *
 * Free edges. Where the edges of the two surfaces coincide (two blocks of
 * one material compressed together), an iterate that moves the primary
 * edge inwards would leave the last secondary face partly uncovered; the
 * free edges of a meshed primary surface are therefore extended by 5 % of
 * a face (MortarCoupling::set_free_edge_extension()).
 *
 * Slip is measured objectively (after A. Popp et al., IJNME 83 (2010)
 * 1428-1465 and M. Gitterle et al., IJNME 84 (2010) 543-571): the
 * increment since the last accepted step is
 * \f$(\sum_k M_{jk}\Delta x_k - D_j\Delta x_j)/D_j\f$ with the current
 * rows and the displacements of material points since that step, of the
 * tool's material points for a rigid tool (translation and rotation). A
 * rigid motion of the pair is no slip. The history lives on the secondary
 * nodes (ContactState) and is committed only with an accepted step.
 */
#ifndef common_contact_current_mortar_geometry_h
#define common_contact_current_mortar_geometry_h

#include <common/contact/contact_geometry.h>
#include <common/contact/contact_parameters.h>
#include <common/contact/contact_state.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief An analytic rigid tool: a rigid surface that translates with a
     * reference node and turns by a prescribed angle about the z axis
     * through a centre that moves with it.
     */
    template <int dim>
    struct RigidTool
    {
      /** Name, for the console and the outputs ("punch", "die"). */
      std::string name;
      /** The surface in the tool's initial position. */
      std::shared_ptr<const RigidSurface<dim>> surface;
      /** DoFs of the reference node, one per component: their displacement
       * is the tool's translation (prescribed by Dirichlet constraints or
       * free under a load). */
      std::array<dealii::types::global_dof_index, dim> reference_node_dofs;
      /** Centre of rotation in the initial position (mm). */
      dealii::Point<dim> centre;
      /** The tool's rotation angle about the z axis through the centre at a
       * load state (rad, counterclockwise seen from +z); none if empty. */
      std::function<double(const Solvers::LoadState &)> rotation;
    };



    /**
     * @brief The contact force on a rigid tool and its moment.
     */
    template <int dim>
    struct ToolLoad
    {
      /** Force of the secondary body on the tool (N; N per mm of thickness
       * in plane strain, the full ring if axisymmetric). */
      dealii::Tensor<1, dim> force;
      /** Moment of that force about the tool's centre where it is now
       * (N mm; per mm of thickness in plane strain); in 2D only the z
       * component is set. */
      dealii::Tensor<1, 3> moment;
    };

    /**
     * @brief Mortar rows integrated again for every displacement, between
     * a secondary surface and a meshed primary surface or a set of rigid
     * tools.
     */
    template <int dim>
    class CurrentMortarGeometry : public ContactGeometry<dim>
    {
    public:
      using typename ContactGeometry<dim>::VectorType;
      using typename ContactGeometry<dim>::RowSelector;

      /**
       * @brief Secondary and primary surfaces are boundaries of the mesh.
       * @param[in] search_distance Points with |gap| above this are not
       * paired (mm).
       * @param[in] axisymmetric Integrals carry the ring measure 2 pi x.
       * The DoF handler and mapping must outlive this object.
       */
      CurrentMortarGeometry(const dealii::DoFHandler<dim>   &dof_handler,
                            const dealii::Mapping<dim>      &mapping,
                            const dealii::types::boundary_id secondary_id,
                            const dealii::types::boundary_id primary_id,
                            const double                     search_distance,
                            const bool                       axisymmetric);

      /**
       * @brief The primary side is the set of rigid @p tools (at least
       * one). Each integration point pairs with the nearest tool its
       * normal ray meets.
       */
      CurrentMortarGeometry(const dealii::DoFHandler<dim>     &dof_handler,
                            const dealii::Mapping<dim>        &mapping,
                            const dealii::types::boundary_id   secondary_id,
                            const std::vector<RigidTool<dim>> &tools,
                            const double                       search_distance,
                            const bool                         axisymmetric);

      void
      reinit(const dealii::AffineConstraints<double> &constraints,
             const RowSelector &needed_rows = RowSelector()) override;

      /**
       * @brief Move the surfaces (and tools) to the displacement @p u and
       * integrate the rows there.
       * @return True if a row now couples to a primary node that the
       * sparsity pattern built after the last true return (or reinit())
       * does not hold.
       */
      bool
      update(const VectorType &u) override;

      const MortarCoupling<dim> &
      coupling() const override;

      std::string
      primary_description() const override;

      /** @brief True. */
      bool
      is_current_configuration() const override;

      /**
       * @brief True against a meshed primary surface: there the fixed
       * rows' gradient leaves out how the mortar weights and the normal
       * turn with both bodies, and the iteration converges linearly, the
       * more slowly the softer the primary body (a roller with 1e-2 of
       * the strip's modulus: a factor of about 0.075 per iteration).
       * False against rigid tools, where the full derivative was measured
       * to cost iterations and time (sheet forming's coarse case: 991
       * Newton iterations instead of 955, and 53 % more time).
       */
      bool
      linearises_rows() const override;

      /** @brief A secondary node whose signed distance to a rigid tool
       * (RigidSurface::closest_point()) is below minus the search
       * distance, named with its position, the tool and the depth. */
      std::string
      inadmissible_state() const override;

      /** @brief The tools' rotations at @p state. */
      void
      set_load_state(const Solvers::LoadState &state) override;

      /** @brief Keep the tools' rotations as the accepted ones. */
      void
      commit() override;

      /** @brief MortarCoupling::relative_displacement() at @p u_accepted,
       * less, for a row paired with a tool, the displacement of the tool's
       * partner points by the tool's rotation since the accepted state.
       * Against a meshed primary surface the accepted relative position of
       * the pair is turned with the node's normal since the accepted state,
       * so that a rigid rotation of both bodies is no slip. */
      std::vector<dealii::Tensor<1, dim>>
      accepted_relative_displacements(
        const VectorType &u_accepted) const override;

      using typename ContactGeometry<dim>::ColumnSink;

      /**
       * @brief The geometric stiffness of contact by difference quotients:
       * each node of a face around a loaded row, each primary node of such
       * a row and each tool's reference node is moved by 1e-7 of the mesh
       * size along each axis, the rows that depend on it are integrated
       * again, and the change of their forces is a column. The columns
       * are restricted to the DoFs the rows couple (those of the sparsity
       * pattern); the error of the quotients (about 1e-7) changes the
       * tangent only, never the converged state.
       */
      void
      contact_force_derivative(
        const std::vector<dealii::Tensor<1, dim>> &tractions,
        const ColumnSink                          &add) const override;

      using typename ContactGeometry<dim>::GapColumnSink;

      /**
       * @brief The weighted gaps' derivative by the difference quotients of
       * contact_force_derivative(): the change of each selected row's
       * weighted gap, the moved node's own displacement included, when a
       * node (or tool) it depends on moves.
       * @return True.
       */
      bool
      weighted_gap_derivative(const std::vector<bool> &selected,
                              const VectorType        &u,
                              const GapColumnSink     &add) const override;

      /** @brief For each paired row: the DoFs of the secondary nodes within
       * two faces of it and of their primary nodes. */
      std::vector<std::vector<dealii::types::global_dof_index>>
      coupled_dof_groups() const override;

      /** @brief The DoFs of the nodes of both surfaces and of the tools'
       * reference nodes. */
      std::vector<dealii::types::global_dof_index>
      dofs_read_by_update() const override;

      /** @brief How the rows against the rigid tools measure the gap
       * (ContactParameters::rigid_tool_gap); mortar unless set. Call
       * before reinit(). */
      void
      set_rigid_tool_gap(const RigidToolGap gap);

      /** @brief Number of rigid tools (0 for a meshed primary surface). */
      unsigned int
      n_tools() const;

      /** @brief Tool @p i. */
      const RigidTool<dim> &
      tool(const unsigned int i) const;

      /** @brief The rigid tool that primary node @p k of the coupling
       * belongs to. */
      unsigned int
      tool_of_primary_node(const unsigned int k) const;

      /** @brief The surface of tool @p i where it is now. */
      const RigidSurface<dim> &
      placed_surface(const unsigned int i) const;

      /** @brief Rotation angle of tool @p i now (rad). */
      double
      tool_angle(const unsigned int i) const;

      /**
       * @brief The contact force and moment on each tool at the current
       * rows and tractions: tool i receives \f$-\sum_j M_{jk}\tau_j\f$
       * from each row j at its primary node k on the tool, applied at that
       * node's point \f$\bar X_{jk}\f$ (the dual-weighted mean of the
       * row's partner points on the tool), with the traction
       * \f$\tau_j = -p_j n_j + t_j\f$ of the secondary node. The forces
       * are those the primary side receives in the residual, so they
       * balance the secondary body's reactions exactly. Sums over the rows
       * of the rank's own secondary nodes (@p locally_owned), then over
       * @p mpi_communicator; the result is the same on every rank. Empty
       * for a meshed primary surface.
       */
      std::vector<ToolLoad<dim>>
      tool_loads(const ContactState<dim> &state,
                 const dealii::IndexSet  &locally_owned,
                 const MPI_Comm           mpi_communicator) const;

      /** @brief Number of times update() found a changed coupling
       * pattern. */
      unsigned int
      n_pattern_changes() const;

    private:
      const dealii::DoFHandler<dim>    &dof_handler;
      const dealii::Mapping<dim>       &mapping;
      const dealii::types::boundary_id  secondary_id;
      const dealii::types::boundary_id  primary_id;
      const std::vector<RigidTool<dim>> tools;
      const double                      search_distance;
      /** How the rows against the rigid tools measure the gap. */
      RigidToolGap rigid_tool_gap = RigidToolGap::mortar;
      const bool   axisymmetric;
      const dealii::AffineConstraints<double>        *constraints = nullptr;
      std::vector<bool>                               integrated_rows;
      std::vector<std::unique_ptr<RigidSurface<dim>>> placed;
      std::vector<double>                             angle;
      std::vector<double>                             accepted_angle;
      /** The nodal normals of the rows at the last accepted state. */
      std::vector<dealii::Tensor<1, dim>> accepted_normals;
      /** The tools as last placed by integrate(). */
      std::vector<RigidPartner<dim>> partners;
      /** The faces of the secondary surface around each of its nodes. */
      std::vector<std::vector<unsigned int>> node_faces;

      std::unique_ptr<ContactSurface<dim>> secondary;
      std::unique_ptr<ContactSurface<dim>> primary;
      std::unique_ptr<ContactSearch<dim>>  search;
      MortarCoupling<dim>                  mortar;
      /** First DoF of every primary node each row coupled to when the
       * pattern was last built, sorted. */
      std::vector<std::vector<dealii::types::global_dof_index>> pattern;
      unsigned int                                              n_changes = 0;

      /** Integrate the rows where the surfaces and tools are now; the
       * tools are translated by the displacement @p u of their reference
       * nodes (zero if null). */
      void
      integrate(const VectorType *u);

      /** Integrate @p rows (by secondary node) into @p target between
       * @p secondary_surface and the primary surface @p primary_surface
       * (with @p primary_search) or the tools placed as @p tools. */
      void
      integrate_rows(const ContactSurface<dim>            &secondary_surface,
                     const ContactSurface<dim>            *primary_surface,
                     const ContactSearch<dim>             *primary_search,
                     const std::vector<RigidPartner<dim>> &tools,
                     const std::vector<bool>              &rows,
                     MortarCoupling<dim>                  &target) const;

      /** One moved node of a difference quotient: a secondary node, a
       * primary node or a tool's reference node, its index, the axis and
       * the length of the move (mm). */
      struct Perturbation
      {
        enum class Kind
        {
          secondary,
          primary,
          tool
        } kind;
        unsigned int                    index;
        unsigned int                    component;
        double                          eps;
        dealii::types::global_dof_index dof;
      };

      /** Move each node that any of @p rows depends on (the nodes within
       * two faces, their primary nodes, the tools) by 1e-7 of the mesh
       * size along each axis in turn, integrate the rows of @p rows that
       * depend on it again, and pass the result to @p visit with those
       * rows and the move. */
      void
      for_each_perturbation(
        const std::vector<unsigned int>                 &rows,
        const std::function<void(const MortarCoupling<dim> &,
                                 const std::vector<unsigned int> &,
                                 const Perturbation &)> &visit) const;

      /** The secondary nodes within two faces of node @p j (itself
       * included), sorted. */
      std::vector<unsigned int>
      neighbourhood(const unsigned int j) const;

      /** The coupling pattern of the current rows. */
      std::vector<std::vector<dealii::types::global_dof_index>>
      current_pattern() const;
    };

    /**
     * @brief The mortar geometry of a pair of meshed surfaces that
     * @p contact asks for (ContactParameters::in_current_configuration()
     * with @p finite_strain): a CurrentMortarGeometry or a
     * ReferenceMortarGeometry.
     */
    template <int dim>
    std::unique_ptr<ContactGeometry<dim>>
    create_mortar_geometry(const dealii::DoFHandler<dim> &dof_handler,
                           const dealii::Mapping<dim>    &mapping,
                           const ContactParameters       &contact,
                           const bool                     finite_strain,
                           const bool                     axisymmetric);

    /**
     * @brief The mortar geometry of a meshed secondary surface against the
     * analytic rigid surface @p rigid, translated with the reference node
     * whose DoFs are @p reference_node_dofs: a CurrentMortarGeometry with
     * one RigidTool named @p name, or a ReferenceMortarGeometry.
     */
    template <int dim>
    std::unique_ptr<ContactGeometry<dim>>
    create_mortar_geometry(
      const dealii::DoFHandler<dim>                  &dof_handler,
      const dealii::Mapping<dim>                     &mapping,
      const ContactParameters                        &contact,
      const bool                                      finite_strain,
      const std::string                              &name,
      const std::shared_ptr<const RigidSurface<dim>> &rigid,
      const std::array<dealii::types::global_dof_index, dim>
                &reference_node_dofs,
      const bool axisymmetric);
  } // namespace Contact
} // namespace Common

#endif
