#include <common/contact/mortar_coupling.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

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

      /**
       * Extension of a primary face past an edge on a symmetry plane, as a
       * fraction of its parameter range (3D). The auxiliary plane of a
       * secondary face beside a symmetry plane is tilted against it, so
       * where the two surfaces are apart the primary edge projects inside
       * the secondary one and leaves a sliver of the face uncovered, of
       * about the gap times the sine of the tilt: half a face's angle on a
       * pin in a hole, 2e-9 of the face at a clearance of 2e-7 mm (which
       * dropped the face's nodes from contact). Past the plane the surface
       * continues as its mirror image, which the face's own map
       * extrapolates to the order of its interpolation; clipping against
       * the secondary face keeps what lies beyond. A quarter of a face
       * covers gaps up to about half the face's size at any tilt up to
       * 30 degrees. In 2D the segments are cut along the secondary normal
       * field, which lies in the plane there, and no sliver arises.
       */
      constexpr double symmetry_edge_extension = 0.25;

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
       * Gauss rule on the triangle (0,0), (1,0), (0,1) of any order: the
       * n x n Gauss rule on the unit square collapsed onto it (Duffy),
       * x = a, y = b (1 - a), weight w_a w_b (1 - a); the weights sum to
       * 1/2, and polynomials of degree 2n - 2 are integrated exactly.
       */
      Quadrature<2>
      collapsed_triangle_rule(const unsigned int n)
      {
        const QGauss<2>       square(n);
        std::vector<Point<2>> points;
        std::vector<double>   weights;
        for (unsigned int q = 0; q < square.size(); ++q)
          {
            const Point<2> &ab = square.point(q);
            points.emplace_back(ab[0], ab[1] * (1. - ab[0]));
            weights.push_back(square.weight(q) * (1. - ab[0]));
          }
        return Quadrature<2>(points, weights);
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
    double
    MortarCoupling<dim>::compute_dual_basis(
      const unsigned int         s,
      const Quadrature<dim - 1> &face_quadrature,
      const bool                 axisymmetric,
      Vector<double>            &De)
    {
      const auto ring = [axisymmetric](const Point<dim> &x) {
        return axisymmetric ? 2. * numbers::PI * x[0] : 1.;
      };
      const unsigned int  n_shape = secondary->face(s).nodes.size();
      std::vector<double> N;

      // Dual basis: A = diag(D_e) Me^{-1}.
      FullMatrix<double> Me(n_shape, n_shape);
      De.reinit(n_shape);
      double face_measure = 0.;
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
      return face_measure;
    }



    template <int dim>
    void
    MortarCoupling<dim>::reinit(const ContactSurface<dim> &secondary_surface,
                                const ContactSurface<dim> &primary_surface,
                                const ContactSearch<dim>  &search,
                                const double               search_distance,
                                const bool                 axisymmetric,
                                const std::vector<bool>   &integrated_rows)
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
      primary_nodes.resize(primary->n_nodes());
      for (unsigned int k = 0; k < primary->n_nodes(); ++k)
        primary_nodes[k] = {primary->node(k).reference_position,
                            primary->node(k).dofs};

      const unsigned int n_nodes = secondary->n_nodes();
      rows.assign(n_nodes, MortarRow<dim>());
      dual_coefficients.assign(secondary->n_faces(), FullMatrix<double>());
      std::vector<std::map<unsigned int, double>> weights(n_nodes);
      const std::vector<bool> paired_faces = select_faces(integrated_rows);
      std::vector<bool>       node_covered(integrated);
      const auto              parameter_boxes = primary_parameter_boxes();

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
          Vector<double>          De;
          const double            face_measure =
            compute_dual_basis(s, face_quadrature, axisymmetric, De);
          const FullMatrix<double> &A = dual_coefficients[s];

          const double size = secondary->face_size(s);
          for (unsigned int a = 0; a < n_shape; ++a)
            {
              rows[face.nodes[a]].weight += De(a);
              rows[face.nodes[a]].mesh_size =
                std::max(rows[face.nodes[a]].mesh_size, size);
            }
          if (!paired_faces[s])
            continue;

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
            {
              // Coverage from exact polygon areas: the quadrature sums
              // of curved faces agree with face_measure only to quadrature
              // accuracy.
              const double fraction = integrate_3d_segments(s,
                                                            search,
                                                            search_distance,
                                                            parameter_boxes,
                                                            add_point);
              covered_measure = std::abs(fraction - 1.) <= coverage_tolerance ?
                                  face_measure :
                                  fraction * face_measure;
            }
          else
            for (const unsigned int m :
                 search.faces_near(secondary->bounding_box(s, search_distance)))
              {
                const Point<dim - 1> &eta_0 = parameter_boxes[m][0];
                const Point<dim - 1> &eta_1 = parameter_boxes[m][1];
                // The parameters of the primary face's ends on the
                // secondary face. An end more than ten secondary faces
                // away (a primary face much longer than the secondary one)
                // has no projection; its side of the face, along the
                // chord, is all the clipping needs. Points of a wrong
                // segment fail the projection checks below, and the face
                // then counts as uncovered.
                const auto end_parameter = [&](const Point<dim - 1> &eta) {
                  const Point<dim> y = primary->point(m, eta);
                  const auto       p =
                    ContactSearch<dim>::project_along_normal_field(*secondary,
                                                                   s,
                                                                   y);
                  if (p.converged)
                    return p.eta[0];
                  const Point<dim> x0 = secondary->point(s, Point<dim - 1>(0.));
                  const Tensor<1, dim> chord =
                    secondary->point(s, Point<dim - 1>(1.)) - x0;
                  return (y - x0) * chord / chord.norm_square();
                };
                const double xi_0 = end_parameter(eta_0);
                const double xi_1 = end_parameter(eta_1);
                const double xi_a = std::max(0., std::min(xi_0, xi_1));
                const double xi_b = std::min(1., std::max(xi_0, xi_1));
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
                    if (!projection.converged ||
                        projection.eta[0] < eta_0[0] - 1e-9 ||
                        projection.eta[0] > eta_1[0] + 1e-9 ||
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
            {
              rows[j].primary_weights.assign(weights[j].begin(),
                                             weights[j].end());
              // Exact operators of a covered node satisfy
              // sum_k M_jk = int psi_j = D_j, since the primary shape
              // functions sum to one: a translation of both bodies leaves
              // the weighted gap unchanged, and the primary body receives
              // the force the multipliers transmit. The segment quadrature
              // of curved 3D faces meets this to about 1e-5 only; the rows
              // are scaled to meet it exactly.
              double row_sum = 0.;
              for (const auto &entry : rows[j].primary_weights)
                row_sum += entry.second;
              for (auto &entry : rows[j].primary_weights)
                entry.second *= rows[j].weight / row_sum;
            }
          // The gap of the reference geometry once: later gaps add only
          // displacements, so their round-off scales with the displacement
          // and not with the coordinates. Since sum_k M_jk = D_j, it is
          // sum_k M_jk (X_k - X_j), formed from differences of nearby
          // points: the products M_jk X_k of absolute coordinates would
          // leave a round-off of |X| times the machine precision, which in
          // the current configuration changes with every iterate.
          const Point<dim> &X_j = secondary->node(j).reference_position;
          Tensor<1, dim>    d;
          for (const auto &[k, M] : rows[j].primary_weights)
            d += M * (primary_nodes[k].reference_position - X_j);
          if (!rows[j].has_partner)
            d -= rows[j].weight * X_j;
          rows[j].reference_weighted_gap = rows[j].normal * d;
        }
    }



    // Rows against an analytic rigid surface: one primary node per
    // secondary row, at the dual-weighted mean of the partner points, with
    // the reference node's DoFs (see the header).
    template <int dim>
    void
    MortarCoupling<dim>::reinit(
      const ContactSurface<dim>                      &secondary_surface,
      const RigidSurface<dim>                        &rigid,
      const std::array<types::global_dof_index, dim> &reference_node_dofs,
      const double                                    search_distance,
      const bool                                      axisymmetric,
      const std::vector<bool>                        &integrated_rows)
    {
      reinit(secondary_surface,
             std::vector<RigidPartner<dim>>{
               {&rigid, reference_node_dofs, Tensor<1, dim>()}},
             search_distance,
             axisymmetric,
             integrated_rows);
    }



    // Rows against several rigid surfaces: each integration point pairs
    // with the nearest surface its normal ray meets; row j gets one primary
    // node per surface it meets (node j n_surfaces + i), at the
    // dual-weighted mean of its partner points on surface i.
    template <int dim>
    void
    MortarCoupling<dim>::reinit(const ContactSurface<dim> &secondary_surface,
                                const std::vector<RigidPartner<dim>> &partners,
                                const double             search_distance,
                                const bool               axisymmetric,
                                const std::vector<bool> &integrated_rows)
    {
      AssertThrow(dim == 2 || !axisymmetric,
                  ExcMessage("Axisymmetric mortar coupling needs 2D "
                             "surfaces."));
      AssertThrow(!partners.empty(),
                  ExcMessage("Mortar coupling: no rigid surface."));
      const auto ring = [axisymmetric](const Point<dim> &x) {
        return axisymmetric ? 2. * numbers::PI * x[0] : 1.;
      };
      secondary = &secondary_surface;
      primary   = nullptr;

      const unsigned int n_nodes    = secondary->n_nodes();
      const unsigned int n_surfaces = partners.size();
      rows.assign(n_nodes, MortarRow<dim>());
      dual_coefficients.assign(secondary->n_faces(), FullMatrix<double>());
      std::vector<double> mass(n_nodes * n_surfaces, 0.);
      // The change of the weighted gap with the node's own position:
      // g_j = n_j . int psi_j (y - x_j) with y = x + t n the partner point
      // on the ray of the face, and int psi_j (x - x_j) = 0 (dual basis),
      // so g_j = int psi_j t (n_j . n), and t changes by -(m . dx) / (n . m)
      // when x moves by dx, m the surface's inward normal at y. Its
      // gradient is -int psi_j N_j m (n_j . n) / (n . m): the dual-weighted
      // normal of the surface, not of the secondary faces, which on a
      // coarse face over a curved tool differ by the angle between them.
      // Along that direction the linearised condition corrects the gap at
      // once (along the face normal only in part at each iteration), and
      // a frictionless force acts normal to the tool. Terms of the order of
      // the pointwise gap (the turn of the rays) are left out, and rays
      // that graze the surface count as if they met it at 75 degrees.
      std::vector<Tensor<1, dim>> gap_gradient(n_nodes);
      std::vector<Tensor<1, dim>> moment(n_nodes * n_surfaces);
      const std::vector<bool>     paired_faces = select_faces(integrated_rows);
      std::vector<bool>           node_covered(integrated);

      // The nearest hit of the ray x + t n on any surface (facing it, if
      // @p facing).
      const auto nearest_hit = [&](const Point<dim>     &x,
                                   const Tensor<1, dim> &n,
                                   const double          length_scale,
                                   const bool            facing) {
        std::pair<unsigned int, typename RigidSurface<dim>::RayHit> best{
          numbers::invalid_unsigned_int,
          {}};
        for (unsigned int i = 0; i < n_surfaces; ++i)
          {
            const auto hit = partners[i].surface->intersect_ray(x,
                                                                n,
                                                                search_distance,
                                                                length_scale);
            if (hit.found && (!facing || hit.normal * n < 0.) &&
                (best.first == numbers::invalid_unsigned_int ||
                 std::abs(hit.t) < std::abs(best.second.t)))
              best = {i, hit};
          }
        return best;
      };

      const unsigned int       degree = secondary->base_element().degree;
      const QGauss<dim - 1>    face_quadrature(degree + 3);
      const QIterated<dim - 1> pairing_quadrature(QGauss<1>(degree + 3), 4);
      std::vector<double>      N;

      for (unsigned int s = 0; s < secondary->n_faces(); ++s)
        {
          const SurfaceFace<dim> &face    = secondary->face(s);
          const unsigned int      n_shape = face.nodes.size();
          Vector<double>          De;
          compute_dual_basis(s, face_quadrature, axisymmetric, De);
          const FullMatrix<double> &A    = dual_coefficients[s];
          const double              size = secondary->face_size(s);
          for (unsigned int a = 0; a < n_shape; ++a)
            {
              rows[face.nodes[a]].weight += De(a);
              rows[face.nodes[a]].mesh_size =
                std::max(rows[face.nodes[a]].mesh_size, size);
            }
          if (!paired_faces[s] || nodal_tool_gap)
            continue;

          bool covered = true;
          for (unsigned int q = 0; q < pairing_quadrature.size(); ++q)
            {
              const Point<dim - 1> &xi = pairing_quadrature.point(q);
              secondary->shape_values(s, xi, N);
              Point<dim>     x;
              Tensor<1, dim> n;
              for (unsigned int a = 0; a < n_shape; ++a)
                {
                  x += N[a] * secondary->node(face.nodes[a]).position;
                  n += N[a] * secondary->node(face.nodes[a]).normal;
                }
              n /= n.norm();
              const auto [i, hit] = nearest_hit(x, n, size, true);
              if (i == numbers::invalid_unsigned_int)
                {
                  covered = false;
                  continue;
                }
              const double JxW = secondary->jacobian(s, xi) *
                                 pairing_quadrature.weight(q) * ring(x);
              for (unsigned int a = 0; a < n_shape; ++a)
                {
                  double psi = 0.;
                  for (unsigned int b = 0; b < n_shape; ++b)
                    psi += A(a, b) * N[b];
                  const unsigned int k = face.nodes[a] * n_surfaces + i;
                  mass[k] += psi * JxW;
                  moment[k] += psi * JxW * hit.point;
                  const Tensor<1, dim> m = -hit.normal;
                  gap_gradient[face.nodes[a]] +=
                    psi * N[a] * JxW *
                    (secondary->node(face.nodes[a]).normal * n) /
                    std::max(n * m, 0.25) * m;
                }
            }
          if (!covered)
            for (unsigned int a = 0; a < n_shape; ++a)
              node_covered[face.nodes[a]] = false;
        }

      double largest_weight = 0.;
      for (const auto &row : rows)
        largest_weight = std::max(largest_weight, row.weight);
      primary_nodes.resize(n_nodes * n_surfaces);
      for (unsigned int j = 0; j < n_nodes; ++j)
        {
          const SurfaceNode<dim> &node = secondary->node(j);
          MortarRow<dim>         &row  = rows[j];
          row.normal                   = node.normal;
          if (row.weight <= 1e-10 * largest_weight)
            row.weight = 0.;
          double total_mass = 0.;
          for (unsigned int i = 0; i < n_surfaces; ++i)
            total_mass += mass[j * n_surfaces + i];
          row.has_partner =
            node_covered[j] && row.weight > 0. && total_mass > 0.;
          // A partner node stores its point less the displacement of the
          // surface's reference node, so that reference position plus
          // displacement is where it is now.
          if (nodal_tool_gap)
            {
              for (unsigned int i = 0; i < n_surfaces; ++i)
                primary_nodes[j * n_surfaces + i] = {node.reference_position,
                                                     partners[i].dofs};
              row.has_partner = false;
              if (!integrated[j] || row.weight == 0.)
                continue;
              // The nearest surface that faces the node.
              unsigned int best = numbers::invalid_unsigned_int;
              typename RigidSurface<dim>::ClosestPoint nearest;
              for (unsigned int i = 0; i < n_surfaces; ++i)
                {
                  const auto cp =
                    partners[i].surface->closest_point(node.position);
                  if (std::abs(cp.distance) > search_distance ||
                      cp.normal * node.normal >= 0.)
                    continue;
                  if (best == numbers::invalid_unsigned_int ||
                      std::abs(cp.distance) < std::abs(nearest.distance))
                    {
                      best    = i;
                      nearest = cp;
                    }
                }
              if (best == numbers::invalid_unsigned_int)
                continue;
              const unsigned int k = j * n_surfaces + best;
              primary_nodes[k].reference_position =
                Point<dim>(nearest.point - partners[best].displacement);
              row.has_partner = true;
              row.primary_weights.emplace_back(k, row.weight);
              row.nodal_gap = nearest.distance;
              // The inward normal of the surface: the gradient of the
              // node's distance, within the symmetry planes it lies on.
              if (tool_normals)
                {
                  Tensor<1, dim> m = -nearest.normal;
                  for (unsigned int c = 0; c < dim; ++c)
                    if (node.on_symmetry_plane[c])
                      m[c] = 0.;
                  if (m * node.normal > std::sqrt(0.5) * m.norm())
                    row.normal = m / m.norm();
                }
              row.reference_weighted_gap =
                row.weight *
                (row.normal * (primary_nodes[k].reference_position -
                               node.reference_position));
              continue;
            }
          Tensor<1, dim> gap;
          for (unsigned int i = 0; i < n_surfaces; ++i)
            {
              const unsigned int k = j * n_surfaces + i;
              primary_nodes[k] = {node.reference_position, partners[i].dofs};
              if (mass[k] == 0. || !row.has_partner)
                continue;
              primary_nodes[k].reference_position =
                Point<dim>(moment[k] / mass[k] - partners[i].displacement);
              // The surfaces cover the node's faces: sum_k M_jk = D_j
              // holds by definition of the partner nodes.
              const double M = n_surfaces == 1 ?
                                 row.weight :
                                 row.weight * mass[k] / total_mass;
              if (std::abs(M) <= 1e-14 * row.weight)
                continue;
              row.primary_weights.emplace_back(k, M);
              gap += M * (primary_nodes[k].reference_position -
                          node.reference_position);
            }
          if (row.has_partner)
            {
              const auto [i, hit] =
                nearest_hit(node.position, node.normal, row.mesh_size, false);
              if (i != numbers::invalid_unsigned_int)
                row.nodal_gap = hit.t;
            }
          // The row's normal is the direction in which its weighted gap
          // changes with the node's own displacement (see gap_gradient),
          // within the symmetry planes the node lies on; the node's normal
          // where that direction is ill-defined (more than 45 degrees off).
          if (row.has_partner && tool_normals)
            {
              Tensor<1, dim> m = gap_gradient[j];
              for (unsigned int c = 0; c < dim; ++c)
                if (node.on_symmetry_plane[c])
                  m[c] = 0.;
              if (m * node.normal > std::sqrt(0.5) * m.norm())
                row.normal = m / m.norm();
            }
          row.reference_weighted_gap = row.has_partner ? row.normal * gap : 0.;
        }
    }



    // Segment-based integration in 3D (after Puso and Laursen 2004 and
    // Popp et al. 2010). Everything is projected along the normal n0 of
    // secondary face s onto the auxiliary plane through its centre. The
    // face is split into k x k sub-squares of its parameter domain (k = 1
    // for Q1 faces, 4 for Q2 faces, whose edges may be curved), each
    // represented in the plane by the quadrilateral Q through its corners;
    // each candidate primary face by the polygon through its corners and,
    // if Q2, through points along its edges. Neighbouring faces share
    // these points, so both families tile the plane without gaps. The
    // primary polygon is clipped against each Q; the overlap, split into
    // triangles about its centroid, carries Gauss points y, which map to
    // the sub-square through the inverse of Q's bilinear map and from there
    // to face s; each secondary point maps to the primary face along the
    // interpolated normal. Returns the fraction of the planar area of the
    // Q covered by primary polygons (exact polygon areas, independent of
    // quadrature). For plane faces with straight edges (parallelograms)
    // the integration is exact.
    template <int dim>
    template <typename AddPoint>
    double
    MortarCoupling<dim>::integrate_3d_segments(
      const unsigned int                                s,
      const ContactSearch<dim>                         &search,
      const double                                      search_distance,
      const std::vector<std::array<Point<dim - 1>, 2>> &parameter_boxes,
      const AddPoint                                   &add_point) const
    {
      if constexpr (dim == 3)
        {
          const Point<dim - 1> centre(0.5, 0.5);
          const Point<dim>     x0 = secondary->point(s, centre);
          const Tensor<1, dim> n0 = secondary->unit_normal(s, centre);
          Tensor<1, dim>       axis;
          axis[std::abs(n0[0]) < 0.6 ? 0 : 1] = 1.;
          Tensor<1, dim> e1                   = cross_product_3d(n0, axis);
          e1 /= e1.norm();
          const Tensor<1, dim> e2       = cross_product_3d(n0, e1);
          const auto           to_plane = [&](const Point<dim> &x) {
            const Tensor<1, dim> d = x - x0;
            return Point<2>(d * e1, d * e2);
          };
          const std::array<Point<2>, 4> unit_corners = {{Point<2>(0., 0.),
                                                         Point<2>(1., 0.),
                                                         Point<2>(1., 1.),
                                                         Point<2>(0., 1.)}};

          // Primary polygons in the plane, counterclockwise.
          const unsigned int n_primary_segments =
            primary->base_element().degree > 1 ? 4 : 1;
          std::vector<std::pair<unsigned int, std::vector<Point<2>>>>
            primary_polygons;
          for (const unsigned int m :
               search.faces_near(secondary->bounding_box(s, search_distance)))
            {
              if (primary->unit_normal(m, centre) * n0 >= 0.)
                continue;
              // Along each edge of the parameter box: its first corner,
              // then the points at k / n_primary_segments of the face's
              // own edge that lie inside the box's edge. Where the box is
              // extended past an edge, the points along the adjacent
              // edges stay where the neighbouring face has them, so that
              // the two polygons still share their common points.
              const auto           &box = parameter_boxes[m];
              std::vector<Point<2>> polygon;
              for (unsigned int e = 0; e < 4; ++e)
                {
                  const Point<2>    &a      = unit_corners[e];
                  const Point<2>    &b      = unit_corners[(e + 1) % 4];
                  const unsigned int along  = e % 2 == 0 ? 0 : 1;
                  const unsigned int across = 1 - along;
                  const auto         bound  = [&](const unsigned int d,
                                         const double       unit) {
                    return unit == 0. ? box[0][d] : box[1][d];
                  };
                  Point<dim - 1> eta;
                  eta[across] = bound(across, a[across]);
                  eta[along]  = bound(along, a[along]);
                  polygon.push_back(to_plane(primary->point(m, eta)));
                  for (unsigned int k = 0; k <= n_primary_segments; ++k)
                    {
                      const double t =
                        a[along] + (b[along] - a[along]) * k /
                                     static_cast<double>(n_primary_segments);
                      if (t == bound(along, a[along]) ||
                          t == bound(along, b[along]))
                        continue;
                      eta[along] = t;
                      polygon.push_back(to_plane(primary->point(m, eta)));
                    }
                }
              if (twice_signed_area(polygon) < 0.)
                std::reverse(polygon.begin(), polygon.end());
              primary_polygons.emplace_back(m, polygon);
            }

          const unsigned int k_sub =
            secondary->base_element().degree > 1 ? 4 : 1;
          // Face integrands are rational in the plane unless the faces are
          // parallelograms, so the rule goes well beyond the polynomial
          // degree (contact_patch_test_03, measured before the rows of M
          // were scaled to sum to D: uniform pressure to 8e-7 with Q1 on
          // kite-shaped faces with 6 x 6 points, 3e-5 with 5 x 5, 5e-2
          // with a rule of degree + 2 points). For Q2 the sub-squares'
          // straight edges dominate (3e-5 on arcs with 5 x 5 points or
          // more, with or without the scaling), and 5 x 5 points integrate
          // the products of Q2 shape functions on parallelograms exactly.
          const Quadrature<2> triangle_quadrature = collapsed_triangle_rule(
            std::max(secondary->base_element().degree,
                     primary->base_element().degree) > 1 ?
              5 :
              6);
          double sub_area = 0., covered_area = 0.;
          for (unsigned int i = 0; i < k_sub; ++i)
            for (unsigned int j = 0; j < k_sub; ++j)
              {
                // The sub-square's corners, in the parameter domain of s
                // and in the plane.
                std::array<Point<2>, 4> eta_corner, q;
                for (unsigned int c = 0; c < 4; ++c)
                  {
                    eta_corner[c] = Point<2>((i + unit_corners[c][0]) / k_sub,
                                             (j + unit_corners[c][1]) / k_sub);
                    q[c] = to_plane(secondary->point(s, eta_corner[c]));
                  }
                std::vector<Point<2>> clip(q.begin(), q.end());
                const bool            reversed = twice_signed_area(clip) < 0.;
                if (reversed)
                  std::reverse(clip.begin(), clip.end());
                sub_area += 0.5 * std::abs(twice_signed_area(clip));
                // Q's bilinear map (u, v) -> y, lexicographic corners.
                const Point<2> &y00 = q[0], &y10 = q[1], &y11 = q[2],
                               &y01 = q[3];
                const auto bilinear = [&](const Point<2> &uv) {
                  const double u = uv[0], v = uv[1];
                  return Point<2>((1 - u) * (1 - v) * y00 + u * (1 - v) * y10 +
                                  u * v * y11 + (1 - u) * v * y01);
                };
                const auto bilinear_jacobian = [&](const Point<2> &uv) {
                  const double   u = uv[0], v = uv[1];
                  const Point<2> du((1 - v) * (y10 - y00) + v * (y11 - y01));
                  const Point<2> dv((1 - u) * (y01 - y00) + u * (y11 - y10));
                  return Tensor<2, 2>({{du[0], dv[0]}, {du[1], dv[1]}});
                };
                const auto inverse = [&](const Point<2> &y) {
                  Point<2> uv(0.5, 0.5);
                  for (unsigned int it = 0; it < 20; ++it)
                    {
                      const Tensor<1, 2> r  = bilinear(uv) - y;
                      const Tensor<1, 2> du = invert(bilinear_jacobian(uv)) * r;
                      uv -= du;
                      if (du.norm() < 1e-14)
                        break;
                    }
                  return uv;
                };

                for (const auto &[m, polygon] : primary_polygons)
                  {
                    const std::vector<Point<2>> clipped =
                      clip_polygon(polygon, clip);
                    if (clipped.size() < 3)
                      continue;
                    const double area = 0.5 * twice_signed_area(clipped);
                    if (area <= 0.)
                      continue;
                    covered_area += area;

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
                        for (unsigned int g = 0; g < triangle_quadrature.size();
                             ++g)
                          {
                            const Point<2> &r = triangle_quadrature.point(g);
                            const Point<2>  y =
                              c + r[0] * (v1 - c) + r[1] * (v2 - c);
                            const Point<2>       uv = inverse(y);
                            const Point<dim - 1> xi((i + uv[0]) / k_sub,
                                                    (j + uv[1]) / k_sub);
                            const double         J_Q =
                              std::abs(determinant(bilinear_jacobian(uv)));
                            const double JxW = triangle_quadrature.weight(g) *
                                               det *
                                               secondary->jacobian(s, xi) /
                                               (J_Q * k_sub * k_sub);

                            // The secondary point, the interpolated
                            // normal, and the partner on face m (the
                            // polygon decides what belongs to m; the
                            // partner of a point near a curved edge may
                            // fall a little outside the face and is
                            // clamped onto it).
                            const auto &nodes = secondary->face(s).nodes;
                            std::vector<double> N;
                            secondary->shape_values(s, xi, N);
                            Point<dim>     x;
                            Tensor<1, dim> n;
                            for (unsigned int a = 0; a < nodes.size(); ++a)
                              {
                                x += N[a] * secondary->node(nodes[a]).position;
                                n += N[a] * secondary->node(nodes[a]).normal;
                              }
                            n /= n.norm();
                            const auto on_primary =
                              ContactSearch<dim>::project_along(*primary,
                                                                m,
                                                                x,
                                                                n);
                            const auto &box    = parameter_boxes[m];
                            bool        inside = on_primary.converged;
                            for (unsigned int d = 0; d < dim - 1; ++d)
                              inside = inside &&
                                       on_primary.eta[d] >= box[0][d] - 0.05 &&
                                       on_primary.eta[d] <= box[1][d] + 0.05;
                            if (!inside ||
                                std::abs(on_primary.distance) > search_distance)
                              continue;
                            Point<dim - 1> eta_m = on_primary.eta;
                            for (unsigned int d = 0; d < dim - 1; ++d)
                              eta_m[d] =
                                std::min(box[1][d],
                                         std::max(box[0][d], eta_m[d]));
                            add_point(xi, JxW, m, eta_m);
                          }
                      }
                  }
              }
          return sub_area > 0. ? covered_area / sub_area : 0.;
        }
      else
        {
          (void)s;
          (void)search;
          (void)search_distance;
          (void)parameter_boxes;
          (void)add_point;
          return 0.;
        }
    }



    template <int dim>
    void
    MortarCoupling<dim>::set_tool_normals(const bool use)
    {
      tool_normals = use;
    }



    template <int dim>
    void
    MortarCoupling<dim>::set_nodal_tool_gap(const bool use)
    {
      nodal_tool_gap = use;
    }



    template <int dim>
    void
    MortarCoupling<dim>::set_free_edge_extension(const double fraction)
    {
      AssertThrow(fraction >= 0. && fraction < 0.5,
                  ExcMessage("The free-edge extension must lie in [0, 0.5)."));
      free_edge_extension = fraction;
    }



    template <int dim>
    std::vector<std::array<Point<dim - 1>, 2>>
    MortarCoupling<dim>::primary_parameter_boxes() const
    {
      const unsigned int                         n_faces = primary->n_faces();
      std::vector<std::array<Point<dim - 1>, 2>> boxes(n_faces);
      for (auto &box : boxes)
        for (unsigned int d = 0; d < dim - 1; ++d)
          box[1][d] = 1.;
      if (free_edge_extension == 0. && dim == 2)
        return boxes;

      // The node at each corner of each face's parameter box, the corners
      // counterclockwise from the origin; an edge of a face runs from
      // corner e to corner e + 1 (in 2D an edge is the end node e).
      constexpr unsigned int n_corners = dim == 2 ? 2 : 4;
      const auto             corner    = [](const unsigned int c) {
        Point<dim - 1> eta;
        if constexpr (dim == 2)
          eta[0] = c;
        else
          {
            eta[0] = (c == 1 || c == 2) ? 1. : 0.;
            eta[1] = c >= 2 ? 1. : 0.;
          }
        return eta;
      };
      const auto edge_key = [](const std::array<unsigned int, n_corners> &c,
                               const unsigned int                         e) {
        if constexpr (dim == 2)
          return std::make_pair(c[e], c[e]);
        else
          return std::minmax(c[e], c[(e + 1) % n_corners]);
      };
      std::vector<std::array<unsigned int, n_corners>> corner_nodes(n_faces);
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> n_sharing;
      std::vector<double>                                           N;
      for (unsigned int m = 0; m < n_faces; ++m)
        {
          for (unsigned int c = 0; c < n_corners; ++c)
            {
              primary->shape_values(m, corner(c), N);
              const auto a = std::max_element(N.begin(), N.end()) - N.begin();
              corner_nodes[m][c] = primary->face(m).nodes[a];
            }
          for (unsigned int e = 0; e < n_corners; ++e)
            ++n_sharing[edge_key(corner_nodes[m], e)];
        }

      // The symmetry planes of the secondary surface: per axis, the
      // coordinates of its nodes on a plane normal to it.
      std::array<std::vector<double>, dim> secondary_planes;
      for (unsigned int j = 0; j < secondary->n_nodes(); ++j)
        for (unsigned int d = 0; d < dim; ++d)
          if (secondary->node(j).on_symmetry_plane[d])
            secondary_planes[d].push_back(
              secondary->node(j).reference_position[d]);

      // An edge of face m on a symmetry plane of both surfaces: its corner
      // nodes lie on a plane normal to the same axis, on which secondary
      // nodes lie too. (A primary body merely held on a plane that the
      // secondary surface crosses is not mirrored there.)
      const auto on_symmetry_plane = [&](const unsigned int m,
                                         const unsigned int e) {
        if constexpr (dim == 2)
          return false;
        const SurfaceNode<dim> &a = primary->node(corner_nodes[m][e]);
        const SurfaceNode<dim> &b =
          primary->node(corner_nodes[m][(e + 1) % n_corners]);
        const double tolerance = 1e-8 * primary->face_size(m);
        for (unsigned int d = 0; d < dim; ++d)
          if (a.on_symmetry_plane[d] && b.on_symmetry_plane[d] &&
              std::any_of(secondary_planes[d].begin(),
                          secondary_planes[d].end(),
                          [&](const double x) {
                            return std::abs(x - a.reference_position[d]) <=
                                   tolerance;
                          }))
            return true;
        return false;
      };

      // Which bound an edge moves: 2D: the ends eta = 0, 1; 3D: the edges
      // eta_1 = 0, eta_0 = 1, eta_1 = 1, eta_0 = 0.
      for (unsigned int m = 0; m < n_faces; ++m)
        for (unsigned int e = 0; e < n_corners; ++e)
          if (n_sharing[edge_key(corner_nodes[m], e)] == 1)
            {
              const double f =
                on_symmetry_plane(m, e) ?
                  std::max(free_edge_extension, symmetry_edge_extension) :
                  free_edge_extension;
              if (f == 0.)
                continue;
              if constexpr (dim == 2)
                (e == 0 ? boxes[m][0][0] : boxes[m][1][0]) =
                  e == 0 ? -f : 1. + f;
              else
                {
                  const unsigned int direction       = e % 2 == 0 ? 1 : 0;
                  const bool         upper           = e == 1 || e == 2;
                  boxes[m][upper ? 1 : 0][direction] = upper ? 1. + f : -f;
                }
            }
      return boxes;
    }



    template <int dim>
    std::vector<std::vector<std::pair<unsigned int, double>>>
    MortarCoupling<dim>::hanging_parents(
      const ContactSurface<dim>       &secondary,
      const AffineConstraints<double> &constraints)
    {
      const unsigned int n = secondary.n_nodes();

      // Secondary node and component of each secondary DoF.
      std::map<types::global_dof_index, std::pair<unsigned int, unsigned int>>
        node_of_dof;
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int c = 0; c < dim; ++c)
          node_of_dof[secondary.node(j).dofs[c]] = {j, c};

      std::vector<std::vector<std::pair<unsigned int, double>>> parents(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          const auto &dofs = secondary.node(j).dofs;
          if (!std::all_of(dofs.begin(), dofs.end(), [&](const auto dof) {
                return constraints.is_constrained(dof);
              }))
            continue;
          for (unsigned int c = 0; c < dim && parents[j].empty(); ++c)
            {
              const auto *entries = constraints.get_constraint_entries(dofs[c]);
              if (entries == nullptr || entries->empty() ||
                  constraints.is_inhomogeneously_constrained(dofs[c]))
                continue;
              std::vector<std::pair<unsigned int, double>> candidate;
              double                                       sum = 0.;
              for (const auto &[dof, w] : *entries)
                {
                  const auto it = node_of_dof.find(dof);
                  if (it == node_of_dof.end() || it->second.second != c)
                    break;
                  candidate.emplace_back(it->second.first, w);
                  sum += w;
                }
              if (candidate.size() == entries->size() &&
                  std::abs(sum - 1.) < 1e-10)
                parents[j] = candidate;
            }
        }
      return parents;
    }



    // A parent's condensed row combines its own row, those of the hanging
    // nodes it takes over and those of their other parents
    // (condense_hanging_nodes()).
    template <int dim>
    std::vector<bool>
    MortarCoupling<dim>::rows_to_integrate(
      const ContactSurface<dim>       &secondary,
      const AffineConstraints<double> &constraints,
      const std::vector<bool>         &needed)
    {
      AssertDimension(needed.size(), secondary.n_nodes());
      std::vector<bool> rows    = needed;
      const auto        parents = hanging_parents(secondary, constraints);
      for (unsigned int h = 0; h < parents.size(); ++h)
        if (std::any_of(parents[h].begin(),
                        parents[h].end(),
                        [&](const auto &p) { return needed[p.first]; }))
          {
            rows[h] = true;
            for (const auto &p : parents[h])
              rows[p.first] = true;
          }
      return rows;
    }



    template <int dim>
    std::vector<bool>
    MortarCoupling<dim>::select_faces(const std::vector<bool> &integrated_rows)
    {
      const unsigned int n_nodes = secondary->n_nodes();
      AssertThrow(integrated_rows.empty() || integrated_rows.size() == n_nodes,
                  ExcDimensionMismatch(integrated_rows.size(), n_nodes));
      integrated = integrated_rows.empty() ? std::vector<bool>(n_nodes, true) :
                                             integrated_rows;
      std::vector<bool> faces(secondary->n_faces(), false);
      for (unsigned int s = 0; s < secondary->n_faces(); ++s)
        for (const unsigned int j : secondary->face(s).nodes)
          faces[s] = faces[s] || integrated[j];
      return faces;
    }



    template <int dim>
    bool
    MortarCoupling<dim>::is_integrated(const unsigned int j) const
    {
      AssertIndexRange(j, integrated.size());
      return integrated[j];
    }



    template <int dim>
    unsigned int
    MortarCoupling<dim>::condense_hanging_nodes(
      const AffineConstraints<double> &constraints)
    {
      Assert(secondary != nullptr, ExcMessage("Call reinit() first."));
      const auto parents = hanging_parents(*secondary, constraints);
      std::vector<unsigned int> hanging;
      for (unsigned int j = 0; j < parents.size(); ++j)
        if (!parents[j].empty())
          hanging.push_back(j);
      if (hanging.empty())
        return 0;

      // A parent without measure has no dual function to correct with:
      // its hanging nodes keep their rows (and take no condition).
      std::vector<unsigned int> condensed;
      for (const unsigned int h : hanging)
        if (std::all_of(parents[h].begin(),
                        parents[h].end(),
                        [this](const auto &p) {
                          return rows[p.first].weight > 0.;
                        }))
          condensed.push_back(h);

      // Each parent a's new row, as a combination of the original rows v:
      // psi''_a = (Lambda_a / D_a) psi_a + sum_h w_ha psi_h
      //           - sum_h w_ha D_h sum_q w_hq psi_q / D_q.
      std::map<unsigned int, std::map<unsigned int, double>> combination;
      for (const unsigned int h : condensed)
        for (const auto &[a, w] : parents[h])
          {
            const auto [entry, is_new] = combination.try_emplace(a);
            auto &c                    = entry->second;
            if (is_new)
              c[a] = 1.;
            c[a] += w * rows[h].weight / rows[a].weight;
            c[h] += w;
            for (const auto &[q, v] : parents[h])
              c[q] -= w * v * rows[h].weight / rows[q].weight;
          }

      const std::vector<MortarRow<dim>> original = rows;
      for (const auto &[a, c] : combination)
        {
          MortarRow<dim>                &row         = rows[a];
          double                         weight      = 0.;
          bool                           has_partner = true;
          Tensor<1, dim>                 gap;
          std::map<unsigned int, double> merged;
          for (const auto &[v, coefficient] : c)
            {
              const MortarRow<dim> &source = original[v];
              weight += coefficient * source.weight;
              has_partner = has_partner && source.has_partner;
              // sum_k M_vk = D_v on a row with a partner: the gap of
              // source row v from differences, as in reinit().
              const Point<dim> &X_v = secondary->node(v).reference_position;
              for (const auto &[k, value] : source.primary_weights)
                {
                  merged[k] += coefficient * value;
                  gap += coefficient * value *
                         (primary_nodes[k].reference_position - X_v);
                }
              if (!source.has_partner)
                gap -= coefficient * source.weight * X_v;
            }
          // The secondary terms sum to Lambda_a u_a for every displacement
          // of the constrained space; weight is Lambda_a.
          row.weight      = weight;
          row.has_partner = has_partner && weight > 0.;
          row.primary_weights.clear();
          if (row.has_partner)
            for (const auto &[k, value] : merged)
              if (std::abs(value) > 1e-14 * weight)
                row.primary_weights.emplace_back(k, value);
          row.reference_weighted_gap = row.normal * gap;
        }

      for (const unsigned int h : condensed)
        {
          MortarRow<dim> &row = rows[h];
          row.weight          = 0.;
          row.has_partner     = false;
          row.primary_weights.clear();
          row.reference_weighted_gap = 0.;
          row.nodal_gap              = std::numeric_limits<double>::infinity();
        }
      return condensed.size();
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
      AssertThrow(primary != nullptr,
                  ExcMessage("The primary side is a rigid surface."));
      return *primary;
    }



    template <int dim>
    bool
    MortarCoupling<dim>::primary_is_rigid() const
    {
      return primary == nullptr;
    }



    template <int dim>
    unsigned int
    MortarCoupling<dim>::n_primary_nodes() const
    {
      return primary_nodes.size();
    }



    template <int dim>
    const PrimaryNode<dim> &
    MortarCoupling<dim>::primary_node(const unsigned int k) const
    {
      return primary_nodes[k];
    }



    template <int dim>
    template <typename VectorType>
    double
    MortarCoupling<dim>::weighted_gap(const unsigned int j,
                                      const VectorType  &u) const
    {
      Assert(integrated[j],
             ExcMessage("Row " + std::to_string(j) +
                        " was not integrated on this rank."));
      const MortarRow<dim>   &r    = rows[j];
      const SurfaceNode<dim> &node = secondary->node(j);
      Tensor<1, dim>          d;
      for (const auto &[k, M] : r.primary_weights)
        for (unsigned int c = 0; c < dim; ++c)
          d[c] += M * u(primary_nodes[k].dofs[c]);
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
      Assert(integrated[j],
             ExcMessage("Row " + std::to_string(j) +
                        " was not integrated on this rank."));
      const MortarRow<dim>   &r    = rows[j];
      const SurfaceNode<dim> &node = secondary->node(j);
      Tensor<1, dim>          d;
      for (const auto &[k, M] : r.primary_weights)
        for (unsigned int c = 0; c < dim; ++c)
          d[c] += M * u(primary_nodes[k].dofs[c]);
      if (r.weight == 0.)
        return d;
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
