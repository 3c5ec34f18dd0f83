#include <common/physics/rigid_body.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <limits>
#include <map>
#include <string>

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



    template <int dim>
    std::vector<std::vector<double>>
    rigid_body_modes(const Mapping<dim>    &mapping,
                     const DoFHandler<dim> &dof_handler,
                     const bool             include_rotations)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_components() == dim && fe.has_support_points(),
                  ExcMessage("Rigid-body modes: the element must be a "
                             "Lagrange element with one component per "
                             "displacement direction."));

      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
      const BoundingBox<dim> box =
        GridTools::compute_bounding_box(dof_handler.get_triangulation());
      const Point<dim> centre = box.center();

      const IndexSet           &owned = dof_handler.locally_owned_dofs();
      std::vector<unsigned int> component(owned.n_elements(), 0);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              if (owned.is_element(dof_indices[i]))
                component[owned.index_within_set(dof_indices[i])] =
                  fe.system_to_component_index(i).first;
          }

      const unsigned int n_rotations =
        include_rotations ? (dim == 2 ? 1 : 3) : 0;
      std::vector<std::vector<double>> modes(
        dim + n_rotations,
        std::vector<double>(owned.n_elements(), 0.));
      for (unsigned int k = 0; k < owned.n_elements(); ++k)
        {
          const types::global_dof_index dof = owned.nth_index_in_set(k);
          const unsigned int            c   = component[k];
          modes[c][k]                       = 1.;
          if (n_rotations == 0)
            continue;
          const auto point = points.find(dof);
          AssertThrow(point != points.end(),
                      ExcMessage("Rigid-body modes: a locally owned DoF has "
                                 "no support point on this process."));
          const Tensor<1, dim> x = point->second - centre;
          // Rotation about axis a: u = e_a x (x - centre); in 2D about the
          // out-of-plane axis.
          for (unsigned int r = 0; r < n_rotations; ++r)
            {
              const unsigned int a = (dim == 2 ? 2 : r);
              // (e_a x x)_c = epsilon_{c a j} x_j, with the Levi-Civita
              // symbol epsilon_{ijk} = (i - j)(j - k)(k - i)/2.
              double value = 0.;
              for (unsigned int j = 0; j < dim; ++j)
                {
                  const int ci = c, ai = a, ji = j;
                  value += (ci - ai) * (ai - ji) * (ji - ci) / 2 * x[j];
                }
              modes[dim + r][k] = value;
            }
        }
      return modes;
    }



    template <int dim>
    void
    PrescribedTranslation<dim>::prescribe(
      const Tensor<1, dim>                      &translation,
      std::map<types::global_dof_index, double> &values) const
    {
      for (unsigned int c = 0; c < dim; ++c)
        for (const auto dof : dofs[c])
          values[dof] = translation[c];
    }



    template <int dim>
    PrescribedTranslation<dim>
    add_prescribed_translation_constraints(
      const DoFHandler<dim>     &dof_handler,
      const types::material_id   body,
      AffineConstraints<double> &constraints)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_components() == dim,
                  ExcMessage("Prescribed body: the element must have one "
                             "component per displacement component."));
      PrescribedTranslation<dim> result;
      result.reference_node_dofs.fill(numbers::invalid_dof_index);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->material_id() == body)
          {
            if (result.reference_node_dofs[0] == numbers::invalid_dof_index)
              for (unsigned int c = 0; c < dim; ++c)
                result.reference_node_dofs[c] = cell->vertex_dof_index(0, c);
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              {
                const auto dof = dof_indices[i];
                result.dofs[fe.system_to_component_index(i).first].push_back(
                  dof);
                if (constraints.can_store_line(dof) &&
                    !constraints.is_constrained(dof))
                  constraints.add_line(dof);
              }
          }
      AssertThrow(result.reference_node_dofs[0] != numbers::invalid_dof_index,
                  ExcMessage("Prescribed body: no cell has material id " +
                             std::to_string(body) + "."));
      for (auto &component : result.dofs)
        {
          std::sort(component.begin(), component.end());
          component.erase(std::unique(component.begin(), component.end()),
                          component.end());
        }
      return result;
    }



    template struct PrescribedTranslation<2>;
    template struct PrescribedTranslation<3>;
    template PrescribedTranslation<2>
    add_prescribed_translation_constraints(const DoFHandler<2> &,
                                           const types::material_id,
                                           AffineConstraints<double> &);
    template PrescribedTranslation<3>
    add_prescribed_translation_constraints(const DoFHandler<3> &,
                                           const types::material_id,
                                           AffineConstraints<double> &);
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
    template std::vector<std::vector<double>>
    rigid_body_modes(const Mapping<2> &, const DoFHandler<2> &, const bool);
    template std::vector<std::vector<double>>
    rigid_body_modes(const Mapping<3> &, const DoFHandler<3> &, const bool);
  } // namespace Physics
} // namespace Common
