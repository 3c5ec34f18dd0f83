/*
 * The quarter mesh of benchmark 4, 3D loaded pin (loaded_pin/pin_mesh.h),
 * coarse, after one global and one graded refinement, and graded toward
 * the arc end (two more halvings along the line theta = 89 degrees of the
 * contact surface, whose cells must be less than 0.4 times those at
 * theta = 150 degrees: two halvings give 0.33 with these cell shapes, one
 * would give about 0.66): the volume of
 * each body and the area of each boundary id of each body, integrated with
 * QGauss(3) and a MappingQ(2), against the exact values (mm^3, mm^2); the
 * largest distance of a vertex on the hole and on the pin's surface from
 * the cylinder r = 50 mm (relative); the cell counts; the vertices the
 * application needs (the load point (0, 0, 10)). Relative errors are
 * printed with two digits, or as "< 1e-6". The test fails (FAIL, or a
 * changed output) if an error exceeds 1e-3, a vertex of the contact
 * surfaces is off the cylinder by more than 1e-10, a (body, boundary id)
 * pair is missing or unexpected, or a Jacobian is not positive. The same
 * mesh built in a parallel::shared::Triangulation must be identical.
 */

#include <common/geometry/two_body_meshes.h>

#include "../tests.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iomanip>
#include <loaded_pin/pin_mesh.h>
#include <map>
#include <sstream>
#include <string>
#include <utility>

using namespace dealii;
using namespace LoadedPin;

namespace
{
  using Key = std::pair<types::material_id, types::boundary_id>;

  /** Volume of each body (key (material id, invalid boundary id)) and
   * area of each (material id, boundary id); false in second if a
   * Jacobian is not positive. */
  std::pair<std::map<Key, double>, bool>
  measure(const Triangulation<3> &tria)
  {
    const MappingQ<3> mapping(2);
    const FE_Q<3>     fe(1);
    FEValues<3>       fe_values(mapping, fe, QGauss<3>(3), update_JxW_values);
    FEFaceValues<3>   fe_face_values(mapping,
                                   fe,
                                   QGauss<2>(3),
                                   update_JxW_values);
    std::map<Key, double> result;
    bool                  positive = true;
    for (const auto &cell : tria.active_cell_iterators())
      {
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            positive = positive && fe_values.JxW(q) > 0.;
            result[{cell->material_id(), numbers::invalid_boundary_id}] +=
              fe_values.JxW(q);
          }
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              fe_face_values.reinit(cell, f);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                result[{cell->material_id(), cell->face(f)->boundary_id()}] +=
                  fe_face_values.JxW(q);
            }
      }
    return {result, positive};
  }

  /** |value / exact - 1| with two digits, or "< 1e-6". */
  std::string
  relative_error(const double value, const double exact)
  {
    const double error = std::abs(value / exact - 1.);
    if (error < 1e-6)
      return "< 1e-6";
    std::ostringstream out;
    out << std::scientific << std::setprecision(1) << error;
    return out.str();
  }

  /** Largest |r / 50 - 1| of the vertices on faces with boundary id
   * @p id. */
  double
  radius_deviation(const Triangulation<3> &tria, const types::boundary_id id)
  {
    double deviation = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          for (const unsigned int v : face->vertex_indices())
            deviation = std::max(deviation,
                                 std::abs(std::hypot(face->vertex(v)[0],
                                                     face->vertex(v)[1]) /
                                            PinGeometry().hole_radius -
                                          1.));
    return deviation;
  }

  /** Whether a cell of material @p material_id has a vertex at @p p. */
  bool
  has_vertex(const Triangulation<3>  &tria,
             const Point<3>          &p,
             const types::material_id material_id)
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->material_id() == material_id)
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).distance(p) < 1e-10)
            return true;
    return false;
  }

  bool
  check(const MeshOptions &options)
  {
    Triangulation<3> tria;
    make_quarter_mesh(PinGeometry(), options, tria);
    deallog << "global refinements " << options.n_global_refinements
            << ", contact refinements " << options.n_contact_refinements << ": "
            << tria.n_active_cells() << " cells" << std::endl;
    std::map<types::material_id, unsigned int> n_cells;
    for (const auto &cell : tria.active_cell_iterators())
      ++n_cells[cell->material_id()];
    deallog << "  sheet " << n_cells[MaterialIds::sheet] << " cells, pin "
            << n_cells[MaterialIds::pin] << " cells" << std::endl;

    const double pi = numbers::PI;
    const double planform =
      200. * 100. + pi * 100. * 100. / 4. - pi * 50. * 50. / 2.; // sheet, mm^2
    const double             disc   = pi * 50. * 50. / 2.;       // pin, mm^2
    const types::boundary_id volume = numbers::invalid_boundary_id;
    const std::map<Key, std::pair<std::string, double>> exact = {
      {{MaterialIds::sheet, volume}, {"sheet volume", planform * 5.}},
      {{MaterialIds::sheet, BoundaryIds::free},
       {"sheet free", planform + 200. * 5. + pi * 100. / 2. * 5.}},
      {{MaterialIds::sheet, BoundaryIds::clamped}, {"sheet clamped", 500.}},
      {{MaterialIds::sheet, BoundaryIds::symmetry_y0},
       {"sheet symmetry y = 0", 200. * 5.}},
      {{MaterialIds::sheet, BoundaryIds::symmetry_z0},
       {"sheet symmetry z = 0", planform}},
      {{MaterialIds::sheet, BoundaryIds::hole}, {"hole", pi * 50. * 5.}},
      {{MaterialIds::pin, volume}, {"pin volume", disc * 10.}},
      {{MaterialIds::pin, BoundaryIds::symmetry_y0},
       {"pin symmetry y = 0", 100. * 10.}},
      {{MaterialIds::pin, BoundaryIds::symmetry_z0},
       {"pin symmetry z = 0", disc}},
      {{MaterialIds::pin, BoundaryIds::pin_contact},
       {"pin contact", pi * 50. * 10.}},
      {{MaterialIds::pin, BoundaryIds::pin_end}, {"pin end", disc}}};

    const auto [values, positive] = measure(tria);
    bool passed                   = positive;
    for (const auto &[key, value] : values)
      if (exact.count(key) == 0)
        {
          deallog << "  unexpected boundary id " << key.second
                  << " on material " << key.first << std::endl;
          passed = false;
        }
    for (const auto &[key, entry] : exact)
      {
        const double value = values.count(key) ? values.at(key) : 0.;
        deallog << "  " << entry.first << ": exact " << std::fixed
                << std::setprecision(1) << entry.second << ", relative error "
                << relative_error(value, entry.second) << std::endl;
        passed = passed && std::abs(value / entry.second - 1.) < 1e-3;
      }
    for (const auto &[id, name] :
         {std::make_pair(BoundaryIds::hole, "hole"),
          std::make_pair(BoundaryIds::pin_contact, "pin contact")})
      {
        const double deviation = radius_deviation(tria, id);
        deallog << "  max |r/50 - 1| of the " << name << " vertices: "
                << (deviation < 1e-10 ? std::string("< 1e-10") :
                                        std::to_string(deviation))
                << std::endl;
        passed = passed && deviation < 1e-10;
      }
    deallog << "  smallest cell near the contact surface: " << std::fixed
            << std::setprecision(2)
            << Common::Geometry::smallest_cell_near<3>(
                 tria,
                 [](const Point<3> &p) {
                   return contact_distance(PinGeometry(), p);
                 })
            << " mm" << std::endl;
    for (const auto &[p, material] :
         {std::make_pair(Point<3>(0., 0., 10.), MaterialIds::pin),
          std::make_pair(Point<3>(0., 0., 0.), MaterialIds::pin),
          std::make_pair(Point<3>(50., 0., 0.), MaterialIds::pin),
          std::make_pair(Point<3>(50., 0., 0.), MaterialIds::sheet),
          std::make_pair(Point<3>(100., 0., 0.), MaterialIds::sheet)})
      {
        const bool found = has_vertex(tria, p, material);
        deallog << "  vertex (" << p << ") of the "
                << (material == MaterialIds::pin ? "pin" : "sheet") << ": "
                << (found ? "yes" : "no") << std::endl;
        passed = passed && found;
      }
    deallog << "  positive Jacobians: " << (positive ? "yes" : "no")
            << std::endl;
    return passed;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  bool        passed = check(MeshOptions());
  MeshOptions refined;
  refined.n_global_refinements  = 1;
  refined.n_contact_refinements = 1;
  passed                        = check(refined) && passed;

  // Graded toward the arc end: two more halvings at theta = 89 degrees
  // than elsewhere on the contact surface (at theta = 150 degrees).
  MeshOptions arc_end;
  arc_end.n_contact_refinements = 1;
  arc_end.n_arc_end_refinements = 2;
  arc_end.arc_end_angle         = 89.;
  passed                        = check(arc_end) && passed;
  {
    Triangulation<3> tria;
    make_quarter_mesh(PinGeometry(), arc_end, tria);
    const auto smallest_at = [&tria](const double theta) {
      return Common::Geometry::smallest_cell_near<3>(
        tria,
        [theta](const Point<3> &p) {
          return arc_end_distance(PinGeometry(), theta, p);
        });
    };
    const double ratio = smallest_at(89.) / smallest_at(150.);
    deallog << "  smallest cell at theta = 89 over theta = 150: " << std::fixed
            << std::setprecision(2) << ratio << std::endl;
    passed = passed && ratio < 0.4;
  }

  // The applications use a shared triangulation: same cells, same
  // vertices.
  Triangulation<3>                   plain;
  parallel::shared::Triangulation<3> shared(MPI_COMM_WORLD);
  make_quarter_mesh(PinGeometry(), refined, plain);
  make_quarter_mesh(PinGeometry(), refined, shared);
  bool same = plain.n_active_cells() == shared.n_active_cells() &&
              plain.n_vertices() == shared.n_vertices();
  for (unsigned int v = 0; same && v < plain.n_vertices(); ++v)
    same = plain.get_vertices()[v].distance(shared.get_vertices()[v]) < 1e-12;
  deallog << "parallel::shared::Triangulation identical: "
          << (same ? "yes" : "no") << std::endl;

  for (const unsigned int n : {0u, 1u, 2u})
    {
      MeshOptions options;
      options.n_global_refinements = n;
      Triangulation<3> tria;
      make_quarter_mesh(PinGeometry(), options, tria);
      deallog << "global refinements " << n
              << ", no contact refinement: " << tria.n_active_cells()
              << " cells" << std::endl;
    }
  deallog << ((passed && same) ? "PASS" : "FAIL") << std::endl;
}
