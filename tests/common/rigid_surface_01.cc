// Checks Common::Contact::RigidSurface on the profile of the rounded punch
// of benchmark 2 (flat face of radius b = 40 mm at height H = 200 mm, a
// fillet of radius rho = 10 mm centred at (b, H + rho), then the side
// x = 50 mm up to H + 100 mm):
// - closest points and signed distances of points below the flat face,
//   below and beside the fillet, and inside the punch, against their
//   closed forms (1e-12 mm);
// - the outward normal (0, -1) under the flat face and radial on the
//   fillet, also 1e-9 mm from the profile on either side (to 1e-13: the
//   normal of a closed contact node against a curved tool); beyond a
//   convex corner the direction from the corner;
// - vertical rays from y = H - 1 mm meet the surface at y = H on the flat
//   face and at y = H + rho - sqrt(rho^2 - (r - b)^2) under the fillet
//   (1e-10 mm), the height a small-strain contact gap is measured by;
// - revolved about the y axis, the same at points on a meridian turned by
//   30 degrees, with normals turned alike.
// Requirement: the geometry the analytic rigid punch is paired with is
// exact to round-off.

#include <common/contact/rigid_surface.h>

#include "../tests.h"

#include <deal.II/base/numbers.h>

#include <cmath>
#include <iomanip>

using namespace dealii;
using Common::Contact::RigidProfile;
using Common::Contact::RigidSurface;

namespace
{
  constexpr double H = 200., b = 40., rho = 10., a = 50.;

  RigidProfile
  punch_profile()
  {
    RigidProfile profile;
    profile.add_line(Point<2>(0., H), Point<2>(b, H));
    profile.add_arc(Point<2>(b, H + rho), rho, -0.5 * numbers::PI, 0.);
    profile.add_line(Point<2>(a, H + rho), Point<2>(a, H + 100.));
    return profile;
  }

  /** Height of the punch face above radius r (under the flat face and the
   * fillet). */
  double
  face_height(const double r)
  {
    return r <= b ? H : H + rho - std::sqrt(rho * rho - (r - b) * (r - b));
  }

  void
  check(const std::string &what, const double error, const double tolerance)
  {
    deallog << what << ": " << (error <= tolerance ? "ok" : "FAILED")
            << std::endl;
    if (error > tolerance)
      deallog << "  error " << error << std::endl;
  }
} // namespace

int
main()
{
  initlog();
  const RigidProfile profile = punch_profile();
  deallog << "Profile: " << profile.description() << std::endl;

  const RigidSurface<2> surface(profile);
  // Below the flat face.
  {
    const auto c = surface.closest_point(Point<2>(20., H - 3.));
    check("flat face: closest point",
          c.point.distance(Point<2>(20., H)) + std::abs(c.distance - 3.) +
            (c.normal - Tensor<1, 2>({0., -1.})).norm(),
          1e-12);
  }
  // Inside the punch, above the flat face: negative distance.
  {
    const auto c = surface.closest_point(Point<2>(10., H + 0.5));
    check("inside the punch: negative distance",
          std::abs(c.distance + 0.5),
          1e-12);
  }
  // Below the fillet, on the ray from its centre at -60 degrees.
  {
    const double       angle = -numbers::PI / 3.;
    const Tensor<1, 2> e({std::cos(angle), std::sin(angle)});
    const Point<2>     centre(b, H + rho);
    const Point<2>     x = centre + (rho + 2.) * e;
    const auto         c = surface.closest_point(x);
    check("fillet: closest point, distance, radial normal",
          c.point.distance(centre + rho * e) + std::abs(c.distance - 2.) +
            (c.normal - e).norm(),
          1e-12);
  }
  // 1e-9 mm from the fillet and from the flat face, outside and inside
  // (a closed contact node): the normal is the profile's own to
  // round-off, not the direction of x - p, whose rounding error at these
  // coordinates (1e-14 mm) would turn it by some 1e-5.
  {
    double error = 0.;
    for (const double offset : {1e-9, -1e-9})
      {
        const double       angle = -1.1;
        const Tensor<1, 2> e({std::cos(angle), std::sin(angle)});
        const Point<2>     centre(b, H + rho);
        const auto c = surface.closest_point(centre + (rho + offset) * e);
        error        = std::max(error, (c.normal - e).norm());
        const auto f = surface.closest_point(Point<2>(13.7, H - offset));
        error = std::max(error, (f.normal - Tensor<1, 2>({0., -1.})).norm());
      }
    check("1e-9 mm from the profile: the profile's normal", error, 1e-13);
  }
  // Beyond the start of the flat face (a convex corner): the normal is the
  // direction from the corner to the point.
  {
    const auto c = surface.closest_point(Point<2>(-3., H - 4.));
    check("beyond a convex corner: distance, normal towards the point",
          c.point.distance(Point<2>(0., H)) + std::abs(c.distance - 5.) +
            (c.normal - Tensor<1, 2>({-0.6, -0.8})).norm(),
          1e-12);
  }
  // Beside the side face.
  {
    const auto c = surface.closest_point(Point<2>(a + 4., H + 50.));
    check("side face: closest point",
          c.point.distance(Point<2>(a, H + 50.)) + std::abs(c.distance - 4.),
          1e-12);
  }

  // Vertical rays from below.
  double ray_error = 0.;
  for (const double r : {0., 20., 39.9, 40., 42., 45., 48., 49.5})
    {
      const auto hit = surface.intersect_ray(Point<2>(r, H - 1.),
                                             Tensor<1, 2>({0., 1.}),
                                             20.,
                                             1.);
      ray_error =
        std::max(ray_error,
                 hit.found ? std::abs(hit.point[1] - face_height(r)) : 1e3);
    }
  check("vertical rays meet the face at its height", ray_error, 1e-10);
  {
    const auto hit = surface.intersect_ray(Point<2>(60., H - 1.),
                                           Tensor<1, 2>({0., 1.}),
                                           5.,
                                           1.);
    deallog << "ray beside the punch within 5 mm: "
            << (hit.found ? "found" : "not found") << std::endl;
  }

  // Revolved about y: a meridian turned by 30 degrees about the axis.
  const RigidSurface<3> revolved(
    profile,
    Common::Contact::ProfileSweep::revolution_about_y);
  deallog << "3D: " << revolved.description() << std::endl;
  const double phi  = numbers::PI / 6.;
  const auto   turn = [phi](const double r, const double y) {
    return Point<3>(r * std::cos(phi), y, r * std::sin(phi));
  };
  double error_3d = 0.;
  for (const double r : {0., 20., 42., 45., 49.5})
    {
      const auto hit = revolved.intersect_ray(turn(r, H - 1.),
                                              Tensor<1, 3>({0., 1., 0.}),
                                              20.,
                                              1.);
      error_3d =
        std::max(error_3d,
                 hit.found ? hit.point.distance(turn(r, face_height(r))) : 1e3);
    }
  {
    const double       angle = -numbers::PI / 4.;
    const Point<3>     x     = turn(b + (rho + 1.) * std::cos(angle),
                            H + rho + (rho + 1.) * std::sin(angle));
    const auto         c     = revolved.closest_point(x);
    const Tensor<1, 3> n({std::cos(angle) * std::cos(phi),
                          std::sin(angle),
                          std::cos(angle) * std::sin(phi)});
    error_3d =
      std::max(error_3d, std::abs(c.distance - 1.) + (c.normal - n).norm());
  }
  check("revolved: rays, distance and normal on a turned meridian",
        error_3d,
        1e-10);
}
