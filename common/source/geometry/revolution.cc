#include <common/geometry/revolution.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

namespace Common
{
  namespace Geometry
  {
    using namespace dealii;

    namespace
    {
      /** Meridian coordinates (r, y) of a 3D point. */
      Point<2>
      meridian_point(const Point<3> &p)
      {
        return Point<2>(std::hypot(p[0], p[2]), p[1]);
      }

      /** Angle from the x axis toward the z axis. */
      double
      angle(const Point<3> &p)
      {
        return std::atan2(p[2], p[0]);
      }

      Point<3>
      revolved_point(const Point<2> &m, const double theta)
      {
        return Point<3>(m[0] * std::cos(theta), m[1], m[0] * std::sin(theta));
      }

      /** Distance of @p p from the segment a-b. */
      double
      distance_to_segment(const Point<2> &p,
                          const Point<2> &a,
                          const Point<2> &b)
      {
        const Tensor<1, 2> ab = b - a;
        const double t = std::max(0., std::min(1., ((p - a) * ab) / (ab * ab)));
        return p.distance(a + t * ab);
      }
    } // namespace



    RevolvedManifold::RevolvedManifold(const Manifold<2> &meridian)
      : meridian(meridian.clone())
    {}



    std::unique_ptr<Manifold<3>>
    RevolvedManifold::clone() const
    {
      return std::make_unique<RevolvedManifold>(*meridian);
    }



    Point<3>
    RevolvedManifold::get_new_point(
      const ArrayView<const Point<3>> &points,
      const ArrayView<const double>   &weights) const
    {
      std::vector<Point<2>> meridian_points(points.size());
      double                theta = 0.;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          meridian_points[i] = meridian_point(points[i]);
          theta += weights[i] * angle(points[i]);
        }
      return revolved_point(
        meridian->get_new_point(make_array_view(meridian_points), weights),
        theta);
    }



    Point<3>
    RevolvedManifold::get_intermediate_point(const Point<3> &p1,
                                             const Point<3> &p2,
                                             const double    w) const
    {
      const std::array<Point<3>, 2> points  = {{p1, p2}};
      const std::array<double, 2>   weights = {{1. - w, w}};
      return get_new_point(make_array_view(points.begin(), points.end()),
                           make_array_view(weights.begin(), weights.end()));
    }



    void
    revolve_quarter(const Triangulation<2>  &meridian,
                    const types::boundary_id plane_z0_id,
                    const types::boundary_id plane_x0_id,
                    const types::manifold_id first_manifold_id,
                    Triangulation<3>        &result)
    {
      AssertThrow(meridian.n_levels() == 1,
                  ExcMessage("revolve_quarter needs a coarse meridian mesh."));
      double size = 0.;
      for (const auto &v : meridian.get_vertices())
        {
          AssertThrow(v[0] > -1e-12 * (1. + std::abs(v[1])),
                      ExcMessage("revolve_quarter: the meridian mesh must lie "
                                 "in x >= 0."));
          size = std::max(size, v.norm());
        }
      const double tolerance = 1e-10 * size;
      const auto   on_axis   = [&](const Point<2> &m) {
        return m[0] < tolerance;
      };

      // Meridian edges: endpoints, boundary id, manifold id, and the
      // circle if the edge is an arc of a circle centred on the axis (it
      // sweeps a sphere).
      struct Edge
      {
        Point<2>           a, b;
        bool               at_boundary;
        types::boundary_id boundary_id;
        types::manifold_id manifold_id;
        bool               spherical = false;
        Point<2>           centre;
        double             radius = 0.;
      };
      std::vector<Edge> edges;
      for (const auto &cell : meridian.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() && cell->neighbor_index(f) < cell->index())
              continue;
            types::manifold_id id = face->manifold_id();
            if (id != numbers::flat_manifold_id &&
                dynamic_cast<const TransfiniteInterpolationManifold<2> *>(
                  &meridian.get_manifold(id)) != nullptr)
              id = numbers::flat_manifold_id;
            Edge e;
            e.a           = face->vertex(0);
            e.b           = face->vertex(1);
            e.at_boundary = face->at_boundary();
            e.boundary_id =
              face->at_boundary() ? face->boundary_id() : types::boundary_id(0);
            e.manifold_id = id;
            if (id != numbers::flat_manifold_id)
              if (const auto *circle =
                    dynamic_cast<const SphericalManifold<2> *>(
                      &meridian.get_manifold(id)))
                if (on_axis(circle->center))
                  {
                    e.spherical = true;
                    e.centre    = circle->center;
                    e.radius    = e.a.distance(e.centre);
                  }
            edges.push_back(e);
          }
      // True if @p p lies on edge e: on the segment, or, for an arc, on the
      // circle and nearer the arc's midpoint than its ends are (the arcs of
      // a coarse mesh are shorter than half a turn).
      const auto on_edge = [&](const Point<2> &p, const Edge &e) {
        if (!e.spherical)
          return distance_to_segment(p, e.a, e.b) < tolerance;
        Tensor<1, 2> to_middle = 0.5 * (e.a + e.b) - e.centre;
        to_middle /= to_middle.norm();
        const Point<2> middle = e.centre + e.radius * to_middle;
        return std::abs(p.distance(e.centre) - e.radius) < tolerance &&
               p.distance(middle) < e.a.distance(middle) + tolerance;
      };
      const auto find_edge = [&](const std::vector<Point<2>> &points,
                                 const bool boundary_only) -> const Edge * {
        for (const Edge &e : edges)
          {
            if (boundary_only && !e.at_boundary)
              continue;
            bool on = true;
            for (const auto &p : points)
              on = on && on_edge(p, e);
            if (on)
              return &e;
          }
        return nullptr;
      };

      // Vertices: one on the axis, three (0, 45, 90 degrees) elsewhere.
      const std::vector<Point<2>>             &mv = meridian.get_vertices();
      std::vector<Point<3>>                    vertices;
      std::vector<std::array<unsigned int, 3>> ring(mv.size());
      const std::array<double, 3>              angles = {
                     {0., numbers::PI / 4., numbers::PI / 2.}};
      for (unsigned int v = 0; v < mv.size(); ++v)
        if (on_axis(mv[v]))
          {
            ring[v].fill(vertices.size());
            vertices.emplace_back(0., mv[v][1], 0.);
          }
        else
          for (unsigned int k = 0; k < 3; ++k)
            {
              ring[v][k] = vertices.size();
              vertices.push_back(revolved_point(mv[v], angles[k]));
            }

      // Inner-square vertices of the quarter disc swept by the edge from
      // axis vertex a to outer vertex b (radius r_b), one set per edge. A
      // horizontal edge sweeps a plane disc; an arc of a circle centred on
      // the axis a spherical cap, on which the vertices are then placed.
      std::map<std::pair<unsigned int, unsigned int>,
               std::array<unsigned int, 3>>
                 square;
      const auto square_vertices = [&](const unsigned int a,
                                       const unsigned int b) {
        auto it = square.find({a, b});
        if (it != square.end())
          return it->second;
        std::function<double(double)> height;
        if (std::abs(mv[a][1] - mv[b][1]) < tolerance)
          height = [y = mv[b][1]](const double) {
            return y;
          };
        else
          {
            const Edge *e = find_edge({mv[a], mv[b]}, false);
            AssertThrow(e != nullptr && e->spherical,
                        ExcMessage("revolve_quarter: the top and bottom "
                                   "edges of a meridian cell on the axis "
                                   "must be horizontal or arcs of circles "
                                   "centred on the axis."));
            const double side = mv[a][1] > e->centre[1] ? 1. : -1.;
            height            = [e, side](const double rho) {
              return e->centre[1] +
                     side * std::sqrt(
                              std::max(0., e->radius * e->radius - rho * rho));
            };
          }
        const double                r = mv[b][0];
        std::array<unsigned int, 3> s;
        s[0] = vertices.size(); // on theta = 0
        vertices.emplace_back(0.5 * r, height(0.5 * r), 0.);
        s[1] = vertices.size(); // on theta = 90 degrees
        vertices.emplace_back(0., height(0.5 * r), 0.5 * r);
        s[2] = vertices.size(); // the corner inside
        vertices.emplace_back(0.4 * r,
                              height(0.4 * std::sqrt(2.) * r),
                              0.4 * r);
        square.emplace(std::make_pair(a, b), s);
        return s;
      };

      std::vector<CellData<3>> cells;
      const auto add_hex = [&](const std::array<unsigned int, 8> &v,
                               const types::material_id           material) {
        // Orientation: the Jacobian of the trilinear map at the centre; a
        // negative one is mended by swapping the two layers.
        const auto d = [&](const unsigned int i, const unsigned int j) {
          return vertices[v[j]] - vertices[v[i]];
        };
        const Tensor<1, 3> dxi      = d(0, 1) + d(2, 3) + d(4, 5) + d(6, 7);
        const Tensor<1, 3> deta     = d(0, 2) + d(1, 3) + d(4, 6) + d(5, 7);
        const Tensor<1, 3> dzeta    = d(0, 4) + d(1, 5) + d(2, 6) + d(3, 7);
        const bool         inverted = cross_product_3d(dxi, deta) * dzeta < 0.;
        CellData<3>        cell;
        for (unsigned int i = 0; i < 8; ++i)
          cell.vertices[i] = v[inverted ? (i + 4) % 8 : i];
        cell.material_id = material;
        cells.push_back(cell);
      };
      for (const auto &cell : meridian.active_cell_iterators())
        {
          std::array<unsigned int, 4> v;
          unsigned int                n_axis = 0;
          for (unsigned int i = 0; i < 4; ++i)
            {
              v[i] = cell->vertex_index(i);
              n_axis += on_axis(mv[v[i]]);
            }
          AssertThrow(n_axis == 0 || n_axis == 2,
                      ExcMessage("revolve_quarter: a meridian cell touches "
                                 "the axis in a single vertex."));
          if (n_axis == 0)
            {
              for (unsigned int k = 0; k < 2; ++k)
                add_hex({{ring[v[0]][k],
                          ring[v[1]][k],
                          ring[v[2]][k],
                          ring[v[3]][k],
                          ring[v[0]][k + 1],
                          ring[v[1]][k + 1],
                          ring[v[2]][k + 1],
                          ring[v[3]][k + 1]}},
                        cell->material_id());
              continue;
            }
          // An axis cell: bottom and top edges from the axis to the outer
          // vertices b0, b1.
          std::array<unsigned int, 2> a, b;
          {
            std::vector<unsigned int> axis, outer;
            for (const unsigned int i : v)
              (on_axis(mv[i]) ? axis : outer).push_back(i);
            if (mv[axis[0]][1] > mv[axis[1]][1])
              std::swap(axis[0], axis[1]);
            if (mv[outer[0]][1] > mv[outer[1]][1])
              std::swap(outer[0], outer[1]);
            a = {{axis[0], axis[1]}};
            b = {{outer[0], outer[1]}};
          }
          std::array<std::array<unsigned int, 7>, 2> level;
          for (unsigned int l = 0; l < 2; ++l)
            {
              const auto s = square_vertices(a[l], b[l]);
              // O, A, B, C, D, F, E: centre, square on theta = 0, on 90,
              // inner corner, arc at 0, 45 and 90 degrees.
              level[l] = {{ring[a[l]][0],
                           s[0],
                           s[1],
                           s[2],
                           ring[b[l]][0],
                           ring[b[l]][1],
                           ring[b[l]][2]}};
            }
          // Plan quads (lexicographic): square O A B C, A D C F, B C E F.
          const std::array<std::array<unsigned int, 4>, 3> plan = {
            {{{0, 1, 2, 3}}, {{1, 4, 3, 5}}, {{2, 3, 6, 5}}}};
          for (const auto &q : plan)
            add_hex({{level[0][q[0]],
                      level[0][q[1]],
                      level[0][q[2]],
                      level[0][q[3]],
                      level[1][q[0]],
                      level[1][q[1]],
                      level[1][q[2]],
                      level[1][q[3]]}},
                    cell->material_id());
        }

      GridTools::invert_all_negative_measure_cells(vertices, cells);
      GridTools::consistently_order_cells(cells);
      result.clear();
      result.create_triangulation(vertices, cells, SubCellData());

      const auto same = [&](const Point<2> &p, const Point<2> &q) {
        return p.distance(q) < tolerance;
      };

      // Manifolds: revolved copies of the meridian manifolds in use (flat
      // included), and a sphere for each arc centred on the axis, numbered
      // from first_manifold_id.
      std::map<types::manifold_id, types::manifold_id> revolved_id;
      std::map<types::manifold_id, types::manifold_id> sphere_id;
      const auto                                       next_id = [&]() {
        return static_cast<types::manifold_id>(
          first_manifold_id + revolved_id.size() + sphere_id.size());
      };
      const auto sphere = [&](const Edge &e) {
        auto it = sphere_id.find(e.manifold_id);
        if (it != sphere_id.end())
          return it->second;
        const types::manifold_id id = next_id();
        sphere_id.emplace(e.manifold_id, id);
        result.set_manifold(id,
                            SphericalManifold<3>(
                              Point<3>(0., e.centre[1], 0.)));
        return id;
      };
      // The spherical edge that carries all of @p points, if any.
      const auto on_sphere =
        [&](const std::vector<Point<2>> &points) -> const Edge * {
        const Edge *e = find_edge(points, false);
        return e != nullptr && e->spherical ? e : nullptr;
      };
      const auto revolved = [&](const types::manifold_id meridian_id) {
        auto it = revolved_id.find(meridian_id);
        if (it != revolved_id.end())
          return it->second;
        const types::manifold_id id = next_id();
        revolved_id.emplace(meridian_id, id);
        if (meridian_id == numbers::flat_manifold_id)
          result.set_manifold(id, RevolvedManifold(FlatManifold<2>()));
        else
          result.set_manifold(id,
                              RevolvedManifold(
                                meridian.get_manifold(meridian_id)));
        return id;
      };

      // Cells, meridian planes and other plane faces stay flat: their new
      // points and mapping support points interpolate those of their
      // curved faces and lines.
      result.set_all_manifold_ids(numbers::flat_manifold_id);
      for (const auto &cell : result.active_cell_iterators())
        {
          for (const unsigned int l : cell->line_indices())
            {
              const auto     line = cell->line(l);
              const Point<2> m0   = meridian_point(line->vertex(0));
              const Point<2> m1   = meridian_point(line->vertex(1));
              if (same(m0, m1)) // an arc about the axis
                line->set_manifold_id(revolved(numbers::flat_manifold_id));
              else if (const Edge *e = on_sphere({m0, m1}))
                line->set_manifold_id(sphere(*e));
              else if (on_axis(m0) || on_axis(m1))
                line->set_manifold_id(numbers::flat_manifold_id);
              else if (std::abs(angle(line->vertex(0)) -
                                angle(line->vertex(1))) < 1e-12)
                {
                  const Edge *e = find_edge({m0, m1}, false);
                  line->set_manifold_id(e != nullptr ?
                                          revolved(e->manifold_id) :
                                          numbers::flat_manifold_id);
                }
              else
                line->set_manifold_id(numbers::flat_manifold_id);
            }
          for (const unsigned int f : cell->face_indices())
            {
              const auto            face = cell->face(f);
              std::vector<Point<2>> m;
              bool                  axis = false;
              for (const unsigned int i : face->vertex_indices())
                {
                  m.push_back(meridian_point(face->vertex(i)));
                  axis = axis || on_axis(m.back());
                }
              double theta_min = 10., theta_max = -10.;
              double y_min = 1e300, y_max = -1e300;
              for (const unsigned int i : face->vertex_indices())
                {
                  theta_min = std::min(theta_min, angle(face->vertex(i)));
                  theta_max = std::max(theta_max, angle(face->vertex(i)));
                  y_min     = std::min(y_min, m[i][1]);
                  y_max     = std::max(y_max, m[i][1]);
                }
              if (const Edge *e = on_sphere(m))
                face->set_manifold_id(sphere(*e));
              else if (axis)
                face->set_manifold_id(numbers::flat_manifold_id);
              else if (theta_max - theta_min < 1e-12)
                ; // a meridian plane
              else if (const Edge *e = find_edge(m, false))
                face->set_manifold_id(revolved(e->manifold_id));
              else if (y_max - y_min < tolerance) // a plane normal to the axis
                face->set_manifold_id(revolved(numbers::flat_manifold_id));
              else
                face->set_manifold_id(numbers::flat_manifold_id);

              if (!face->at_boundary())
                continue;
              bool z0 = true, x0 = true;
              for (const unsigned int i : face->vertex_indices())
                {
                  z0 = z0 && std::abs(face->vertex(i)[2]) < tolerance;
                  x0 = x0 && std::abs(face->vertex(i)[0]) < tolerance;
                }
              if (z0)
                face->set_boundary_id(plane_z0_id);
              else if (x0)
                face->set_boundary_id(plane_x0_id);
              else
                {
                  const Edge *e = find_edge(m, true);
                  AssertThrow(e != nullptr,
                              ExcMessage("revolve_quarter: a boundary face "
                                         "has no meridian boundary edge."));
                  face->set_boundary_id(e->boundary_id);
                }
            }
        }
    }
  } // namespace Geometry
} // namespace Common
