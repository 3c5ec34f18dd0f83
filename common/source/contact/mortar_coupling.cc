#include <common/contact/mortar_coupling.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
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

          // Segments: the parameter interval of face s that projects onto
          // each candidate primary face. In 2D the segments are intervals;
          // 3D needs polygon clipping, which is not implemented.
          double covered_measure = 0.;
          if constexpr (dim != 2)
            {
              AssertThrow(false,
                          ExcMessage("Mortar segmentation is implemented "
                                     "for 2D (and axisymmetric) surfaces "
                                     "only."));
            }
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

                    const double JxW =
                      secondary->jacobian(s, xi) * weight * ring(x);
                    covered_measure += JxW;
                    primary->shape_values(m, projection.eta, N_primary);
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
