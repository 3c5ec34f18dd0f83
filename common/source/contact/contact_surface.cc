#include <common/contact/contact_surface.h>

#include <deal.II/base/qprojector.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_poly.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <tuple>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    namespace
    {
      /** Every polynomial of @p space at the unit cell point @p p, and
       * their gradients if @p gradients: the 1D factors of a tensor
       * product space are evaluated once for all shape functions. The
       * rows are integrated again and again at the same points (the
       * quadrature points of the faces, for every Newton iterate and every
       * difference quotient of contact_force_derivative()): the values and
       * gradients are kept per space and point, in a cache of each thread
       * that is emptied when it holds 20000 points. */
      template <int dim>
      void
      evaluate_all(const ScalarPolynomialsBase<dim> &space,
                   const Point<dim>                 &p,
                   std::vector<double>              &values,
                   std::vector<Tensor<1, dim>>      &grads,
                   const bool                        gradients)
      {
        using Key =
          std::tuple<const void *, unsigned int, std::array<double, dim>>;
        struct Entry
        {
          std::vector<double>         values;
          std::vector<Tensor<1, dim>> grads;
        };
        thread_local std::map<Key, Entry> cache;
        std::array<double, dim>           coordinates;
        for (unsigned int d = 0; d < dim; ++d)
          coordinates[d] = p[d];
        const Key key{&space, space.n(), coordinates};
        auto      it = cache.find(key);
        if (it == cache.end())
          {
            if (cache.size() >= 20000)
              cache.clear();
            thread_local std::vector<Tensor<2, dim>> no_hessians;
            thread_local std::vector<Tensor<3, dim>> no_third;
            thread_local std::vector<Tensor<4, dim>> no_fourth;
            Entry                                    entry;
            entry.values.resize(space.n());
            entry.grads.resize(space.n());
            space.evaluate(p,
                           entry.values,
                           entry.grads,
                           no_hessians,
                           no_third,
                           no_fourth);
            it = cache.emplace(key, std::move(entry)).first;
          }
        values = it->second.values;
        if (gradients)
          grads = it->second.grads;
        else
          grads.clear();
      }
    } // namespace

    template <int dim>
    ContactSurface<dim>::ContactSurface(const DoFHandler<dim>   &dof_handler,
                                        const Mapping<dim>      &mapping,
                                        const types::boundary_id boundary_id)
      : fe(dof_handler.get_fe().base_element(0))
      , poly_space(nullptr)
    {
      if (const auto *poly = dynamic_cast<const FE_Poly<dim> *>(&fe))
        poly_space = &poly->get_poly_space();
      const FiniteElement<dim> &system_fe = dof_handler.get_fe();
      AssertThrow(system_fe.n_base_elements() == 1 &&
                    system_fe.element_multiplicity(0) == dim,
                  ExcMessage("Contact surfaces need an FESystem of dim "
                             "equal scalar elements."));
      AssertThrow(fe.has_support_points(),
                  ExcMessage("Contact surfaces need a Lagrange element."));

      // Affine maps from face coordinates into the unit cell, one per face
      // number, from deal.II's own face projection.
      const unsigned int faces_per_cell = GeometryInfo<dim>::faces_per_cell;
      face_origin.resize(faces_per_cell);
      face_axes.resize(faces_per_cell);
      {
        std::vector<Point<dim - 1>> points(dim);
        for (unsigned int k = 0; k < dim - 1; ++k)
          points[k + 1][k] = 1.;
        const Quadrature<dim - 1> q(points,
                                    std::vector<double>(points.size(), 1.));
        for (unsigned int f = 0; f < faces_per_cell; ++f)
          {
            const Quadrature<dim> projected = QProjector<dim>::project_to_face(
              ReferenceCells::get_hypercube<dim>(),
              q,
              f);
            face_origin[f] = projected.point(0);
            for (unsigned int k = 0; k < dim - 1; ++k)
              face_axes[f][k] = projected.point(k + 1) - projected.point(0);
          }
      }

      const std::vector<Point<dim>> &unit_points = fe.get_unit_support_points();
      std::map<types::global_dof_index, unsigned int> node_of_dof;
      std::vector<types::global_dof_index>            dof_indices(
        system_fe.n_dofs_per_cell());

      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              cell->get_dof_indices(dof_indices);
              SurfaceFace<dim> face;
              face.cell    = cell;
              face.face_no = f;
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.has_support_on_face(i, f))
                  {
                    std::array<types::global_dof_index, dim> dofs;
                    for (unsigned int c = 0; c < dim; ++c)
                      dofs[c] =
                        dof_indices[system_fe.component_to_system_index(c, i)];
                    const auto   it = node_of_dof.find(dofs[0]);
                    unsigned int node;
                    if (it == node_of_dof.end())
                      {
                        node = nodes.size();
                        node_of_dof.emplace(dofs[0], node);
                        SurfaceNode<dim> new_node;
                        new_node.reference_position =
                          mapping.transform_unit_to_real_cell(cell,
                                                              unit_points[i]);
                        new_node.position = new_node.reference_position;
                        new_node.dofs     = dofs;
                        nodes.push_back(new_node);
                      }
                    else
                      node = it->second;
                    face.shape_indices.push_back(i);
                    face.nodes.push_back(node);
                  }
              face.orientation = 1.;
              faces.push_back(face);
            }
      AssertThrow(!faces.empty(),
                  ExcMessage("Boundary id " + std::to_string(boundary_id) +
                             " does not exist on the mesh."));

      // Orient each face normal out of its cell.
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          Point<dim - 1> centre;
          for (unsigned int k = 0; k < dim - 1; ++k)
            centre[k] = 0.5;
          const Tensor<1, dim> n = unit_normal(f, centre);
          const Tensor<1, dim> outward =
            point(f, centre) - faces[f].cell->center();
          faces[f].orientation = (n * outward >= 0. ? 1. : -1.);
        }
      compute_nodal_normals();
    }



    template <int dim>
    unsigned int
    ContactSurface<dim>::n_faces() const
    {
      return faces.size();
    }



    template <int dim>
    unsigned int
    ContactSurface<dim>::n_nodes() const
    {
      return nodes.size();
    }



    template <int dim>
    const SurfaceFace<dim> &
    ContactSurface<dim>::face(const unsigned int f) const
    {
      return faces[f];
    }



    template <int dim>
    const SurfaceNode<dim> &
    ContactSurface<dim>::node(const unsigned int n) const
    {
      return nodes[n];
    }



    template <int dim>
    const FiniteElement<dim> &
    ContactSurface<dim>::base_element() const
    {
      return fe;
    }



    template <int dim>
    Point<dim>
    ContactSurface<dim>::unit_cell_point(const unsigned int    face_no,
                                         const Point<dim - 1> &eta) const
    {
      Point<dim> p = face_origin[face_no];
      for (unsigned int k = 0; k < dim - 1; ++k)
        p += eta[k] * face_axes[face_no][k];
      return p;
    }



    template <int dim>
    void
    ContactSurface<dim>::shape_values(const unsigned int    f,
                                      const Point<dim - 1> &eta,
                                      std::vector<double>  &values) const
    {
      const SurfaceFace<dim> &face = faces[f];
      const Point<dim>        p    = unit_cell_point(face.face_no, eta);
      values.resize(face.shape_indices.size());
      if (poly_space != nullptr)
        {
          thread_local std::vector<double>         all_values;
          thread_local std::vector<Tensor<1, dim>> no_grads;
          evaluate_all(*poly_space, p, all_values, no_grads, false);
          for (unsigned int a = 0; a < face.shape_indices.size(); ++a)
            values[a] = all_values[face.shape_indices[a]];
          return;
        }
      for (unsigned int a = 0; a < face.shape_indices.size(); ++a)
        values[a] = fe.shape_value(face.shape_indices[a], p);
    }



    template <int dim>
    void
    ContactSurface<dim>::shape_values_and_derivatives(
      const unsigned int               f,
      const Point<dim - 1>            &eta,
      std::vector<double>             &values,
      std::vector<Tensor<1, dim - 1>> &derivatives) const
    {
      const SurfaceFace<dim> &face = faces[f];
      const Point<dim>        p    = unit_cell_point(face.face_no, eta);
      values.resize(face.shape_indices.size());
      derivatives.resize(face.shape_indices.size());
      if (poly_space != nullptr)
        {
          thread_local std::vector<double>         all_values;
          thread_local std::vector<Tensor<1, dim>> all_grads;
          evaluate_all(*poly_space, p, all_values, all_grads, true);
          for (unsigned int a = 0; a < face.shape_indices.size(); ++a)
            {
              values[a] = all_values[face.shape_indices[a]];
              for (unsigned int k = 0; k < dim - 1; ++k)
                derivatives[a][k] =
                  all_grads[face.shape_indices[a]] * face_axes[face.face_no][k];
            }
          return;
        }
      for (unsigned int a = 0; a < face.shape_indices.size(); ++a)
        {
          values[a]                 = fe.shape_value(face.shape_indices[a], p);
          const Tensor<1, dim> grad = fe.shape_grad(face.shape_indices[a], p);
          for (unsigned int k = 0; k < dim - 1; ++k)
            derivatives[a][k] = grad * face_axes[face.face_no][k];
        }
    }



    template <int dim>
    Point<dim>
    ContactSurface<dim>::point(const unsigned int    f,
                               const Point<dim - 1> &eta) const
    {
      std::vector<double> values;
      shape_values(f, eta, values);
      Point<dim> x;
      for (unsigned int a = 0; a < values.size(); ++a)
        x += values[a] * nodes[faces[f].nodes[a]].position;
      return x;
    }



    template <int dim>
    Point<dim>
    ContactSurface<dim>::point_and_tangents(
      const unsigned int                   f,
      const Point<dim - 1>                &eta,
      std::array<Tensor<1, dim>, dim - 1> &tangents) const
    {
      std::vector<double>             values;
      std::vector<Tensor<1, dim - 1>> derivatives;
      shape_values_and_derivatives(f, eta, values, derivatives);
      Point<dim> x;
      for (auto &t : tangents)
        t = 0;
      for (unsigned int a = 0; a < values.size(); ++a)
        {
          const Point<dim> &xa = nodes[faces[f].nodes[a]].position;
          x += values[a] * xa;
          for (unsigned int k = 0; k < dim - 1; ++k)
            tangents[k] += derivatives[a][k] * xa;
        }
      return x;
    }



    template <int dim>
    Tensor<1, dim>
    ContactSurface<dim>::unit_normal(const unsigned int    f,
                                     const Point<dim - 1> &eta) const
    {
      std::array<Tensor<1, dim>, dim - 1> t;
      point_and_tangents(f, eta, t);
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        n = Tensor<1, dim>({t[0][1], -t[0][0]});
      else
        n = cross_product_3d(t[0], t[1]);
      return faces[f].orientation * n / n.norm();
    }



    template <int dim>
    double
    ContactSurface<dim>::jacobian(const unsigned int    f,
                                  const Point<dim - 1> &eta) const
    {
      std::array<Tensor<1, dim>, dim - 1> t;
      point_and_tangents(f, eta, t);
      if constexpr (dim == 2)
        return t[0].norm();
      else
        return cross_product_3d(t[0], t[1]).norm();
    }



    template <int dim>
    BoundingBox<dim>
    ContactSurface<dim>::bounding_box(const unsigned int f,
                                      const double       margin) const
    {
      std::vector<Point<dim>> points;
      for (const unsigned int n : faces[f].nodes)
        points.push_back(nodes[n].position);
      BoundingBox<dim> box(points);
      box.extend(margin);
      return box;
    }



    template <int dim>
    double
    ContactSurface<dim>::face_size(const unsigned int f) const
    {
      double size = 0;
      for (const unsigned int a : faces[f].nodes)
        for (const unsigned int b : faces[f].nodes)
          size = std::max(size, nodes[a].position.distance(nodes[b].position));
      return size;
    }



    template <int dim>
    void
    ContactSurface<dim>::compute_nodal_normals()
    {
      const std::vector<Point<dim>> &unit_points = fe.get_unit_support_points();
      for (auto &node : nodes)
        node.normal = 0;
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          const SurfaceFace<dim> &face = faces[f];
          for (unsigned int a = 0; a < face.nodes.size(); ++a)
            {
              // Face coordinates of the node: invert the affine face map
              // (its axes are orthogonal unit vectors of the unit cell).
              const Tensor<1, dim> d =
                unit_points[face.shape_indices[a]] - face_origin[face.face_no];
              Point<dim - 1> eta;
              for (unsigned int k = 0; k < dim - 1; ++k)
                eta[k] = d * face_axes[face.face_no][k] /
                         face_axes[face.face_no][k].norm_square();
              nodes[face.nodes[a]].normal += unit_normal(f, eta);
            }
        }
      for (auto &node : nodes)
        {
          for (unsigned int c = 0; c < dim; ++c)
            if (node.on_symmetry_plane[c])
              node.normal[c] = 0.;
          node.normal /= node.normal.norm();
        }
    }



    template <int dim>
    void
    ContactSurface<dim>::symmetrize_normals(
      const AffineConstraints<double> &constraints)
    {
      // Per node and component: whether the faces around the node reach
      // below and above the plane through it normal to e_c.
      std::vector<std::array<std::array<bool, 2>, dim>> sides(
        nodes.size(),
        std::array<std::array<bool, 2>, dim>{});
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          const double tolerance = 1e-8 * face_size(f);
          for (const unsigned int a : faces[f].nodes)
            for (const unsigned int b : faces[f].nodes)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const double d = nodes[b].reference_position[c] -
                                   nodes[a].reference_position[c];
                  if (d < -tolerance)
                    sides[a][c][0] = true;
                  else if (d > tolerance)
                    sides[a][c][1] = true;
                }
        }
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          SurfaceNode<dim>     &node = nodes[n];
          std::array<bool, dim> held{}, on_plane{};
          unsigned int          n_held = 0;
          for (unsigned int c = 0; c < dim; ++c)
            {
              const auto *line =
                constraints.get_constraint_entries(node.dofs[c]);
              held[c] = line != nullptr && line->empty() &&
                        constraints.get_inhomogeneity(node.dofs[c]) == 0.;
              n_held += held[c] ? 1 : 0;
              // The surface ends at the plane: it lies on one side only.
              on_plane[c] = held[c] && sides[n][c][0] != sides[n][c][1];
            }
          if (n_held < dim)
            node.on_symmetry_plane = on_plane;
        }
      compute_nodal_normals();
    }



    template <int dim>
    template <typename VectorType>
    void
    ContactSurface<dim>::update_positions(const VectorType &displacement)
    {
      for (auto &node : nodes)
        {
          node.position = node.reference_position;
          for (unsigned int c = 0; c < dim; ++c)
            node.position[c] += displacement(node.dofs[c]);
        }
      compute_nodal_normals();
    }

    template <int dim>
    void
    ContactSurface<dim>::move_node(const unsigned int    n,
                                   const Tensor<1, dim> &shift)
    {
      AssertIndexRange(n, nodes.size());
      nodes[n].position += shift;
      compute_nodal_normals();
    }

    template class ContactSurface<2>;
    template class ContactSurface<3>;
    template void
    ContactSurface<2>::update_positions(const Vector<double> &);
    template void
    ContactSurface<3>::update_positions(const Vector<double> &);
    template void
    ContactSurface<2>::update_positions(const TrilinosWrappers::MPI::Vector &);
    template void
    ContactSurface<3>::update_positions(const TrilinosWrappers::MPI::Vector &);
  } // namespace Contact
} // namespace Common
