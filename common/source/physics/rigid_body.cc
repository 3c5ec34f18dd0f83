#include <common/physics/rigid_body.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/fe/fe.h>

#include <limits>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    template <int dim>
    std::vector<types::global_dof_index>
    add_rigid_translation_constraints(const DoFHandler<dim>   &dof_handler,
                                      const types::material_id body,
                                      const Point<dim>        &reference_point,
                                      const ComponentMask     &fixed_components,
                                      AffineConstraints<double> &constraints)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_components() == dim && fe.n_dofs_per_vertex() == dim,
                  ExcMessage("Rigid body: the element must have one "
                             "displacement DoF per component at each "
                             "vertex."));
      AssertThrow(fixed_components.size() == 0 ||
                    fixed_components.size() == dim,
                  ExcMessage("Rigid body: the component mask must have one "
                             "entry per displacement component."));

      // The master DoFs: the body's vertex nearest to the reference point.
      std::vector<types::global_dof_index> master(dim,
                                                  numbers::invalid_dof_index);
      double nearest = std::numeric_limits<double>::max();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->material_id() == body)
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(reference_point) < nearest)
              {
                nearest = cell->vertex(v).distance(reference_point);
                for (unsigned int c = 0; c < dim; ++c)
                  master[c] = cell->vertex_dof_index(v, c);
              }
      AssertThrow(master[0] != numbers::invalid_dof_index,
                  ExcMessage("Rigid body: no cell has material id " +
                             std::to_string(body) + "."));

      const auto is_fixed = [&](const unsigned int c) {
        return fixed_components.size() > 0 && fixed_components[c];
      };
      for (unsigned int c = 0; c < dim; ++c)
        if (!is_fixed(c))
          AssertThrow(!constraints.is_constrained(master[c]),
                      ExcMessage("Rigid body: the master DoF of component " +
                                 std::to_string(c) +
                                 " is constrained already; fix the "
                                 "component instead."));

      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->material_id() == body)
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              {
                const types::global_dof_index dof = dof_indices[i];
                const unsigned int c = fe.system_to_component_index(i).first;
                if (dof == master[c] || constraints.is_constrained(dof))
                  continue;
                constraints.add_line(dof);
                if (!is_fixed(c))
                  constraints.add_entry(dof, master[c], 1.);
              }
          }
      for (unsigned int c = 0; c < dim; ++c)
        if (is_fixed(c) && !constraints.is_constrained(master[c]))
          constraints.add_line(master[c]);
      return master;
    }

    template std::vector<types::global_dof_index>
    add_rigid_translation_constraints(const DoFHandler<2> &,
                                      const types::material_id,
                                      const Point<2> &,
                                      const ComponentMask &,
                                      AffineConstraints<double> &);
    template std::vector<types::global_dof_index>
    add_rigid_translation_constraints(const DoFHandler<3> &,
                                      const types::material_id,
                                      const Point<3> &,
                                      const ComponentMask &,
                                      AffineConstraints<double> &);
  } // namespace Physics
} // namespace Common
