/**
 * @file revolution.h
 * Quarter models of bodies of revolution: the coarse mesh of a meridian
 * section (r, y) is revolved through 90 degrees about the y axis into a 3D
 * coarse mesh, with manifolds that keep every surface of revolution exact
 * under refinement. The 3D point of meridian point (r, y) at angle theta
 * is (r cos theta, y, r sin theta); the quarter is bounded by the
 * symmetry planes z = 0 (theta = 0) and x = 0 (theta = 90 degrees).
 */
#ifndef common_geometry_revolution_h
#define common_geometry_revolution_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <memory>

namespace Common
{
  namespace Geometry
  {
    /**
     * @brief The surface (or curve, or volume) swept by a meridian
     * manifold turning about the y axis: a new point takes its meridian
     * coordinates (r, y) from the meridian manifold and its angle as the
     * weighted mean of the surrounding points' angles. Exact for surfaces
     * of revolution of any meridian curve the 2D manifold describes
     * (cylinders, cones, planes normal to the axis, tori). Valid away from
     * the axis only (every point with r > 0, angles within a half turn).
     */
    class RevolvedManifold : public dealii::Manifold<3>
    {
    public:
      /** @param[in] meridian Manifold of the meridian section (copied). */
      explicit RevolvedManifold(const dealii::Manifold<2> &meridian);

      std::unique_ptr<dealii::Manifold<3>>
      clone() const override;

      dealii::Point<3>
      get_new_point(
        const dealii::ArrayView<const dealii::Point<3>> &points,
        const dealii::ArrayView<const double> &weights) const override;

      dealii::Point<3>
      get_intermediate_point(const dealii::Point<3> &p1,
                             const dealii::Point<3> &p2,
                             const double            w) const override;

    private:
      std::unique_ptr<dealii::Manifold<2>> meridian;
    };

    /**
     * @brief Revolve the coarse meridian mesh @p meridian (x = r >= 0,
     * y axial) through 90 degrees about the y axis into @p result.
     *
     * A meridian cell away from the axis becomes two hexahedra (0 to 45
     * and 45 to 90 degrees); a cell with an edge on the axis becomes the
     * three cells of a quarter disc (an inner square and two cells up to
     * the arc) per layer. Its top and bottom edges must be horizontal (the
     * layer is bounded by plane discs) or arcs of circles centred on the
     * axis, with a SphericalManifold<2> (the pole of a sphere: the layer is
     * bounded by a spherical cap, on which the inner square's vertices are
     * placed). Cells with a single vertex on the axis are not allowed.
     * Material ids
     * are kept; boundary faces take the boundary id of the meridian edge
     * they are swept from, and the symmetry planes @p plane_z0_id (z = 0)
     * and @p plane_x0_id (x = 0). Faces and lines of revolution get a
     * RevolvedManifold of their meridian edge's manifold (ids from
     * @p first_manifold_id on; a transfinite meridian manifold counts as
     * flat); faces and lines that lie on the sphere swept by such an arc
     * get a SphericalManifold<3> about its centre instead (except circles
     * about the axis, which stay revolved); cells and plane faces stay
     * flat, so that their new points and
     * mapping support points interpolate the curved faces and lines; a Q2
     * mapping then converges to the exact volume at order 4.
     */
    void
    revolve_quarter(const dealii::Triangulation<2>  &meridian,
                    const dealii::types::boundary_id plane_z0_id,
                    const dealii::types::boundary_id plane_x0_id,
                    const dealii::types::manifold_id first_manifold_id,
                    dealii::Triangulation<3>        &result);
  } // namespace Geometry
} // namespace Common

#endif
