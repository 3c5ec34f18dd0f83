#include <common/contact/contact_search.h>

#include <deal.II/base/tensor.h>

// The equality of points, which rtree::remove() needs.
#include <boost/geometry/algorithms/equals.hpp>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    bool
    Projection<dim>::inside(const double tolerance) const
    {
      for (unsigned int k = 0; k < dim - 1; ++k)
        if (eta[k] < -tolerance || eta[k] > 1. + tolerance)
          return false;
      return converged;
    }



    template <int dim>
    ContactSearch<dim>::ContactSearch(const ContactSurface<dim> &surface,
                                      const double               margin)
      : surface(surface)
      , margin(margin)
    {
      update();
    }



    template <int dim>
    void
    ContactSearch<dim>::update()
    {
      boxes.clear();
      for (unsigned int f = 0; f < surface.n_faces(); ++f)
        boxes.emplace_back(surface.bounding_box(f, margin), f);
      tree = pack_rtree(boxes);
    }



    template <int dim>
    std::vector<unsigned int>
    ContactSearch<dim>::faces_near(const BoundingBox<dim> &box) const
    {
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      tree.query(boost::geometry::index::intersects(box),
                 std::back_inserter(hits));
      std::vector<unsigned int> result;
      for (const auto &hit : hits)
        result.push_back(hit.second);
      std::sort(result.begin(), result.end());
      return result;
    }



    namespace
    {
      /**
       * Newton's method for F(eta, t) = x(eta) + t v(eta) - y = 0, with
       * v = d (constant) or the interpolated normal field. The unknowns are
       * (eta_0, ..., eta_{dim-2}, t).
       */
      template <int dim, typename Evaluate>
      Projection<dim>
      solve_projection(const Evaluate &evaluate, const Point<dim> &y)
      {
        Projection<dim> result;
        Point<dim - 1>  eta;
        for (unsigned int k = 0; k < dim - 1; ++k)
          eta[k] = 0.5;
        double t = 0.;
        for (unsigned int it = 0; it < 30; ++it)
          {
            Point<dim>                          x;
            Tensor<1, dim>                      v;
            std::array<Tensor<1, dim>, dim - 1> dx, dv;
            evaluate(eta, x, dx, v, dv);
            const Tensor<1, dim> F = x + t * v - y;
            Tensor<2, dim>       J;
            for (unsigned int k = 0; k < dim - 1; ++k)
              for (unsigned int i = 0; i < dim; ++i)
                J[i][k] = dx[k][i] + t * dv[k][i];
            for (unsigned int i = 0; i < dim; ++i)
              J[i][dim - 1] = v[i];
            const double det = determinant(J);
            if (std::abs(det) < 1e-300)
              return result;
            const Tensor<1, dim> delta = invert(J) * F;
            for (unsigned int k = 0; k < dim - 1; ++k)
              eta[k] -= delta[k];
            t -= delta[dim - 1];
            // A face is a polynomial patch: far outside [0,1] the
            // projection is meaningless, so give up early.
            for (unsigned int k = 0; k < dim - 1; ++k)
              if (std::abs(eta[k]) > 10.)
                return result;
            double step = 0;
            for (unsigned int k = 0; k < dim - 1; ++k)
              step = std::max(step, std::abs(delta[k]));
            // Quadratic convergence: after a step below 1e-10 the error
            // is at round-off, which for small faces far from the origin
            // (0.05 mm faces at 200 mm) is itself about 1e-12 in eta.
            if (step < 1e-10)
              {
                evaluate(eta, x, dx, v, dv);
                result.converged = true;
                result.eta       = eta;
                result.distance  = t;
                result.point     = x;
                return result;
              }
          }
        return result;
      }
    } // namespace



    template <int dim>
    Projection<dim>
    ContactSearch<dim>::project_along(const ContactSurface<dim> &surface,
                                      const unsigned int         f,
                                      const Point<dim>          &x,
                                      const Tensor<1, dim>      &direction)
    {
      // y(eta) - t d = x: the surface point plays the role of x(eta) and
      // -d the role of v.
      const auto evaluate = [&](const Point<dim - 1>                &eta,
                                Point<dim>                          &p,
                                std::array<Tensor<1, dim>, dim - 1> &dp,
                                Tensor<1, dim>                      &v,
                                std::array<Tensor<1, dim>, dim - 1> &dv) {
        p = surface.point_and_tangents(f, eta, dp);
        v = -direction;
        for (auto &d : dv)
          d = 0;
      };
      Projection<dim> result = solve_projection<dim>(evaluate, x);
      return result;
    }



    template <int dim>
    Projection<dim>
    ContactSearch<dim>::project_along_normal_field(
      const ContactSurface<dim> &surface,
      const unsigned int         f,
      const Point<dim>          &y)
    {
      const SurfaceFace<dim> &face = surface.face(f);
      const auto              evaluate = [&](const Point<dim - 1>                &eta,
                                Point<dim>                          &p,
                                std::array<Tensor<1, dim>, dim - 1> &dp,
                                Tensor<1, dim>                      &v,
                                std::array<Tensor<1, dim>, dim - 1> &dv) {
        std::vector<double>             N;
        std::vector<Tensor<1, dim - 1>> dN;
        surface.shape_values_and_derivatives(f, eta, N, dN);
        p = Point<dim>();
        v = 0;
        for (auto &d : dp)
          d = 0;
        for (auto &d : dv)
          d = 0;
        for (unsigned int a = 0; a < N.size(); ++a)
          {
            const SurfaceNode<dim> &node = surface.node(face.nodes[a]);
            p += N[a] * node.position;
            v += N[a] * node.normal;
            for (unsigned int k = 0; k < dim - 1; ++k)
              {
                dp[k] += dN[a][k] * node.position;
                dv[k] += dN[a][k] * node.normal;
              }
          }
      };
      return solve_projection<dim>(evaluate, y);
    }

    template <int dim>
    NearestPoints<dim>::NearestPoints(const std::vector<Point<dim>>   &points,
                                      const std::vector<unsigned int> &indices)
      : points(points)
    {
      std::vector<std::pair<Point<dim>, unsigned int>> entries;
      entries.reserve(indices.size());
      for (const unsigned int i : indices)
        entries.emplace_back(points[i], i);
      tree = pack_rtree(entries);
    }



    template <int dim>
    unsigned int
    NearestPoints<dim>::nearest(const Point<dim>  &x,
                                const unsigned int excluded) const
    {
      // Two candidates, in case one is the excluded index.
      std::vector<std::pair<Point<dim>, unsigned int>> hits;
      tree.query(boost::geometry::index::nearest(x, 2),
                 std::back_inserter(hits));
      unsigned int result   = numbers::invalid_unsigned_int;
      double       distance = 0.;
      for (const auto &[point, i] : hits)
        if (i != excluded && (result == numbers::invalid_unsigned_int ||
                              x.distance(point) < distance))
          {
            result   = i;
            distance = x.distance(point);
          }
      return result;
    }



    template <int dim>
    void
    NearestPoints<dim>::remove(const unsigned int i)
    {
      const std::size_t n_removed = tree.remove(std::make_pair(points[i], i));
      (void)n_removed;
      Assert(n_removed == 1, ExcInternalError());
    }


    template struct Projection<2>;
    template struct Projection<3>;
    template class ContactSearch<2>;
    template class ContactSearch<3>;
    template class NearestPoints<2>;
    template class NearestPoints<3>;
  } // namespace Contact
} // namespace Common
