/**
 * @file contact_geometry.h
 * The geometry of a contact pair as the contact-Newton problem sees it:
 * the mortar rows (D, M, normals, weighted gaps) over a secondary surface,
 * kept up to date with the displacement. Implemented here in the
 * reference configuration (small strain: the rows are integrated once),
 * over a primary side that is either a meshed surface or an analytic rigid
 * surface carried by a reference node. A current-configuration geometry
 * (finite strain, large sliding) implements the same interface.
 */
#ifndef common_contact_contact_geometry_h
#define common_contact_contact_geometry_h

#include <common/contact/contact_search.h>
#include <common/contact/contact_surface.h>
#include <common/contact/mortar_coupling.h>
#include <common/contact/rigid_surface.h>
#include <common/solvers/load_program.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief Interface of the geometry of one contact pair.
     */
    template <int dim>
    class ContactGeometry
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      virtual ~ContactGeometry() = default;

      /**
       * @brief The rows of the secondary surface a rank needs, by node
       * (all if empty): under MPI, the rows it holds.
       */
      using RowSelector =
        std::function<std::vector<bool>(const ContactSurface<dim> &)>;

      /**
       * @brief Build the surfaces, the pairing and the mortar rows for the
       * current configuration of the mesh, and adapt the rows to the
       * hanging nodes of the secondary surface.
       * @param[in] constraints Hanging-node and Dirichlet constraints,
       * closed (MortarCoupling::condense_hanging_nodes()).
       * @param[in] needed_rows Called with the secondary surface once it is
       * built: only the rows it selects are integrated (with those their
       * hanging-node condensation reads); every row if not given.
       */
      virtual void
      reinit(const dealii::AffineConstraints<double> &constraints,
             const RowSelector &needed_rows = RowSelector()) = 0;

      /**
       * @brief Bring the rows to the displacement @p u (ghosted, mm).
       * @return True if the set of primary nodes coupled to a secondary
       * node may have changed, so that the sparsity pattern must be built
       * again; false if only values changed (never anything in the
       * reference configuration).
       */
      virtual bool
      update(const VectorType &u) = 0;

      /** @brief The mortar rows. */
      virtual const MortarCoupling<dim> &
      coupling() const = 0;

      /** @brief "meshed surface" or "rigid <surface description>", for the
       * console and summary.json. */
      virtual std::string
      primary_description() const = 0;

      /** @brief True if the rows follow the configuration (update() then
       * integrates them again for every displacement); false in the
       * reference configuration. */
      virtual bool
      is_current_configuration() const
      {
        return false;
      }

      /**
       * @brief True if the Newton iteration should linearise the contact
       * conditions with the full derivative of the weighted gaps
       * (weighted_gap_derivative(); ContactNewtonProblem's trial
       * corrections) rather than with the fixed rows' gradient. False by
       * default: in the reference configuration the fixed rows' gradient
       * is exact.
       */
      virtual bool
      linearises_rows() const
      {
        return false;
      }

      /**
       * @brief Why the state of the last update() cannot be accepted, or
       * an empty string if it can. A secondary node inside a rigid tool
       * deeper than the search distance is no longer seen by the pairing:
       * an iterate has carried it through the tool, and an equilibrium
       * without that contact is not a solution. Empty by default.
       * Collective.
       */
      virtual std::string
      inadmissible_state() const
      {
        return std::string();
      }

      /** @brief Move what the load program prescribes (a tool's rotation)
       * to @p state; called at the start of every load step, before
       * update(). Nothing by default. */
      virtual void
      set_load_state(const Solvers::LoadState &state)
      {
        (void)state;
      }

      /** @brief Keep the prescribed motion of the current load step as that
       * of the last accepted one. Nothing by default. */
      virtual void
      commit()
      {}

      /**
       * @brief The relative displacement of every integrated row at the
       * last accepted state @p u_accepted (ghosted), measured with the
       * current rows: the origin from which slip is measured
       * (ContactState::rebase()). By default
       * MortarCoupling::relative_displacement() of each row; a geometry
       * with a turning tool adds the tool's rotation since that state.
       */
      virtual std::vector<dealii::Tensor<1, dim>>
      accepted_relative_displacements(const VectorType &u_accepted) const
      {
        const auto                         &rows = coupling();
        std::vector<dealii::Tensor<1, dim>> result(rows.n_rows());
        for (unsigned int j = 0; j < rows.n_rows(); ++j)
          if (rows.is_integrated(j))
            result[j] = rows.relative_displacement(j, u_accepted);
        return result;
      }

      /** @brief Receives one column of a matrix: the row DoFs, the column
       * DoF and the values. */
      using ColumnSink = std::function<
        void(const std::vector<dealii::types::global_dof_index> &rows,
             const dealii::types::global_dof_index               column,
             const std::vector<double>                          &values)>;

      /**
       * @brief The derivative of the contact forces with respect to the
       * displacement at fixed nodal tractions: the geometric stiffness of
       * contact, which the Newton tangent needs when the rows follow the
       * configuration. The forces are those of
       * add_traction_forces(): \f$D_j\tau_j\f$ on secondary node j and
       * \f$-M_{jk}\tau_j\f$ on its primary nodes, with the traction
       * \f$\tau_j = -\lambda_j n_j + t_j\f$ whose pressure and
       * tangential magnitude are held while n_j turns with the rows.
       * Nothing by default: in the reference configuration the forces do
       * not depend on the displacement.
       * @param[in] tractions \f$\tau_j\f$ of every row (MPa), zero for
       * an open node or a row this rank does not own.
       * @param[in] add Receives every column of the derivative (N/mm).
       */
      virtual void
      contact_force_derivative(
        const std::vector<dealii::Tensor<1, dim>> &tractions,
        const ColumnSink                          &add) const
      {
        (void)tractions;
        (void)add;
      }

      /** @brief Receives one entry of the weighted gaps' derivative: the
       * row, the column DoF and the value (mm^(dim-1)). */
      using GapColumnSink =
        std::function<void(const unsigned int                    row,
                           const dealii::types::global_dof_index column,
                           const double                          value)>;

      /**
       * @brief The full derivative of the weighted gaps of the rows
       * @p selected with respect to the displacement, where the rows follow
       * the configuration: the change of n_j, D and M included, which the
       * fixed rows' gradient (gap_gradient()) leaves out. A penalty force
       * depends on the gap itself, so its tangent needs these terms (of
       * the order of the pointwise gap times the penalty stiffness, and,
       * over a curved rigid tool, of the turn of the surface across a
       * face). Nothing by default: in the reference configuration the
       * fixed rows' gradient is exact.
       * @param[in] selected The rows wanted, by secondary node.
       * @param[in] u The displacement the rows were integrated at (mm).
       * @param[in] add Receives every entry of the derivative.
       * @return False if nothing was computed (the default).
       */
      virtual bool
      weighted_gap_derivative(const std::vector<bool> &selected,
                              const VectorType        &u,
                              const GapColumnSink     &add) const
      {
        (void)selected;
        (void)u;
        (void)add;
        return false;
      }

      /** @brief Groups of DoFs that the geometric stiffness of
       * contact_force_derivative() couples, each to be coupled all with
       * all in the sparsity pattern; none by default. */
      virtual std::vector<std::vector<dealii::types::global_dof_index>>
      coupled_dof_groups() const
      {
        return {};
      }

      /** @brief DoFs that update() reads beyond those of the rows (the
       * nodes of both surfaces in the current configuration), which a
       * rank must store; none by default. */
      virtual std::vector<dealii::types::global_dof_index>
      dofs_read_by_update() const
      {
        return {};
      }
    };



    /**
     * @brief Mortar rows integrated once, in the reference configuration
     * (small strain), between a secondary surface and a meshed primary
     * surface or an analytic rigid one.
     */
    template <int dim>
    class ReferenceMortarGeometry : public ContactGeometry<dim>
    {
    public:
      using typename ContactGeometry<dim>::VectorType;

      /**
       * @brief Secondary and primary surfaces are boundaries of the mesh.
       * @param[in] search_distance Points with |gap| above this are not
       * paired (mm).
       * @param[in] axisymmetric Integrals carry the ring measure 2 pi x.
       * The DoF handler and mapping must outlive this object.
       */
      ReferenceMortarGeometry(const dealii::DoFHandler<dim>   &dof_handler,
                              const dealii::Mapping<dim>      &mapping,
                              const dealii::types::boundary_id secondary_id,
                              const dealii::types::boundary_id primary_id,
                              const double                     search_distance,
                              const bool                       axisymmetric);

      /**
       * @brief The primary side is the analytic rigid surface @p rigid,
       * which moves with the displacement of a reference node whose DoFs
       * are @p reference_node_dofs (one per component; the rigid body's
       * other nodes, if it has any, are constrained to them).
       */
      ReferenceMortarGeometry(const dealii::DoFHandler<dim>   &dof_handler,
                              const dealii::Mapping<dim>      &mapping,
                              const dealii::types::boundary_id secondary_id,
                              std::shared_ptr<const RigidSurface<dim>> rigid,
                              const std::array<dealii::types::global_dof_index,
                                               dim> &reference_node_dofs,
                              const double           search_distance,
                              const bool             axisymmetric);

      using typename ContactGeometry<dim>::RowSelector;

      void
      reinit(const dealii::AffineConstraints<double> &constraints,
             const RowSelector &needed_rows = RowSelector()) override;

      /** @brief Reference configuration: nothing changes; false. */
      bool
      update(const VectorType &u) override;

      const MortarCoupling<dim> &
      coupling() const override;

      std::string
      primary_description() const override;

    private:
      const dealii::DoFHandler<dim>                 &dof_handler;
      const dealii::Mapping<dim>                    &mapping;
      const dealii::types::boundary_id               secondary_id;
      const dealii::types::boundary_id               primary_id;
      const std::shared_ptr<const RigidSurface<dim>> rigid;
      const std::array<dealii::types::global_dof_index, dim>
                   reference_node_dofs;
      const double search_distance;
      const bool   axisymmetric;

      std::unique_ptr<ContactSurface<dim>> secondary;
      std::unique_ptr<ContactSurface<dim>> primary;
      std::unique_ptr<ContactSearch<dim>>  search;
      MortarCoupling<dim>                  mortar;
    };
  } // namespace Contact
} // namespace Common

#endif
