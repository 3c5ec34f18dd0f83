// Checks Common::Contact::ContactSearch::project_along on a discretised
// circle. A disc of radius R = 1 (GridGenerator::hyper_ball, spherical
// manifold on the boundary, transfinite interpolation inside) is refined
// globally, discretised with FE_Q(p)^2 and MappingQ(p), p = 1 and 2, and
// its boundary becomes a ContactSurface. Points placed at distance
// delta = 0.1 outside the circle are projected toward the centre along the
// radial direction onto the candidate faces returned by faces_near; the
// projection distance must equal delta up to the geometric error of the
// isoparametric boundary. The maximum error over 2048 points is printed
// per refinement level with the observed convergence rate: about 2 for the
// Q1 polygon, about 4 for Q2 (an even-degree interpolant of a circle is
// superconvergent in the radial direction). The test fails if a point is
// not found or if the last rate is below 1.8 (Q1) or 2.8 (Q2).

#include <common/contact/contact_search.h>
#include <common/contact/contact_surface.h>

#include "../tests.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

using namespace dealii;

namespace
{
  std::string
  scientific(const double x)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(4) << x;
    return s.str();
  }



  // Maximum |t - delta| over the sample points, and the number of points
  // whose projection was not found.
  std::pair<double, unsigned int>
  projection_error(const unsigned int degree, const unsigned int n_refinements)
  {
    const double     R     = 1.;
    const double     delta = 0.1 * R;
    Triangulation<2> triangulation;
    GridGenerator::hyper_ball(triangulation, Point<2>(), R);
    triangulation.set_all_manifold_ids(1);
    triangulation.set_all_manifold_ids_on_boundary(0);
    triangulation.set_manifold(0, SphericalManifold<2>(Point<2>()));
    TransfiniteInterpolationManifold<2> transfinite;
    transfinite.initialize(triangulation);
    triangulation.set_manifold(1, transfinite);
    triangulation.refine_global(n_refinements);

    const FESystem<2> fe(FE_Q<2>(degree), 2);
    const MappingQ<2> mapping(degree);
    DoFHandler<2>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);

    const Common::Contact::ContactSurface<2> surface(dof_handler, mapping, 0);
    const Common::Contact::ContactSearch<2>  search(surface, 0.01 * R);

    const unsigned int n_points  = 2048;
    double             max_error = 0.;
    unsigned int       n_missed  = 0;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        const double theta = numbers::PI / 4. + 2. * numbers::PI * i / n_points;
        const Tensor<1, 2> e({std::cos(theta), std::sin(theta)});
        const Point<2>     x(Point<2>() + (R + delta) * e);
        const Tensor<1, 2> direction = -e;

        // Candidate faces: those near the radial segment from x to a point
        // 2 delta further in.
        const BoundingBox<2> box(
          std::vector<Point<2>>{x, Point<2>(x + 2. * delta * direction)});
        double distance = std::numeric_limits<double>::infinity();
        for (const unsigned int f : search.faces_near(box))
          {
            const auto projection =
              Common::Contact::ContactSearch<2>::project_along(surface,
                                                               f,
                                                               x,
                                                               direction);
            if (projection.inside() && projection.distance > 0. &&
                projection.distance < distance)
              distance = projection.distance;
          }
        if (distance == std::numeric_limits<double>::infinity())
          ++n_missed;
        else
          max_error = std::max(max_error, std::abs(distance - delta));
      }
    return {max_error, n_missed};
  }
} // namespace

int
main()
{
  initlog();

  for (const unsigned int degree : {1u, 2u})
    {
      deallog << "Q" << degree << std::endl;
      double       previous_error = 0.;
      double       rate           = 0.;
      unsigned int total_missed   = 0;
      for (unsigned int level = 1; level <= 5; ++level)
        {
          const auto [error, n_missed] = projection_error(degree, level);
          total_missed += n_missed;
          deallog << "  refinements " << level << ": faces "
                  << 4 * (1u << level)
                  << ", max |gap - exact| = " << scientific(error)
                  << ", missed points " << n_missed;
          if (level > 1)
            {
              rate = std::log2(previous_error / error);
              deallog << ", rate " << std::setprecision(1) << rate
                      << std::setprecision(6);
            }
          deallog << std::endl;
          previous_error = error;
        }
      const double required = (degree == 1 ? 1.8 : 2.8);
      deallog << "Q" << degree << " rate > " << std::setprecision(1) << required
              << std::setprecision(6) << " and no missed points: "
              << (rate > required && total_missed == 0 ? "PASS" : "FAIL")
              << std::endl;
    }
}
