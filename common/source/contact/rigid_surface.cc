#include <common/contact/rigid_surface.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    void
    RigidProfile::add_line(const Point<2> &start, const Point<2> &end)
    {
      AssertThrow(start.distance(end) > 0.,
                  ExcMessage("Rigid profile: a line of zero length."));
      Piece piece;
      piece.is_arc = false;
      piece.start  = start;
      piece.end    = end;
      pieces.push_back(piece);
    }



    void
    RigidProfile::add_arc(const Point<2> &centre,
                          const double    radius,
                          const double    start_angle,
                          const double    end_angle)
    {
      AssertThrow(radius > 0. && start_angle != end_angle,
                  ExcMessage("Rigid profile: an arc needs a positive radius "
                             "and two different angles."));
      Piece piece;
      piece.is_arc      = true;
      piece.centre      = centre;
      piece.radius      = radius;
      piece.start_angle = start_angle;
      piece.end_angle   = end_angle;
      piece.start       = centre + radius * Point<2>(std::cos(start_angle),
                                               std::sin(start_angle));
      piece.end =
        centre + radius * Point<2>(std::cos(end_angle), std::sin(end_angle));
      pieces.push_back(piece);
    }



    RigidProfile::ClosestPoint
    RigidProfile::closest_point(const Point<2> &x) const
    {
      AssertThrow(!pieces.empty(), ExcMessage("Rigid profile: no segments."));
      ClosestPoint best;
      double       best_distance = std::numeric_limits<double>::infinity();
      // Whether the closest point is an end of its piece, where x lies
      // beyond the piece (a convex corner).
      bool best_at_end = false;
      for (const auto &piece : pieces)
        {
          Point<2>     p;
          Tensor<1, 2> tangent;
          bool         at_end = false;
          if (!piece.is_arc)
            {
              const Tensor<1, 2> e      = piece.end - piece.start;
              const double       length = e.norm();
              const double s_raw = (x - piece.start) * e / (length * length);
              const double s     = std::clamp(s_raw, 0., 1.);
              at_end             = s != s_raw;
              p                  = piece.start + s * e;
              tangent            = e / length;
            }
          else
            {
              // The angle of x about the centre, in the arc's range (which
              // may run either way), clamped to its nearer end.
              const double lo = std::min(piece.start_angle, piece.end_angle);
              const double hi = std::max(piece.start_angle, piece.end_angle);
              double       angle =
                std::atan2(x[1] - piece.centre[1], x[0] - piece.centre[0]);
              const double mid = 0.5 * (lo + hi);
              while (angle < mid - numbers::PI)
                angle += 2. * numbers::PI;
              while (angle > mid + numbers::PI)
                angle -= 2. * numbers::PI;
              at_end = angle < lo || angle > hi;
              angle  = std::clamp(angle, lo, hi);
              const Tensor<1, 2> radial({std::cos(angle), std::sin(angle)});
              p = piece.centre + piece.radius * radial;
              // Counterclockwise tangent, reversed for a clockwise arc.
              tangent = Tensor<1, 2>({-radial[1], radial[0]}) *
                        (piece.end_angle > piece.start_angle ? 1. : -1.);
            }
          const double d = x.distance(p);
          if (d < best_distance)
            {
              best_distance = d;
              best_at_end   = at_end;
              best.point    = p;
              best.normal   = Tensor<1, 2>({tangent[1], -tangent[0]});
            }
        }
      // The sign from the side of the closest piece; at a point exactly on
      // the profile the distance is zero either way.
      best.distance = (x - best.point) * best.normal;
      // Beyond a convex corner the normal is the direction from the corner
      // to x and the distance the distance to the corner, which keeps the
      // distance function smooth. Elsewhere it is the piece's own normal at
      // the point: x - p has that direction too, but for a point near the
      // profile (a closed contact node) its rounding error would turn the
      // normal by up to 1e-16 |x| / |x - p|.
      if (best_at_end && best_distance > 1e-12 * (1. + x.norm()))
        {
          const Tensor<1, 2> direction = (x - best.point) / best_distance;
          best.normal =
            best.distance >= 0. ? direction : Tensor<1, 2>(-direction);
          best.distance = (x - best.point) * best.normal;
        }
      return best;
    }



    unsigned int
    RigidProfile::n_pieces() const
    {
      return pieces.size();
    }



    std::string
    RigidProfile::description() const
    {
      unsigned int n_arcs = 0;
      for (const auto &piece : pieces)
        n_arcs += piece.is_arc;
      const unsigned int n_lines = pieces.size() - n_arcs;
      return std::to_string(n_lines) + (n_lines == 1 ? " line" : " lines") +
             " and " + std::to_string(n_arcs) +
             (n_arcs == 1 ? " arc" : " arcs");
    }



    template <int dim>
    RigidSurface<dim>::RigidSurface(const RigidProfile &profile,
                                    const ProfileSweep  sweep)
      : profile(profile)
      , sweep(sweep)
      , placement_rotation(Tensor<2, dim>(unit_symmetric_tensor<dim>()))
    {
      AssertThrow(profile.n_pieces() > 0,
                  ExcMessage("Rigid surface: the profile is empty."));
    }



    template <int dim>
    void
    RigidSurface<dim>::set_placement(const Tensor<1, dim> &translation,
                                     const double          angle,
                                     const Point<dim>     &centre)
    {
      placement_translation    = translation;
      placement_centre         = centre;
      placement_rotation       = Tensor<2, dim>(unit_symmetric_tensor<dim>());
      placement_rotation[0][0] = std::cos(angle);
      placement_rotation[0][1] = -std::sin(angle);
      placement_rotation[1][0] = std::sin(angle);
      placement_rotation[1][1] = std::cos(angle);
      placed                   = translation.norm() > 0. || angle != 0.;
    }



    template <int dim>
    Point<dim>
    RigidSurface<dim>::to_body(const Point<dim> &x) const
    {
      if (!placed)
        return x;
      return placement_centre +
             transpose(placement_rotation) *
               (x - placement_centre - placement_translation);
    }



    template <int dim>
    Point<dim>
    RigidSurface<dim>::from_body(const Point<dim> &y) const
    {
      if (!placed)
        return y;
      return placement_centre + placement_translation +
             placement_rotation * (y - placement_centre);
    }



    template <int dim>
    const Tensor<2, dim> &
    RigidSurface<dim>::rotation() const
    {
      return placement_rotation;
    }



    template <int dim>
    typename RigidSurface<dim>::ClosestPoint
    RigidSurface<dim>::closest_point(const Point<dim> &x) const
    {
      if (!placed)
        return closest_point_in_body(x);
      ClosestPoint result = closest_point_in_body(to_body(x));
      result.point        = from_body(result.point);
      result.normal       = placement_rotation * result.normal;
      return result;
    }



    template <int dim>
    typename RigidSurface<dim>::ClosestPoint
    RigidSurface<dim>::closest_point_in_body(const Point<dim> &x) const
    {
      ClosestPoint result;
      if constexpr (dim == 2)
        {
          const auto c    = profile.closest_point(x);
          result.point    = c.point;
          result.normal   = c.normal;
          result.distance = c.distance;
        }
      else
        closest_point_3d(x, result);
      return result;
    }



    template <int dim>
    void
    RigidSurface<dim>::closest_point_3d(const Point<dim> &x,
                                        ClosestPoint     &result) const
    {
      if constexpr (dim == 3)
        {
          if (sweep == ProfileSweep::extrusion_along_z)
            {
              const auto c    = profile.closest_point(Point<2>(x[0], x[1]));
              result.point    = Point<dim>(c.point[0], c.point[1], x[2]);
              result.normal   = Tensor<1, dim>({c.normal[0], c.normal[1], 0.});
              result.distance = c.distance;
            }
          else
            {
              // The meridian plane through x: radius r, direction e_r.
              const double   r = std::sqrt(x[0] * x[0] + x[2] * x[2]);
              Tensor<1, dim> e_r({1., 0., 0.});
              if (r > 0.)
                e_r = Tensor<1, dim>({x[0] / r, 0., x[2] / r});
              const auto c     = profile.closest_point(Point<2>(r, x[1]));
              result.point     = Point<dim>(c.point[0] * e_r[0],
                                        c.point[1],
                                        c.point[0] * e_r[2]);
              result.normal    = c.normal[0] * e_r;
              result.normal[1] = c.normal[1];
              result.distance  = c.distance;
            }
        }
      else
        {
          (void)x;
          (void)result;
        }
    }



    template <int dim>
    typename RigidSurface<dim>::RayHit
    RigidSurface<dim>::intersect_ray(const Point<dim>     &x,
                                     const Tensor<1, dim> &d,
                                     const double          max_distance,
                                     const double          length_scale) const
    {
      RayHit hit;
      // Newton on phi(t) = distance(x + t d), phi' = n . d.
      const auto   start  = closest_point(x);
      const double slope0 = start.normal * d;
      if (std::abs(slope0) < 1e-12)
        return hit;
      double t = -start.distance / slope0;
      for (unsigned int it = 0; it < 50; ++it)
        {
          if (!std::isfinite(t) ||
              std::abs(t) > 2. * max_distance + length_scale)
            return hit;
          const Point<dim> y     = x + t * d;
          const auto       c     = closest_point(y);
          const double     slope = c.normal * d;
          if (std::abs(c.distance) <= 1e-12 * length_scale)
            {
              hit.found  = std::abs(t) <= max_distance;
              hit.t      = t;
              hit.point  = y;
              hit.normal = c.normal;
              return hit;
            }
          if (std::abs(slope) < 1e-12)
            return hit;
          t -= c.distance / slope;
        }
      return hit;
    }



    template <int dim>
    std::string
    RigidSurface<dim>::description() const
    {
      if (dim == 2)
        return "profile of " + profile.description();
      return "profile of " + profile.description() +
             (sweep == ProfileSweep::revolution_about_y ?
                " revolved about the y axis" :
                " extruded along z");
    }

    template class RigidSurface<2>;
    template class RigidSurface<3>;
  } // namespace Contact
} // namespace Common
