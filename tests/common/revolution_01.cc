/*
 * Quarter models of bodies of revolution (common/geometry/revolution.h):
 * (1) the meridian rectangle [0,2] x [0,3] mm (2 x 3 cells, boundary ids 1
 * bottom, 2 top, 3 side) revolves into a quarter cylinder: its volume
 * converges to 3 pi mm^3, the side (id 3) to 3 pi mm^2, the bottom (id 1)
 * to pi mm^2 and each symmetry plane (ids 4: z = 0, 5: x = 0) to 6 mm^2;
 * (2) a disc of radius 1 centred at r = 3 (deal.II's hyper_ball, curved
 * boundary) revolves into a quarter torus whose volume converges to
 * Pappus's 1.5 pi^2 mm^3 and its surface to 3 pi^2 mm^2. Volumes and areas
 * are integrated with a Q2 mapping after 0 to 3 global refinements; the
 * relative errors must fall by at least a factor of 8 per refinement and
 * lie below 1e-5 at the finest level, and every cell must have a positive
 * Jacobian at every quadrature point. (3) Both bodies revolved apart and
 * joined by join_bodies (common/geometry/two_body_meshes.h) must converge
 * in the same way: the join keeps the manifold ids of faces and lines and
 * the manifolds themselves. (4) The lower half of the disc of radius 1
 * about the origin (three cells of a quarter disc; the cell at the pole
 * has an arc for its bottom edge, with a SphericalManifold) revolves into
 * an eighth of a ball: volume pi/6 mm^3, sphere (id 1) pi/2 mm^2, top
 * (id 2) and each symmetry plane pi/4 mm^2.
 */

#include <common/geometry/revolution.h>
#include <common/geometry/two_body_meshes.h>

#include "../tests.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  /** Volume and the area of each boundary id, with a Q2 mapping; false in
   * second if a Jacobian is not positive. */
  std::pair<std::map<int, double>, bool>
  measure(const Triangulation<3> &tria)
  {
    const MappingQ<3>     mapping(2);
    const FE_Q<3>         fe(1);
    const QGauss<3>       quadrature(4);
    const QGauss<2>       face_quadrature(4);
    FEValues<3>           fe_values(mapping, fe, quadrature, update_JxW_values);
    FEFaceValues<3>       fe_face_values(mapping,
                                   fe,
                                   face_quadrature,
                                   update_JxW_values);
    std::map<int, double> result;
    bool                  positive = true;
    for (const auto &cell : tria.active_cell_iterators())
      {
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            positive = positive && fe_values.JxW(q) > 0.;
            result[-1] += fe_values.JxW(q);
          }
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              fe_face_values.reinit(cell, f);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                result[cell->face(f)->boundary_id()] += fe_face_values.JxW(q);
            }
      }
    return {result, positive};
  }

  void
  check(const std::string                         &name,
        Triangulation<3>                          &tria,
        const std::vector<std::pair<int, double>> &exact)
  {
    deallog << name << ": " << tria.n_active_cells() << " coarse cells"
            << std::endl;
    std::map<int, double> last_error;
    bool                  passed = true;
    for (unsigned int level = 0; level <= 3; ++level)
      {
        if (level > 0)
          tria.refine_global(1);
        const auto [values, positive] = measure(tria);
        passed                        = passed && positive;
        deallog << "  level " << level << ":";
        for (const auto &[id, value] : exact)
          {
            const double error = std::abs(values.at(id) / value - 1.);
            deallog << " "
                    << (id < 0 ? std::string("volume") :
                                 "id " + std::to_string(id))
                    << " " << error;
            if (level > 0 && last_error[id] > 1e-12)
              passed = passed && error < last_error[id] / 8.;
            if (level == 3)
              passed = passed && error < 1e-5;
            last_error[id] = error;
          }
        deallog << std::endl;
      }
    deallog << name << ": " << (passed ? "PASS" : "FAIL") << std::endl;
  }
} // namespace



/** The meridian rectangle [0,2] x [0,3] mm, 2 x 3 cells; boundary ids 1
 * bottom, 2 top, 3 side. */
void
make_rectangle(Triangulation<2> &meridian)
{
  GridGenerator::subdivided_hyper_rectangle(meridian,
                                            {2u, 3u},
                                            Point<2>(0., 0.),
                                            Point<2>(2., 3.));
  for (const auto &cell : meridian.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        {
          const Point<2> c = cell->face(f)->center();
          cell->face(f)->set_boundary_id(std::abs(c[1]) < 1e-12      ? 1 :
                                         std::abs(c[1] - 3.) < 1e-12 ? 2 :
                                         std::abs(c[0] - 2.) < 1e-12 ? 3 :
                                                                       0);
        }
}



/** The lower half of the disc of radius 1 mm about the origin: a quarter
 * disc of three cells (at the pole, at the side, and the square at the
 * centre); boundary ids 1 on the arc (SphericalManifold, id 0), 2 on top
 * (y = 0). */
void
make_hemisphere(Triangulation<2> &meridian)
{
  const double                                   s        = std::sqrt(0.5);
  const std::vector<Point<2>>                    vertices = {{0., -1.},
                                                             {s, -s},
                                                             {1., 0.},
                                                             {0., -0.5},
                                                             {0.5, -0.5},
                                                             {0.5, 0.},
                                                             {0., 0.}};
  const std::vector<std::array<unsigned int, 4>> cell_vertices =
    {{{0, 1, 3, 4}}, {{1, 2, 4, 5}}, {{3, 4, 6, 5}}};
  std::vector<CellData<2>> cells(cell_vertices.size());
  for (unsigned int c = 0; c < cells.size(); ++c)
    for (unsigned int v = 0; v < 4; ++v)
      cells[c].vertices[v] = cell_vertices[c][v];
  GridTools::consistently_order_cells(cells);
  meridian.create_triangulation(vertices, cells, SubCellData());
  for (const auto &cell : meridian.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        {
          const Point<2> c = cell->face(f)->center();
          if (std::abs(c[1]) < 1e-12)
            cell->face(f)->set_boundary_id(2);
          else if (c[0] > 1e-12)
            {
              cell->face(f)->set_boundary_id(1);
              cell->face(f)->set_manifold_id(0);
            }
        }
  meridian.set_manifold(0, SphericalManifold<2>(Point<2>()));
}



/** The disc of radius 1 mm centred at r = 3 mm, boundary id @p id. */
void
make_disc(Triangulation<2> &meridian, const types::boundary_id id)
{
  GridGenerator::hyper_ball(meridian, Point<2>(3., 0.), 1.);
  meridian.set_all_manifold_ids_on_boundary(0);
  for (const auto &cell : meridian.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        cell->face(f)->set_boundary_id(id);
}



int
main()
{
  initlog(3);
  deallog << std::scientific;
  const double pi = numbers::PI;
  {
    Triangulation<2> meridian;
    make_rectangle(meridian);
    Triangulation<3> tria;
    Common::Geometry::revolve_quarter(meridian, 4, 5, 10, tria);
    check("quarter cylinder",
          tria,
          {{-1, 3. * pi}, {3, 3. * pi}, {1, pi}, {4, 6.}, {5, 6.}});
  }
  {
    Triangulation<2> meridian;
    make_disc(meridian, 1);
    Triangulation<3> tria;
    Common::Geometry::revolve_quarter(meridian, 4, 5, 10, tria);
    check("quarter torus", tria, {{-1, 1.5 * pi * pi}, {1, 3. * pi * pi}});
  }
  {
    // (3) Both bodies revolved apart (manifold ids from 10 and from 20)
    // and joined by join_bodies, which must carry over the manifold ids
    // of faces and lines and the manifolds themselves: the torus (boundary
    // id 6) touches the cylinder along a circle only.
    Triangulation<2> rectangle, disc;
    make_rectangle(rectangle);
    make_disc(disc, 6);
    Triangulation<3> cylinder, torus, tria;
    Common::Geometry::revolve_quarter(rectangle, 4, 5, 10, cylinder);
    Common::Geometry::revolve_quarter(disc, 4, 5, 20, torus);
    Common::Geometry::join_bodies<3>({&cylinder, &torus}, tria);
    check("joined cylinder and torus",
          tria,
          {{-1, 3. * pi + 1.5 * pi * pi},
           {3, 3. * pi},
           {1, pi},
           {6, 3. * pi * pi},
           {4, 6. + pi},
           {5, 6. + pi}});
  }
  {
    Triangulation<2> meridian;
    make_hemisphere(meridian);
    Triangulation<3> tria;
    Common::Geometry::revolve_quarter(meridian, 4, 5, 10, tria);
    check(
      "eighth of a ball",
      tria,
      {{-1, pi / 6.}, {1, pi / 2.}, {2, pi / 4.}, {4, pi / 4.}, {5, pi / 4.}});
  }
}
