/*
 * Displacement profiles along a boundary, sampled at support points, and
 * the displacement of a material point.
 */
#include <common/physics/boundary_displacement.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    template <int dim>
    std::vector<BoundaryDisplacementPoint<dim>>
    boundary_displacements(const Mapping<dim>                  &mapping,
                           const DoFHandler<dim>               &dof_handler,
                           const TrilinosWrappers::MPI::Vector &u,
                           const types::boundary_id             boundary_id,
                           const unsigned int                   sort_coordinate)
    {
      AssertIndexRange(sort_coordinate, dim);
      const auto &fe = dof_handler.get_fe();
      Assert(fe.has_face_support_points(),
             ExcMessage("The element has no face support points."));
      const Quadrature<dim - 1> points(fe.get_unit_face_support_points());
      FEFaceValues<dim>         fe_face_values(mapping,
                                       fe,
                                       points,
                                       update_values |
                                         update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<1, dim>>      values(points.size());

      std::vector<BoundaryDisplacementPoint<dim>> local;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == boundary_id)
              {
                fe_face_values.reinit(cell, face);
                fe_face_values[displacement].get_function_values(u, values);
                for (unsigned int q = 0; q < points.size(); ++q)
                  local.push_back(
                    {fe_face_values.quadrature_point(q), values[q]});
              }

      std::vector<BoundaryDisplacementPoint<dim>> all;
      for (const auto &part :
           Utilities::MPI::all_gather(dof_handler.get_communicator(), local))
        all.insert(all.end(), part.begin(), part.end());

      // Lexicographic order led by the sort coordinate; points shared by
      // neighbouring faces then sit next to each other.
      const auto before = [sort_coordinate](const auto &x, const auto &y) {
        for (unsigned int k = 0; k < dim; ++k)
          {
            const unsigned int d = (sort_coordinate + k) % dim;
            if (x.position[d] != y.position[d])
              return x.position[d] < y.position[d];
          }
        return false;
      };
      std::sort(all.begin(), all.end(), before);
      double extent = 0.;
      for (const auto &p : all)
        extent = std::max(extent, p.position.norm());
      const double tolerance = 1e-10 * std::max(extent, 1.);
      // A point is a repeat if an earlier one lies within the tolerance;
      // those all sit in the window of nearly equal sort coordinates.
      std::vector<BoundaryDisplacementPoint<dim>> unique;
      for (const auto &p : all)
        {
          bool repeat = false;
          for (auto q = unique.rbegin();
               q != unique.rend() && q->position[sort_coordinate] >
                                       p.position[sort_coordinate] - tolerance;
               ++q)
            if (q->position.distance(p.position) < tolerance)
              {
                repeat = true;
                break;
              }
          if (!repeat)
            unique.push_back(p);
        }
      return unique;
    }



    template <int dim>
    Tensor<1, dim>
    displacement_at(const Mapping<dim>                  &mapping,
                    const DoFHandler<dim>               &dof_handler,
                    const TrilinosWrappers::MPI::Vector &u,
                    const Point<dim>                    &point,
                    const std::string                   &what)
    {
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
        found;
      try
        {
          found = GridTools::find_active_cell_around_point(mapping,
                                                           dof_handler,
                                                           point);
        }
      catch (...)
        {
          AssertThrow(false, ExcMessage("No cell holds " + what + "."));
        }
      AssertThrow(found.first.state() == IteratorState::valid,
                  ExcMessage("No cell holds " + what + "."));
      Tensor<1, dim> value;
      if (found.first->is_locally_owned())
        {
          const Quadrature<dim> at_point(
            GeometryInfo<dim>::project_to_unit_cell(found.second));
          FEValues<dim> fe_values(mapping,
                                  dof_handler.get_fe(),
                                  at_point,
                                  update_values);
          fe_values.reinit(found.first);
          std::vector<Tensor<1, dim>> values(1);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(u,
                                                                       values);
          value = values[0];
        }
      return Utilities::MPI::sum(value, dof_handler.get_communicator());
    }



    template std::vector<BoundaryDisplacementPoint<2>>
    boundary_displacements(const Mapping<2> &,
                           const DoFHandler<2> &,
                           const TrilinosWrappers::MPI::Vector &,
                           const types::boundary_id,
                           const unsigned int);
    template std::vector<BoundaryDisplacementPoint<3>>
    boundary_displacements(const Mapping<3> &,
                           const DoFHandler<3> &,
                           const TrilinosWrappers::MPI::Vector &,
                           const types::boundary_id,
                           const unsigned int);
    template Tensor<1, 2>
    displacement_at(const Mapping<2> &,
                    const DoFHandler<2> &,
                    const TrilinosWrappers::MPI::Vector &,
                    const Point<2> &,
                    const std::string &);
    template Tensor<1, 3>
    displacement_at(const Mapping<3> &,
                    const DoFHandler<3> &,
                    const TrilinosWrappers::MPI::Vector &,
                    const Point<3> &,
                    const std::string &);
  } // namespace Physics
} // namespace Common
