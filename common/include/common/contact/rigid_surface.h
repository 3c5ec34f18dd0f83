/**
 * @file rigid_surface.h
 * Analytic rigid surfaces for tools that need no mesh: a profile of
 * straight segments and circular arcs in a plane, used as it is in 2D
 * (plane strain or the meridian of an axisymmetric model), and in 3D
 * revolved about the y axis (punches, dies of revolution) or extruded
 * along z (cylinders, planes, die profiles). Geometry only: the signed
 * distance, the closest point with its outward normal, and the point
 * where a ray meets the surface.
 *
 * The rigid body lies to the left of the profile as it is traversed; its
 * outward normal points to the right: \f$n = (t_y, -t_x)\f$ for the unit
 * tangent t.
 *
 * A surface can be placed by a rigid motion (set_placement()): a
 * translation and a rotation about the z axis through a centre, so that a
 * tool moves and turns without a mesh (a roller, a punch). Every query
 * answers for the placed surface.
 */
#ifndef common_contact_rigid_surface_h
#define common_contact_rigid_surface_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief A chain of straight segments and circular arcs in the plane.
     */
    class RigidProfile
    {
    public:
      /** @brief Closest point of the profile to a point. */
      struct ClosestPoint
      {
        dealii::Point<2> point;
        /** Outward unit normal of the rigid body at the point. */
        dealii::Tensor<1, 2> normal;
        /** Signed distance (mm): positive outside the rigid body. */
        double distance;
      };

      /** @brief Append the straight segment from @p start to @p end (mm). */
      void
      add_line(const dealii::Point<2> &start, const dealii::Point<2> &end);

      /**
       * @brief Append the circular arc about @p centre of radius @p radius
       * (mm) from angle @p start_angle to @p end_angle (radians, from the
       * x axis; counterclockwise if the end angle is larger).
       */
      void
      add_arc(const dealii::Point<2> &centre,
              const double            radius,
              const double            start_angle,
              const double            end_angle);

      /** @brief The closest point of the profile to @p x, with the
       * profile's outward normal there and the signed distance of @p x
       * along it (mm). Beyond a convex corner (the closest point an end of
       * its piece) the normal is the unit vector from the corner to @p x
       * (reversed inside the body) and the distance the distance to the
       * corner, so that the distance function stays continuously
       * differentiable. Throws if the profile is empty. */
      ClosestPoint
      closest_point(const dealii::Point<2> &x) const;

      /** @brief Number of segments and arcs. */
      unsigned int
      n_pieces() const;

      /** @brief "2 lines and 1 arc". */
      std::string
      description() const;

    private:
      struct Piece
      {
        bool             is_arc;
        dealii::Point<2> start, end;
        dealii::Point<2> centre;
        double           radius      = 0.;
        double           start_angle = 0.;
        double           end_angle   = 0.;
      };
      std::vector<Piece> pieces;
    };

    /** How a planar profile becomes a surface in 3D. */
    enum class ProfileSweep
    {
      /** Revolved about the y axis: the profile's x is the radius. */
      revolution_about_y,
      /** Extruded along z. */
      extrusion_along_z
    };

    /**
     * @brief A rigid surface in dim dimensions made of a RigidProfile.
     */
    template <int dim>
    class RigidSurface
    {
    public:
      /** @brief Closest point with its outward normal. */
      struct ClosestPoint
      {
        dealii::Point<dim>     point;
        dealii::Tensor<1, dim> normal;
        double                 distance;
      };

      /** @brief Where a ray meets the surface. */
      struct RayHit
      {
        bool found = false;
        /** Distance along the ray (mm): the hit is x + t d. */
        double                 t = 0.;
        dealii::Point<dim>     point;
        dealii::Tensor<1, dim> normal;
      };

      /**
       * @param[in] profile The planar profile (copied).
       * @param[in] sweep How it makes a 3D surface (ignored in 2D).
       */
      RigidSurface(const RigidProfile &profile,
                   const ProfileSweep sweep = ProfileSweep::revolution_about_y);

      /** @brief Closest point of the surface to @p x. */
      ClosestPoint
      closest_point(const dealii::Point<dim> &x) const;

      /**
       * @brief The point where the ray \f$x + t\,d\f$ (d a unit vector)
       * meets the surface, by Newton's method on the signed distance along
       * the ray, starting from the closest point; not found if the
       * iteration does not converge to 1e-12 of @p length_scale within 50
       * steps, or if |t| exceeds @p max_distance.
       */
      RayHit
      intersect_ray(const dealii::Point<dim>     &x,
                    const dealii::Tensor<1, dim> &d,
                    const double                  max_distance,
                    const double                  length_scale) const;

      /** @brief The profile and the sweep, for the console. */
      std::string
      description() const;

      /**
       * @brief Place the surface by a rigid motion: a point Y of the
       * surface as it was defined moves to
       * \f$c + s + R(\theta)(Y - c)\f$, with R the rotation by
       * @p angle (radians, counterclockwise seen from +z) about the z axis
       * through the centre c (in 3D the axis parallel to z through c).
       * @param[in] translation s (mm).
       * @param[in] angle theta (rad).
       * @param[in] centre c, in the surface's own coordinates (mm).
       */
      void
      set_placement(const dealii::Tensor<1, dim> &translation,
                    const double                  angle,
                    const dealii::Point<dim>     &centre);

      /** @brief The point of the surface as it was defined that the
       * placement carries to @p x (the inverse of the rigid motion). */
      dealii::Point<dim>
      to_body(const dealii::Point<dim> &x) const;

      /** @brief Where the placement carries the point @p y of the surface
       * as it was defined. */
      dealii::Point<dim>
      from_body(const dealii::Point<dim> &y) const;

      /** @brief The rotation R(theta) of the placement. */
      const dealii::Tensor<2, dim> &
      rotation() const;

    private:
      const RigidProfile     profile;
      const ProfileSweep     sweep;
      dealii::Tensor<1, dim> placement_translation;
      dealii::Tensor<2, dim> placement_rotation;
      dealii::Point<dim>     placement_centre;
      bool                   placed = false;

      /** closest_point() of the surface as it was defined. */
      ClosestPoint
      closest_point_in_body(const dealii::Point<dim> &y) const;

      /** closest_point() of a swept profile (dim = 3). */
      void
      closest_point_3d(const dealii::Point<dim> &x, ClosestPoint &result) const;
    };
  } // namespace Contact
} // namespace Common

#endif
