#include <common/physics/boundary_conditions.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/numerics/vector_tools.h>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    template <int dim>
    void
    add_zero_component_constraints(
      const Mapping<dim>    &mapping,
      const DoFHandler<dim> &dof_handler,
      const std::vector<
        std::pair<unsigned int, std::vector<types::boundary_id>>>
                                &zero_components,
      AffineConstraints<double> &constraints)
    {
      for (const auto &[component, ids] : zero_components)
        for (const auto id : ids)
          VectorTools::interpolate_boundary_values(
            mapping,
            dof_handler,
            id,
            Functions::ZeroFunction<dim>(dim),
            constraints,
            dof_handler.get_fe().component_mask(
              FEValuesExtractors::Scalar(component)));
    }



    template <int dim>
    void
    make_homogeneous_constraints(
      const Mapping<dim>                    &mapping,
      const DoFHandler<dim>                 &dof_handler,
      const std::vector<types::boundary_id> &clamped,
      const std::vector<
        std::pair<unsigned int, std::vector<types::boundary_id>>>
                                &zero_components,
      AffineConstraints<double> &constraints)
    {
      constraints.clear();
      constraints.reinit(complete_index_set(dof_handler.n_dofs()));
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      for (const auto id : clamped)
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 id,
                                                 Functions::ZeroFunction<dim>(
                                                   dim),
                                                 constraints);
      add_zero_component_constraints(mapping,
                                     dof_handler,
                                     zero_components,
                                     constraints);
    }

    template void
    add_zero_component_constraints(
      const Mapping<2> &,
      const DoFHandler<2> &,
      const std::vector<
        std::pair<unsigned int, std::vector<types::boundary_id>>> &,
      AffineConstraints<double> &);
    template void
    add_zero_component_constraints(
      const Mapping<3> &,
      const DoFHandler<3> &,
      const std::vector<
        std::pair<unsigned int, std::vector<types::boundary_id>>> &,
      AffineConstraints<double> &);
    template void
    make_homogeneous_constraints(
      const Mapping<2> &,
      const DoFHandler<2> &,
      const std::vector<types::boundary_id> &,
      const std::vector<
        std::pair<unsigned int, std::vector<types::boundary_id>>> &,
      AffineConstraints<double> &);
    template void
    make_homogeneous_constraints(
      const Mapping<3> &,
      const DoFHandler<3> &,
      const std::vector<types::boundary_id> &,
      const std::vector<
        std::pair<unsigned int, std::vector<types::boundary_id>>> &,
      AffineConstraints<double> &);
  } // namespace Physics
} // namespace Common
