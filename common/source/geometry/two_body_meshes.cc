#include <common/geometry/two_body_meshes.h>

#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <limits>
#include <map>
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
    } // namespace



    template <int dim>
    void
    refine_global_checked(Triangulation<dim> &tria,
                          const unsigned int  n_times,
                          const std::string  &entries)
    {
      // Each refinement multiplies the cells by 2^dim: the count is
      // checked one refinement at a time, before it overflows.
      std::uint64_t n_cells = tria.n_active_cells();
      for (unsigned int i = 0; i < n_times; ++i)
        {
          n_cells *= (1u << dim);
          check_mesh_size<dim>(n_cells, entries);
        }
      tria.refine_global(n_times);
    }



    template <int dim>
    void
    refine_toward(Triangulation<dim>                              &tria,
                  const std::function<double(const Point<dim> &)> &distance,
                  const unsigned int                               n_passes,
                  const double                                     factor,
                  const std::string                               &entries)
    {
      for (unsigned int pass = 0; pass < n_passes; ++pass)
        {
          std::uint64_t n_flagged = 0;
          for (const auto &cell : tria.active_cell_iterators())
            if (distance(cell->center()) < factor * cell->diameter())
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
    refine_global_checked(Triangulation<2> &,
                          const unsigned int,
                          const std::string &);
    template void
    refine_toward(Triangulation<2> &,
                  const std::function<double(const Point<2> &)> &,
                  const unsigned int,
                  const double,
                  const std::string &);
    template void
    refine_global_checked(Triangulation<3> &,
                          const unsigned int,
                          const std::string &);
    template void
    refine_toward(Triangulation<3> &,
                  const std::function<double(const Point<3> &)> &,
                  const unsigned int,
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
