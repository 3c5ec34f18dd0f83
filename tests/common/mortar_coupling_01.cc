// Checks Common::Contact::MortarCoupling on two stacked rectangular blocks
// with non-matching interface meshes: the lower block [0,2]x[0,1] (3
// subdivisions in x) and the upper block [0,2]x[1+g0,2+g0] (5 subdivisions
// in x), joined with Common::Geometry::join_bodies; the lower block's top
// is the secondary surface, the upper block's bottom the primary surface;
// FE_Q(p)^2 with MappingQ(p), p = 1 and 2, coarse and once refined, with
// initial gap g0 = 0 (touching) and g0 = 0.1. Checked: (a) for every
// secondary node with a partner, sum_k M_jk = D_j (dual basis: the primary
// shape functions sum to one); (b) sum_j D_j equals the interface length
// 2; (c) linear exactness of the weighted gap: for a displacement that is
// affine on each body (one continuous affine field interpolated with
// VectorTools::interpolate, and different affine fields on the two bodies),
// weighted_gap(j)/D_j equals the exact gap g0 + n.(u_primary(x_j + g0 e_y)
// - u_secondary(x_j)) at the node, and relative_displacement(j) equals
// u_primary(x_j + g0 e_y) - u_secondary(x_j); with zero displacement
// weighted_gap(j)/D_j = g0. A node table (position, D_j, sum_k M_jk, number
// of primary partners, weighted gap / D_j) is printed for the coarse
// meshes.

#include <common/contact/contact_search.h>
#include <common/contact/contact_surface.h>
#include <common/contact/mortar_coupling.h>
#include <common/geometry/two_body_meshes.h>

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

using namespace dealii;

namespace
{
  constexpr unsigned int secondary_id = 1;
  constexpr unsigned int primary_id   = 2;
  constexpr double       width        = 2.;

  // Affine displacement of the lower (secondary) body.
  Tensor<1, 2>
  u_lower(const Point<2> &p)
  {
    return Tensor<1, 2>(
      {0.01 * p[0] + 0.002 * p[1], -0.003 + 0.004 * p[0] + 0.005 * p[1]});
  }

  // A different affine displacement of the upper (primary) body.
  Tensor<1, 2>
  u_upper(const Point<2> &p)
  {
    return u_lower(p) + Tensor<1, 2>({0.001 + 0.002 * p[0] - 0.003 * p[1],
                                      0.002 - 0.004 * p[0] + 0.001 * p[1]});
  }

  class AffineField : public Function<2>
  {
  public:
    AffineField()
      : Function<2>(2)
    {}

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      return u_lower(p)[component];
    }
  };

  // Set u at every support point from the affine field of the cell's body.
  void
  interpolate_per_body(const DoFHandler<2> &dof_handler,
                       const MappingQ<2>   &mapping,
                       Vector<double>      &u)
  {
    const FiniteElement<2>              &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const Point<2> p = mapping.transform_unit_to_real_cell(
              cell,
              fe.get_unit_support_points()[i]);
            const unsigned int c = fe.system_to_component_index(i).first;
            u(dof_indices[i]) =
              (cell->material_id() == 0 ? u_lower(p) : u_upper(p))[c];
          }
      }
  }



  void
  run(const unsigned int degree,
      const unsigned int n_refinements,
      const double       initial_gap,
      const bool         print_table)
  {
    deallog << "Q" << degree << ", refinements " << n_refinements
            << ", initial gap " << initial_gap << std::endl;

    Triangulation<2> lower, upper, triangulation;
    GridGenerator::subdivided_hyper_rectangle(lower,
                                              {3, 2},
                                              Point<2>(0., 0.),
                                              Point<2>(width, 1.));
    GridGenerator::subdivided_hyper_rectangle(upper,
                                              {5, 2},
                                              Point<2>(0., 1. + initial_gap),
                                              Point<2>(width,
                                                       2. + initial_gap));
    for (const auto &cell : upper.active_cell_iterators())
      cell->set_material_id(1);
    Common::Geometry::join_bodies<2>({&lower, &upper}, triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<2> c = cell->face(f)->center();
            if (cell->material_id() == 0 && std::abs(c[1] - 1.) < 1e-12)
              cell->face(f)->set_boundary_id(secondary_id);
            else if (cell->material_id() == 1 &&
                     std::abs(c[1] - 1. - initial_gap) < 1e-12)
              cell->face(f)->set_boundary_id(primary_id);
            else
              cell->face(f)->set_boundary_id(0);
          }
    triangulation.refine_global(n_refinements);

    const FESystem<2> fe(FE_Q<2>(degree), 2);
    const MappingQ<2> mapping(degree);
    DoFHandler<2>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);

    const Common::Contact::ContactSurface<2> secondary(dof_handler,
                                                       mapping,
                                                       secondary_id);
    const Common::Contact::ContactSurface<2> primary(dof_handler,
                                                     mapping,
                                                     primary_id);
    const Common::Contact::ContactSearch<2>  search(primary, 0.);
    Common::Contact::MortarCoupling<2>       coupling;
    coupling.reinit(secondary, primary, search, 0.5);

    Vector<double> zero(dof_handler.n_dofs());
    Vector<double> continuous(dof_handler.n_dofs());
    VectorTools::interpolate(mapping, dof_handler, AffineField(), continuous);
    Vector<double> per_body(dof_handler.n_dofs());
    interpolate_per_body(dof_handler, mapping, per_body);

    // Exact gap and relative displacement at secondary node j: the primary
    // point facing x_j is x_j + g0 e_y.
    const auto exact_relative_displacement =
      [&](const unsigned int                                   j,
          const std::function<Tensor<1, 2>(const Point<2> &)> &u_primary,
          const std::function<Tensor<1, 2>(const Point<2> &)> &u_secondary) {
        const Point<2> x = secondary.node(j).reference_position;
        return u_primary(x + Tensor<1, 2>({0., initial_gap})) - u_secondary(x);
      };
    const auto zero_field = [](const Point<2> &) {
      return Tensor<1, 2>();
    };

    unsigned int          n_partner        = 0;
    double                sum_D            = 0.;
    double                max_sum_M_error  = 0.;
    bool                  normals_ok       = true;
    double                max_gap_error[3] = {0., 0., 0.};
    double                max_rel_error[3] = {0., 0., 0.};
    const Vector<double> *fields[3]        = {&zero, &continuous, &per_body};
    const std::function<Tensor<1, 2>(const Point<2> &)> primary_fields[3] =
      {zero_field, u_lower, u_upper};
    const std::function<Tensor<1, 2>(const Point<2> &)> secondary_fields[3] =
      {zero_field, u_lower, u_lower};

    std::vector<unsigned int> order(coupling.n_rows());
    for (unsigned int j = 0; j < order.size(); ++j)
      order[j] = j;
    std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
      return secondary.node(a).reference_position[0] <
             secondary.node(b).reference_position[0];
    });

    if (print_table)
      deallog << "  x         D_j       sum_k M_jk  partners  g_j/D_j   "
                 "exact (per-body field)"
              << std::endl;
    for (const unsigned int j : order)
      {
        const auto &row = coupling.row(j);
        sum_D += row.weight;
        if (!row.has_partner)
          continue;
        ++n_partner;
        normals_ok =
          normals_ok && (row.normal - Tensor<1, 2>({0., 1.})).norm() < 1e-14;
        double sum_M = 0.;
        for (const auto &[k, M] : row.primary_weights)
          sum_M += M;
        max_sum_M_error =
          std::max(max_sum_M_error, std::abs(sum_M - row.weight) / row.weight);

        for (unsigned int i = 0; i < 3; ++i)
          {
            const Tensor<1, 2> rel =
              exact_relative_displacement(j,
                                          primary_fields[i],
                                          secondary_fields[i]);
            const double exact_gap = initial_gap + rel[1];
            max_gap_error[i] =
              std::max(max_gap_error[i],
                       std::abs(coupling.weighted_gap(j, *fields[i]) /
                                  row.weight -
                                exact_gap));
            max_rel_error[i] = std::max(
              max_rel_error[i],
              (coupling.relative_displacement(j, *fields[i]) - rel).norm());
          }
        if (print_table)
          deallog << "  " << secondary.node(j).reference_position[0] << "  "
                  << row.weight << "  " << sum_M << "    "
                  << row.primary_weights.size() << "         "
                  << coupling.weighted_gap(j, per_body) / row.weight << "  "
                  << initial_gap +
                       exact_relative_displacement(j, u_upper, u_lower)[1]
                  << std::endl;
      }

    deallog << "  secondary nodes " << coupling.n_rows() << ", with partner "
            << n_partner << std::endl;
    deallog << "  nodal normals = (0, 1): " << (normals_ok ? "yes" : "no")
            << std::endl;
    deallog << "  sum_j D_j = " << sum_D << ", |sum_j D_j - " << width
            << "| < 1e-12: " << (std::abs(sum_D - width) < 1e-12 ? "yes" : "no")
            << std::endl;
    deallog << "  max |sum_k M_jk - D_j|/D_j < 1e-12: "
            << (max_sum_M_error < 1e-12 ? "yes" : "no") << std::endl;
    const char *names[3] = {"zero displacement",
                            "continuous affine field",
                            "per-body affine fields"};
    for (unsigned int i = 0; i < 3; ++i)
      deallog << "  " << names[i] << ": max |g_j/D_j - exact| < 1e-12: "
              << (max_gap_error[i] < 1e-12 ? "yes" : "no")
              << ", max |relative displacement - exact| < 1e-12: "
              << (max_rel_error[i] < 1e-12 ? "yes" : "no") << std::endl;
  }
} // namespace

int
main()
{
  initlog();

  for (const unsigned int degree : {1u, 2u})
    for (const double initial_gap : {0., 0.1})
      for (const unsigned int n_refinements : {0u, 1u})
        run(degree, n_refinements, initial_gap, n_refinements == 0);
}
