#include <common/geometry/two_body_meshes.h>

#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <random>
#include <string>

namespace Common
{
  namespace Geometry
  {
    using namespace dealii;

    template <int dim>
    void
    join_bodies(const std::vector<const Triangulation<dim> *> &parts,
                Triangulation<dim>                            &result)
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      SubCellData                subcell_data;
      for (const Triangulation<dim> *part : parts)
        {
          AssertThrow(part->n_levels() == 1,
                      ExcMessage("join_bodies needs coarse meshes."));
          const unsigned int offset = vertices.size();
          vertices.insert(vertices.end(),
                          part->get_vertices().begin(),
                          part->get_vertices().end());
          for (const auto &cell : part->active_cell_iterators())
            {
              CellData<dim> data;
              for (const unsigned int v : cell->vertex_indices())
                data.vertices[v] = cell->vertex_index(v) + offset;
              data.material_id = cell->material_id();
              data.manifold_id = cell->manifold_id();
              cells.push_back(data);
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->at_boundary())
                  {
                    CellData<dim - 1> face_data;
                    for (const unsigned int v : cell->face(f)->vertex_indices())
                      face_data.vertices[v] =
                        cell->face(f)->vertex_index(v) + offset;
                    face_data.boundary_id = cell->face(f)->boundary_id();
                    face_data.manifold_id = cell->face(f)->manifold_id();
                    if constexpr (dim == 2)
                      subcell_data.boundary_lines.push_back(face_data);
                    else if constexpr (dim == 3)
                      subcell_data.boundary_quads.push_back(face_data);
                  }
            }
        }
      result.create_triangulation(vertices, cells, subcell_data);

      // Coarse cells keep the order and the vertex order of the parts, so
      // that their faces and lines correspond one to one.
      auto target = result.begin_active();
      std::map<types::manifold_id, const Triangulation<dim> *> owner;
      for (const Triangulation<dim> *part : parts)
        {
          for (const auto &cell : part->active_cell_iterators())
            {
              target->set_manifold_id(cell->manifold_id());
              for (const unsigned int f : cell->face_indices())
                target->face(f)->set_manifold_id(cell->face(f)->manifold_id());
              if constexpr (dim == 3)
                for (const unsigned int l : cell->line_indices())
                  target->line(l)->set_manifold_id(
                    cell->line(l)->manifold_id());
              ++target;
            }
          for (const types::manifold_id id : part->get_manifold_ids())
            if (id != numbers::flat_manifold_id &&
                dynamic_cast<const FlatManifold<dim> *>(
                  &part->get_manifold(id)) == nullptr)
              {
                AssertThrow(
                  dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(
                    &part->get_manifold(id)) == nullptr,
                  ExcMessage("join_bodies: attach transfinite "
                             "interpolation manifolds to the joined mesh."));
                AssertThrow(owner.emplace(id, part).second,
                            ExcMessage("join_bodies: two parts attach "
                                       "manifolds to id " +
                                       std::to_string(id) + "."));
                result.set_manifold(id, part->get_manifold(id));
              }
        }
    }



    namespace
    {
      /** Refuse a mesh of @p n_cells cells beyond max_active_cells. */
      template <int dim>
      void
      check_mesh_size(const std::uint64_t n_cells, const std::string &entries)
      {
        AssertThrow(n_cells <= max_active_cells<dim>,
                    ExcMessage(entries + " would make a mesh of more than " +
                               std::to_string(max_active_cells<dim>) +
                               " cells (" + std::to_string(n_cells) +
                               " or more): use fewer refinements."));
      }



      /** Refuse @p n_times global refinements of @p tria that would make
       * more than max_active_cells cells. */
      template <int dim>
      void
      check_global_refinements(const Triangulation<dim> &tria,
                               const unsigned int        n_times,
                               const std::string        &entries)
      {
        // Each refinement multiplies the cells by 2^dim: the count is
        // checked one refinement at a time, before it overflows.
        std::uint64_t n_cells = tria.n_active_cells();
        for (unsigned int i = 0; i < n_times; ++i)
          {
            n_cells *= (1u << dim);
            check_mesh_size<dim>(n_cells, entries);
          }
      }



      /**
       * Cells that n_passes - pass passes make of the part [lo, hi] of a
       * cell with the straight-sided vertices @p v (the reference box
       * [0, 1]^dim): the passes before @p n_uniform refine every part (global
       * refinements), the others only the parts the grading flags. A part
       * left unrefined counts 1, a refined one the sum over its 2^dim
       * children. Ignores the refinements that keep one hanging node per
       * face, so the count is a lower bound. Stops when it exceeds
       * @p budget.
       */
      template <int dim>
      std::uint64_t
      predicted_cells(
        const std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> &v,
        const Point<dim>                                                   &lo,
        const Point<dim>                                                   &hi,
        const unsigned int                               pass,
        const unsigned int                               n_uniform,
        const unsigned int                               n_passes,
        const double                                     factor,
        const std::function<double(const Point<dim> &)> &distance,
        const std::uint64_t                              budget)
      {
        if (pass == n_passes)
          return 1;
        const Point<dim> middle = 0.5 * (lo + hi);
        if (pass >= n_uniform)
          {
            const auto map = [&v](const Point<dim> &xi) {
              Point<dim> x;
              for (unsigned int i = 0; i < v.size(); ++i)
                x += GeometryInfo<dim>::d_linear_shape_function(xi, i) * v[i];
              return x;
            };
            // The diameter as deal.II's: the longest diagonal.
            double diameter = 0.;
            for (unsigned int c = 0; c < (1u << (dim - 1)); ++c)
              {
                Point<dim> corner, opposite;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const bool upper = d < dim - 1 && (c >> d) & 1u;
                    corner[d]        = upper ? hi[d] : lo[d];
                    opposite[d]      = upper ? lo[d] : hi[d];
                  }
                diameter =
                  std::max(diameter, map(corner).distance(map(opposite)));
              }
            if (!(distance(map(middle)) < factor * diameter))
              return 1;
          }
        std::uint64_t n = 0;
        for (unsigned int child = 0; child < (1u << dim) && n <= budget;
             ++child)
          {
            Point<dim> child_lo, child_hi;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const bool upper = (child >> d) & 1u;
                child_lo[d]      = upper ? middle[d] : lo[d];
                child_hi[d]      = upper ? hi[d] : middle[d];
              }
            n += predicted_cells(v,
                                 child_lo,
                                 child_hi,
                                 pass + 1,
                                 n_uniform,
                                 n_passes,
                                 factor,
                                 distance,
                                 budget - n);
          }
        return n;
      }



      /**
       * Cells that @p n_uniform global refinements and then @p n_passes
       * graded passes would make of @p tria (refine_toward()), predicted on
       * its straight-sided cells: a lower bound, exceeding max_active_cells
       * by at most one cell's share when it stops there.
       */
      template <int dim>
      std::uint64_t
      predicted_mesh_size(
        const Triangulation<dim>                        &tria,
        const std::function<double(const Point<dim> &)> &distance,
        const unsigned int                               n_uniform,
        const unsigned int                               n_passes,
        const double                                     factor,
        const types::material_id                         material_id)
      {
        std::uint64_t predicted = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            // A cell of another body takes the global refinements only.
            const bool graded = material_id == numbers::invalid_material_id ||
                                cell->material_id() == material_id;
            std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> v;
            for (const unsigned int i : cell->vertex_indices())
              v[i] = cell->vertex(i);
            Point<dim> lo, hi;
            for (unsigned int d = 0; d < dim; ++d)
              hi[d] = 1.;
            predicted +=
              predicted_cells<dim>(v,
                                   lo,
                                   hi,
                                   0,
                                   n_uniform,
                                   n_uniform + (graded ? n_passes : 0),
                                   factor,
                                   distance,
                                   max_active_cells<dim> - predicted);
            if (predicted > max_active_cells<dim>)
              break;
          }
        return predicted;
      }
    } // namespace



    void
    check_cell_count(const std::uint64_t n_cells,
                     const std::uint64_t max_cells,
                     const std::string  &entries)
    {
      AssertThrow(n_cells <= max_cells,
                  ExcMessage("Mesh: " + entries + " would make a mesh of " +
                             std::to_string(n_cells) + " cells, more than " +
                             std::to_string(max_cells) + "."));
    }



    template <int dim>
    void
    refine_toward(Triangulation<dim>                              &tria,
                  const std::function<double(const Point<dim> &)> &distance,
                  const unsigned int                               n_passes,
                  const double                                     factor,
                  const std::string                               &entries,
                  const types::material_id                         material_id)
    {
      // All passes at once first, on straight-sided cells without the
      // smoothing refinements (a lower bound): a pass that refines nearly
      // every cell is refused before it runs, not after it made a mesh
      // just under the limit.
      check_mesh_size<dim>(
        predicted_mesh_size(tria, distance, 0, n_passes, factor, material_id),
        entries);

      for (unsigned int pass = 0; pass < n_passes; ++pass)
        {
          std::uint64_t n_flagged = 0;
          for (const auto &cell : tria.active_cell_iterators())
            if ((material_id == numbers::invalid_material_id ||
                 cell->material_id() == material_id) &&
                distance(cell->center()) < factor * cell->diameter())
              {
                cell->set_refine_flag();
                ++n_flagged;
              }
          // Each flagged cell becomes 2^dim; the neighbours refined to keep
          // one hanging node per face come on top.
          check_mesh_size<dim>(tria.n_active_cells() +
                                 n_flagged * ((1u << dim) - 1),
                               entries);
          tria.execute_coarsening_and_refinement();
        }
    }



    template <int dim>
    void
    refine_planned(Triangulation<dim>                       &tria,
                   const unsigned int                        n_global,
                   const std::string                        &global_entries,
                   const std::vector<GradedRefinement<dim>> &graded)
    {
      // Each set refines the mesh the sets before it left, which refines
      // the globally refined coarse mesh: what the set alone would make
      // of that mesh is a lower bound of the final mesh, predicted before
      // the global refinements run.
      check_global_refinements(tria, n_global, global_entries);
      for (const GradedRefinement<dim> &set : graded)
        check_mesh_size<dim>(predicted_mesh_size(tria,
                                                 set.distance,
                                                 n_global,
                                                 set.n_passes,
                                                 set.factor,
                                                 set.material_id),
                             set.entries);
      tria.refine_global(n_global);
      for (const GradedRefinement<dim> &set : graded)
        refine_toward(tria,
                      set.distance,
                      set.n_passes,
                      set.factor,
                      set.entries,
                      set.material_id);
    }



    template <int dim>
    void
    perturb_interior_vertices(Triangulation<dim> &tria,
                              const double        fraction,
                              const std::string  &entry)
    {
      AssertThrow(fraction >= 0. && fraction <= 0.3,
                  ExcMessage(entry + " must lie in [0, 0.3]."));
      if (fraction == 0.)
        return;

      // Vertices that stay: those on the boundary. Hanging vertices, with
      // the level of their parent edge or face (coarsest first), are put
      // back at its middle afterwards.
      const unsigned int  n_vertices = tria.n_vertices();
      std::vector<bool>   fixed(n_vertices, false);
      std::vector<double> shortest_edge(n_vertices,
                                        std::numeric_limits<double>::max());
      std::vector<std::pair<unsigned int, unsigned int>> hanging; // level, v
      std::map<unsigned int, std::vector<unsigned int>>  parent_vertices;
      for (const auto &cell : tria.active_cell_iterators())
        {
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              for (const unsigned int v : cell->face(f)->vertex_indices())
                fixed[cell->face(f)->vertex_index(v)] = true;
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            {
              const auto line = cell->line(l);
              if (line->has_children())
                {
                  const unsigned int v = line->child(0)->vertex_index(1);
                  hanging.emplace_back(cell->level(), v);
                  parent_vertices[v] = {line->vertex_index(0),
                                        line->vertex_index(1)};
                }
              else
                for (const unsigned int v : {0u, 1u})
                  shortest_edge[line->vertex_index(v)] =
                    std::min(shortest_edge[line->vertex_index(v)],
                             line->diameter());
            }
          if constexpr (dim == 3)
            for (const unsigned int f : cell->face_indices())
              {
                const auto face = cell->face(f);
                if (face->has_children())
                  {
                    const unsigned int v = face->child(0)->vertex_index(3);
                    hanging.emplace_back(cell->level(), v);
                    parent_vertices[v] = {face->vertex_index(0),
                                          face->vertex_index(1),
                                          face->vertex_index(2),
                                          face->vertex_index(3)};
                  }
              }
        }
      for (const auto &h : hanging)
        fixed[h.second] = true;

      // New positions, drawn in the order of the vertex indices: uniform
      // in the ball of radius fraction * shortest edge.
      std::vector<Point<dim>>                vertices = tria.get_vertices();
      std::mt19937                           generator(5489u);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      const std::vector<bool>               &used = tria.get_used_vertices();
      for (unsigned int v = 0; v < n_vertices; ++v)
        if (used[v] && !fixed[v] &&
            shortest_edge[v] < std::numeric_limits<double>::max())
          {
            Tensor<1, dim> shift;
            do
              for (unsigned int d = 0; d < dim; ++d)
                shift[d] = uniform(generator);
            while (shift.norm_square() > 1.);
            vertices[v] += fraction * shortest_edge[v] * shift;
          }
      std::sort(hanging.begin(), hanging.end());
      for (const auto &h : hanging)
        {
          Point<dim> middle;
          for (const unsigned int p : parent_vertices[h.second])
            middle += vertices[p];
          vertices[h.second] =
            middle / static_cast<double>(parent_vertices[h.second].size());
        }

      std::vector<bool> moved(n_vertices, false);
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (!moved[cell->vertex_index(v)])
            {
              cell->vertex(v)              = vertices[cell->vertex_index(v)];
              moved[cell->vertex_index(v)] = true;
            }

      // Curved interior descriptions (transfinite interpolation) would
      // pull the moved vertices back to charts built on the coarse cells,
      // whose vertices may have moved: the interior, and boundaries
      // described by a transfinite interpolation, become straight-sided;
      // the other boundary manifolds (circles, cylinders) stay.
      const auto straighten = [&tria](const auto &object) {
        const types::manifold_id id = object->manifold_id();
        if (id == numbers::flat_manifold_id)
          return;
        if (!object->at_boundary() ||
            dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(
              &tria.get_manifold(id)) != nullptr)
          object->set_manifold_id(numbers::flat_manifold_id);
      };
      for (const auto &cell : tria.active_cell_iterators())
        {
          cell->set_manifold_id(numbers::flat_manifold_id);
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            straighten(cell->line(l));
          if constexpr (dim == 3)
            for (const unsigned int f : cell->face_indices())
              straighten(cell->face(f));
        }

      for (const auto &cell : tria.active_cell_iterators())
        AssertThrow(cell->measure() > 0.,
                    ExcMessage(entry + " inverts a cell at " +
                               Utilities::to_string(cell->center()[0]) + ", " +
                               Utilities::to_string(cell->center()[1]) +
                               ": use a smaller value."));
    }



    template <int dim>
    double
    smallest_cell_near(
      const Triangulation<dim>                        &tria,
      const std::function<double(const Point<dim> &)> &distance)
    {
      double h = std::numeric_limits<double>::max();
      for (const auto &cell : tria.active_cell_iterators())
        if (distance(cell->center()) < cell->diameter())
          h = std::min(h, cell->diameter());
      return h;
    }

    template void
    join_bodies(const std::vector<const Triangulation<2> *> &,
                Triangulation<2> &);
    template <int dim>
    types::global_dof_index
    vertex_dof(const DoFHandler<dim>   &dof_handler,
               const Point<dim>        &point,
               const unsigned int       component,
               const double             tolerance,
               const std::string       &what,
               const types::material_id material_id)
    {
      types::global_dof_index dof = numbers::invalid_dof_index;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (material_id == numbers::invalid_material_id ||
            cell->material_id() == material_id)
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(point) < tolerance)
              dof = cell->vertex_dof_index(v, component);
      AssertThrow(dof != numbers::invalid_dof_index,
                  ExcMessage("No mesh vertex at " + what + "."));
      return dof;
    }



    template void
    join_bodies(const std::vector<const Triangulation<3> *> &,
                Triangulation<3> &);
    template void
    refine_toward(Triangulation<2> &,
                  const std::function<double(const Point<2> &)> &,
                  const unsigned int,
                  const double,
                  const std::string &,
                  const types::material_id);
    template void
    refine_planned(Triangulation<2> &,
                   const unsigned int,
                   const std::string &,
                   const std::vector<GradedRefinement<2>> &);
    template void
    perturb_interior_vertices(Triangulation<2> &,
                              const double,
                              const std::string &);
    template void
    refine_toward(Triangulation<3> &,
                  const std::function<double(const Point<3> &)> &,
                  const unsigned int,
                  const double,
                  const std::string &,
                  const types::material_id);
    template void
    refine_planned(Triangulation<3> &,
                   const unsigned int,
                   const std::string &,
                   const std::vector<GradedRefinement<3>> &);
    template void
    perturb_interior_vertices(Triangulation<3> &,
                              const double,
                              const std::string &);
    template double
    smallest_cell_near(const Triangulation<2> &,
                       const std::function<double(const Point<2> &)> &);
    template double
    smallest_cell_near(const Triangulation<3> &,
                       const std::function<double(const Point<3> &)> &);
    template types::global_dof_index
    vertex_dof(const DoFHandler<2> &,
               const Point<2> &,
               const unsigned int,
               const double,
               const std::string &,
               const types::material_id);
    template types::global_dof_index
    vertex_dof(const DoFHandler<3> &,
               const Point<3> &,
               const unsigned int,
               const double,
               const std::string &,
               const types::material_id);
  } // namespace Geometry
} // namespace Common
