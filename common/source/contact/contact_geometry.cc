#include <common/contact/contact_geometry.h>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    ReferenceMortarGeometry<dim>::ReferenceMortarGeometry(
      const DoFHandler<dim>   &dof_handler,
      const Mapping<dim>      &mapping,
      const types::boundary_id secondary_id,
      const types::boundary_id primary_id,
      const double             search_distance,
      const bool               axisymmetric)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , secondary_id(secondary_id)
      , primary_id(primary_id)
      , reference_node_dofs()
      , search_distance(search_distance)
      , axisymmetric(axisymmetric)
    {}



    template <int dim>
    ReferenceMortarGeometry<dim>::ReferenceMortarGeometry(
      const DoFHandler<dim>                          &dof_handler,
      const Mapping<dim>                             &mapping,
      const types::boundary_id                        secondary_id,
      std::shared_ptr<const RigidSurface<dim>>        rigid,
      const std::array<types::global_dof_index, dim> &reference_node_dofs,
      const double                                    search_distance,
      const bool                                      axisymmetric)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , secondary_id(secondary_id)
      , primary_id(numbers::invalid_boundary_id)
      , rigid(std::move(rigid))
      , reference_node_dofs(reference_node_dofs)
      , search_distance(search_distance)
      , axisymmetric(axisymmetric)
    {
      for (const auto dof : reference_node_dofs)
        AssertThrow(dof < dof_handler.n_dofs(),
                    ExcMessage("The reference node of a rigid surface "
                               "needs a DoF for every component."));
    }



    // Small strain: the contact geometry is evaluated once, in the
    // reference configuration.
    template <int dim>
    void
    ReferenceMortarGeometry<dim>::reinit(
      const AffineConstraints<double> &constraints,
      const RowSelector               &needed_rows)
    {
      secondary = std::make_unique<ContactSurface<dim>>(dof_handler,
                                                        mapping,
                                                        secondary_id);
      secondary->symmetrize_normals(constraints);
      const std::vector<bool> rows =
        needed_rows ?
          MortarCoupling<dim>::rows_to_integrate(*secondary,
                                                 constraints,
                                                 needed_rows(*secondary)) :
          std::vector<bool>();
      if (rigid)
        mortar.reinit(*secondary,
                      *rigid,
                      reference_node_dofs,
                      search_distance,
                      axisymmetric,
                      rows);
      else
        {
          primary = std::make_unique<ContactSurface<dim>>(dof_handler,
                                                          mapping,
                                                          primary_id);
          // Its edges on symmetry planes (primary_parameter_boxes()).
          primary->symmetrize_normals(constraints);
          search = std::make_unique<ContactSearch<dim>>(*primary, 0.);
          mortar.reinit(*secondary,
                        *primary,
                        *search,
                        search_distance,
                        axisymmetric,
                        rows);
        }
      mortar.condense_hanging_nodes(constraints);
    }



    template <int dim>
    bool
    ReferenceMortarGeometry<dim>::update(const VectorType &)
    {
      return false;
    }



    template <int dim>
    const MortarCoupling<dim> &
    ReferenceMortarGeometry<dim>::coupling() const
    {
      return mortar;
    }



    template <int dim>
    std::string
    ReferenceMortarGeometry<dim>::primary_description() const
    {
      return rigid ? "rigid surface, " + rigid->description() :
                     "meshed surface";
    }

    template class ReferenceMortarGeometry<2>;
    template class ReferenceMortarGeometry<3>;
  } // namespace Contact
} // namespace Common
