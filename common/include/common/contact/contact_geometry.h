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
