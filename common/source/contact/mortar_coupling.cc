#include <common/contact/mortar_coupling.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <map>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    namespace
    {
      /** Coverage tolerance: a face counts as covered if the paired part of
       * its measure differs from the whole by less than this fraction. */
      constexpr double coverage_tolerance = 1e-9;

      /** Twice the signed area of a plane polygon (positive if its vertices
       * run counterclockwise). */
      double
      twice_signed_area(const std::vector<Point<2>> &polygon)
      {
        double a = 0.;
        for (unsigned int i = 0; i < polygon.size(); ++i)
          {
            const Point<2> &p = polygon[i];
            const Point<2> &q = polygon[(i + 1) % polygon.size()];
            a += p[0] * q[1] - q[0] * p[1];
          }
        return a;
      }

      /** Cross product of b - a and c - a (twice the signed area of the
       * triangle a, b, c). */
      double
      orientation(const Point<2> &a, const Point<2> &b, const Point<2> &c)
      {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      }

      /**
       * Sutherland-Hodgman clipping of @p subject by the convex polygon
       * @p clip; both run counterclockwise. Returns the intersection
       * (empty if the two do not overlap).
       */
      std::vector<Point<2>>
      clip_polygon(const std::vector<Point<2>> &subject,
                   const std::vector<Point<2>> &clip)
      {
        std::vector<Point<2>> result = subject;
        for (unsigned int e = 0; e < clip.size() && !result.empty(); ++e)
          {
            const Point<2>             &a     = clip[e];
            const Point<2>             &b     = clip[(e + 1) % clip.size()];
            const std::vector<Point<2>> input = result;
            result.clear();
            for (unsigned int i = 0; i < input.size(); ++i)
              {
                const Point<2> &p      = input[i];
                const Point<2> &q      = input[(i + 1) % input.size()];
                const double    side_p = orientation(a, b, p);
                const double    side_q = orientation(a, b, q);
                if (side_p >= 0.)
                  result.push_back(p);
                if ((side_p >= 0.) != (side_q >= 0.))
                  result.push_back(p + (side_p / (side_p - side_q)) * (q - p));
              }
          }
        return result;
      }
    } // namespace



    template <int dim>
    void
    MortarCoupling<dim>::reinit(const ContactSurface<dim> &secondary_surface,
                                const ContactSurface<dim> &primary_surface,
                                const ContactSearch<dim>  &search,
                                const double               search_distance,
                                const bool                 axisymmetric)
    {
      AssertThrow(dim == 2 || !axisymmetric,
                  ExcMessage("Axisymmetric mortar coupling needs 2D "
                             "surfaces."));
      // Ring measure 2 pi x of an axisymmetric model, 1 otherwise.
      const auto ring = [axisymmetric](const Point<dim> &x) {
        return axisymmetric ? 2. * numbers::PI * x[0] : 1.;
      };

      secondary = &secondary_surface;
      primary   = &primary_surface;

      const unsigned int n_nodes = secondary->n_nodes();
      rows.assign(n_nodes, MortarRow<dim>());
      dual_coefficients.assign(secondary->n_faces(), FullMatrix<double>());
      std::vector<std::map<unsigned int, double>> weights(n_nodes);
      std::vector<bool>                           node_covered(n_nodes, true);

      const unsigned int degree = secondary->base_element().degree;
      // Exact for the products of shape functions on straight faces, and
      // accurate for curved ones.
      const QGauss<dim - 1> face_quadrature(degree + 3);
      const QGauss<1>       segment_quadrature(
        std::max(degree, primary->base_element().degree) + 3);

      std::vector<double>             N, N_primary;
      std::vector<Tensor<1, dim - 1>> dN;

      for (unsigned int s = 0; s < secondary->n_faces(); ++s)
        {
          const SurfaceFace<dim> &face    = secondary->face(s);
          const unsigned int      n_shape = face.nodes.size();

          // Dual basis: A = diag(D_e) Me^{-1}.
          FullMatrix<double> Me(n_shape, n_shape);
          Vector<double>     De(n_shape);
          double             face_measure = 0.;
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            {
              const Point<dim - 1> &eta = face_quadrature.point(q);
              secondary->shape_values(s, eta, N);
              const double JxW = secondary->jacobian(s, eta) *
                                 face_quadrature.weight(q) *
                                 ring(secondary->point(s, eta));
              face_measure += JxW;
              for (unsigned int a = 0; a < n_shape; ++a)
                {
                  De(a) += N[a] * JxW;
                  for (unsigned int b = 0; b < n_shape; ++b)
                    Me(a, b) += N[a] * N[b] * JxW;
                }
            }
          FullMatrix<double> Me_inverse(n_shape, n_shape);
          Me_inverse.invert(Me);
          FullMatrix<double> &A = dual_coefficients[s];
          A.reinit(n_shape, n_shape);
          for (unsigned int a = 0; a < n_shape; ++a)
            for (unsigned int b = 0; b < n_shape; ++b)
              A(a, b) = De(a) * Me_inverse(a, b);

          const double size = secondary->face_size(s);
          for (unsigned int a = 0; a < n_shape; ++a)
            {
              rows[face.nodes[a]].weight += De(a);
              rows[face.nodes[a]].mesh_size =
                std::max(rows[face.nodes[a]].mesh_size, size);
            }

          // One integration point: secondary face parameter xi, weight JxW,
          // partner on primary face m at parameter eta_m.
          double     covered_measure = 0.;
          const auto add_point       = [&](const Point<dim - 1> &xi,
                                     const double          JxW,
                                     const unsigned int    m,
                                     const Point<dim - 1> &eta_m) {
            covered_measure += JxW;
            secondary->shape_values(s, xi, N);
            primary->shape_values(m, eta_m, N_primary);
            const auto &primary_nodes = primary->face(m).nodes;
            for (unsigned int a = 0; a < n_shape; ++a)
              {
                double psi = 0.;
                for (unsigned int b = 0; b < n_shape; ++b)
                  psi += A(a, b) * N[b];
                for (unsigned int k = 0; k < primary_nodes.size(); ++k)
                  weights[face.nodes[a]][primary_nodes[k]] +=
                    psi * N_primary[k] * JxW;
              }
          };

          // Segments: the part of face s that projects onto each candidate
          // primary face. In 2D the segments are parameter intervals, cut
          // along the secondary normal field; in 3D they are polygons,
          // clipped in an auxiliary plane.
          if constexpr (dim == 3)
            integrate_3d_segments(s, search, search_distance, add_point);
          else
            for (const unsigned int m :
                 search.faces_near(secondary->bounding_box(s, search_distance)))
              {
                const Point<dim - 1> eta_0(0.), eta_1(1.);
                const auto p0 = ContactSearch<dim>::project_along_normal_field(
                  *secondary,
                  s,
                  primary->point(m, eta_0));
                const auto p1 = ContactSearch<dim>::project_along_normal_field(
                  *secondary,
                  s,
                  primary->point(m, eta_1));
                if (!p0.converged || !p1.converged)
                  continue;
                const double xi_a =
                  std::max(0., std::min(p0.eta[0], p1.eta[0]));
                const double xi_b =
                  std::min(1., std::max(p0.eta[0], p1.eta[0]));
                if (xi_b - xi_a < 1e-12)
                  continue;

                for (unsigned int q = 0; q < segment_quadrature.size(); ++q)
                  {
                    const Point<dim - 1> xi(
                      xi_a + (xi_b - xi_a) * segment_quadrature.point(q)[0]);
                    const double weight =
                      segment_quadrature.weight(q) * (xi_b - xi_a);

                    // Secondary point and the interpolated normal field.
                    secondary->shape_values(s, xi, N);
                    Point<dim>     x;
                    Tensor<1, dim> n;
                    for (unsigned int a = 0; a < n_shape; ++a)
                      {
                        x += N[a] * secondary->node(face.nodes[a]).position;
                        n += N[a] * secondary->node(face.nodes[a]).normal;
                      }
                    n /= n.norm();

                    const auto projection =
                      ContactSearch<dim>::project_along(*primary, m, x, n);
                    if (!projection.inside(1e-9) ||
                        std::abs(projection.distance) > search_distance ||
                        primary->unit_normal(m, projection.eta) * n >= 0.)
                      continue;

                    add_point(xi,
                              secondary->jacobian(s, xi) * weight * ring(x),
                              m,
                              projection.eta);
                  }
              }
          if (std::abs(covered_measure - face_measure) >
              coverage_tolerance * face_measure)
            for (unsigned int a = 0; a < n_shape; ++a)
              node_covered[face.nodes[a]] = false;
        }

      // Pointwise gap at each paired node along its normal.
      for (unsigned int j = 0; j < n_nodes; ++j)
        if (node_covered[j] && !weights[j].empty())
          {
            const SurfaceNode<dim> &node = secondary->node(j);
            BoundingBox<dim> box(std::make_pair(node.position, node.position));
            box.extend(search_distance);
            for (const unsigned int m : search.faces_near(box))
              {
                const auto projection =
                  ContactSearch<dim>::project_along(*primary,
                                                    m,
                                                    node.position,
                                                    node.normal);
                if (projection.inside(1e-9) &&
                    std::abs(projection.distance) <= search_distance &&
                    std::abs(projection.distance) < std::abs(rows[j].nodal_gap))
                  rows[j].nodal_gap = projection.distance;
              }
          }

      // A node without measure carries no contact force and has no
      // condition: in an axisymmetric model the Q2 vertex on the axis, whose
      // ring-weighted D_j = int N_j 2 pi r ds vanishes.
      double largest_weight = 0.;
      for (const auto &row : rows)
        largest_weight = std::max(largest_weight, row.weight);
      for (unsigned int j = 0; j < n_nodes; ++j)
        {
          rows[j].normal = secondary->node(j).normal;
          if (rows[j].weight <= 1e-10 * largest_weight)
            rows[j].weight = 0.;
          rows[j].has_partner =
            node_covered[j] && !weights[j].empty() && rows[j].weight > 0.;
          if (rows[j].has_partner)
            rows[j].primary_weights.assign(weights[j].begin(),
                                           weights[j].end());
          // The gap of the reference geometry once: later gaps add only
          // displacements, so their round-off scales with the displacement
          // and not with the coordinates.
          Tensor<1, dim> d;
          for (const auto &[k, M] : rows[j].primary_weights)
            d += M * primary->node(k).reference_position;
          d -= rows[j].weight * secondary->node(j).reference_position;
          rows[j].reference_weighted_gap = rows[j].normal * d;
        }
    }



    // Segment-based integration in 3D (Puso and Laursen 2004; Popp et al.
    // 2010): an auxiliary plane through the centre of secondary face s,
    // normal to it; the corners of s and of each candidate primary face,
    // projected onto the plane along its normal, span two polygons; their
    // intersection, split into triangles about its centroid, carries
    // Gauss points, which map back to both faces along the plane normal.
    // The weight is the plane's area element over |n_s . n_0|, the
    // secondary face's own; exact for plane faces with straight edges.
    template <int dim>
    template <typename AddPoint>
    void
    MortarCoupling<dim>::integrate_3d_segments(const unsigned int        s,
                                               const ContactSearch<dim> &search,
                                               const double    search_distance,
                                               const AddPoint &add_point) const
    {
      if constexpr (dim == 3)
        {
          const Point<dim - 1> centre(0.5, 0.5);
          const Point<dim>     x0 = secondary->point(s, centre);
          const Tensor<1, dim> n0 = secondary->unit_normal(s, centre);
          // Any direction not parallel to n0 spans the plane's axes.
          Tensor<1, dim> axis;
          axis[std::abs(n0[0]) < 0.6 ? 0 : 1] = 1.;
          Tensor<1, dim> e1                   = cross_product_3d(n0, axis);
          e1 /= e1.norm();
          const Tensor<1, dim> e2       = cross_product_3d(n0, e1);
          const auto           to_plane = [&](const Point<dim> &x) {
            const Tensor<1, dim> d = x - x0;
            return Point<2>(d * e1, d * e2);
          };
          const std::array<Point<dim - 1>, 4> corners = {
            {Point<dim - 1>(0., 0.),
             Point<dim - 1>(1., 0.),
             Point<dim - 1>(1., 1.),
             Point<dim - 1>(0., 1.)}};
          const auto polygon = [&](const ContactSurface<dim> &surface,
                                   const unsigned int         f) {
            std::vector<Point<2>> p;
            for (const auto &eta : corners)
              p.push_back(to_plane(surface.point(f, eta)));
            if (twice_signed_area(p) < 0.)
              std::reverse(p.begin(), p.end());
            return p;
          };

          const std::vector<Point<2>> secondary_polygon =
            polygon(*secondary, s);
          const double secondary_area =
            0.5 * twice_signed_area(secondary_polygon);
          const QGaussSimplex<2> triangle_quadrature(
            std::max(secondary->base_element().degree,
                     primary->base_element().degree) +
            2);

          for (const unsigned int m :
               search.faces_near(secondary->bounding_box(s, search_distance)))
            {
              if (primary->unit_normal(m, centre) * n0 >= 0.)
                continue;
              const std::vector<Point<2>> clipped =
                clip_polygon(polygon(*primary, m), secondary_polygon);
              if (clipped.size() < 3 ||
                  0.5 * twice_signed_area(clipped) < 1e-12 * secondary_area)
                continue;

              Point<2> c;
              for (const auto &v : clipped)
                c += v / static_cast<double>(clipped.size());
              for (unsigned int e = 0; e < clipped.size(); ++e)
                {
                  const Point<2> &v1  = clipped[e];
                  const Point<2> &v2  = clipped[(e + 1) % clipped.size()];
                  const double    det = orientation(c, v1, v2);
                  if (det <= 0.)
                    continue;
                  for (unsigned int q = 0; q < triangle_quadrature.size(); ++q)
                    {
                      const Point<2> &r = triangle_quadrature.point(q);
                      const Point<2>  y = c + r[0] * (v1 - c) + r[1] * (v2 - c);
                      const Point<dim> y3 = x0 + y[0] * e1 + y[1] * e2;

                      const auto on_secondary =
                        ContactSearch<dim>::project_along(*secondary,
                                                          s,
                                                          y3,
                                                          n0);
                      if (!on_secondary.inside(1e-8))
                        continue;
                      const auto on_primary =
                        ContactSearch<dim>::project_along(*primary,
                                                          m,
                                                          on_secondary.point,
                                                          n0);
                      if (!on_primary.inside(1e-8) ||
                          std::abs(on_primary.distance) > search_distance)
                        continue;
                      const double cosine = std::abs(
                        secondary->unit_normal(s, on_secondary.eta) * n0);
                      add_point(on_secondary.eta,
                                triangle_quadrature.weight(q) * det / cosine,
                                m,
                                on_primary.eta);
                    }
                }
            }
        }
      else
        {
          (void)s;
          (void)search;
          (void)search_distance;
          (void)add_point;
        }
    }



    template <int dim>
    unsigned int
    MortarCoupling<dim>::n_rows() const
    {
      return rows.size();
    }



    template <int dim>
    const MortarRow<dim> &
    MortarCoupling<dim>::row(const unsigned int j) const
    {
      return rows[j];
    }



    template <int dim>
    const FullMatrix<double> &
    MortarCoupling<dim>::dual_basis(const unsigned int f) const
    {
      return dual_coefficients[f];
    }



    template <int dim>
    const ContactSurface<dim> &
    MortarCoupling<dim>::secondary_surface() const
    {
      return *secondary;
    }



    template <int dim>
    const ContactSurface<dim> &
    MortarCoupling<dim>::primary_surface() const
    {
      return *primary;
    }



    template <int dim>
    template <typename VectorType>
    double
    MortarCoupling<dim>::weighted_gap(const unsigned int j,
                                      const VectorType  &u) const
    {
      const MortarRow<dim>   &r    = rows[j];
      const SurfaceNode<dim> &node = secondary->node(j);
      Tensor<1, dim>          d;
      for (const auto &[k, M] : r.primary_weights)
        for (unsigned int c = 0; c < dim; ++c)
          d[c] += M * u(primary->node(k).dofs[c]);
      for (unsigned int c = 0; c < dim; ++c)
        d[c] -= r.weight * u(node.dofs[c]);
      return r.reference_weighted_gap + r.normal * d;
    }



    template <int dim>
    template <typename VectorType>
    Tensor<1, dim>
    MortarCoupling<dim>::relative_displacement(const unsigned int j,
                                               const VectorType  &u) const
    {
      const MortarRow<dim>   &r    = rows[j];
      const SurfaceNode<dim> &node = secondary->node(j);
      Tensor<1, dim>          d;
      for (const auto &[k, M] : r.primary_weights)
        for (unsigned int c = 0; c < dim; ++c)
          d[c] += M * u(primary->node(k).dofs[c]);
      for (unsigned int c = 0; c < dim; ++c)
        d[c] -= r.weight * u(node.dofs[c]);
      return d / r.weight;
    }

    template class MortarCoupling<2>;
    template class MortarCoupling<3>;
#define INSTANTIATE(dim, V)                                                     \
  template double         MortarCoupling<dim>::weighted_gap(const unsigned int, \
                                                    const V &) const;   \
  template Tensor<1, dim> MortarCoupling<dim>::relative_displacement(           \
    const unsigned int,                                                         \
    const V &) const;
    INSTANTIATE(2, Vector<double>)
    INSTANTIATE(3, Vector<double>)
    INSTANTIATE(2, TrilinosWrappers::MPI::Vector)
    INSTANTIATE(3, TrilinosWrappers::MPI::Vector)
#undef INSTANTIATE
  } // namespace Contact
} // namespace Common
