/*
 * Displacement profiles along a boundary (common/physics/boundary_
 * displacement.h): the field u(x) = (0.1 x y + 0.2, 0.05 y - 0.3 x^2 [, 0.2 z])
 * (mm) is interpolated onto (1) the quarter of an annulus with radii 1 and
 * 2 mm (Q2 element, Q2 mapping, 3 x 2 coarse cells refined once; outer arc
 * = boundary id 1) and (2) the box [0,4] x [0,1] x [0,2] mm (Q1, 4 x 1 x 2
 * cells; top face y = 1 = boundary id 3). The samples must be the support
 * points of the boundary faces, each once: 2 * 6 + 1 = 13 on the arc and
 * 5 * 3 = 15 on the top face; the arc samples lie on the circle of radius 2
 * (1e-12 mm), are sorted by x, and carry the exact field (1e-12 mm, the
 * interpolant is exact at support points). The test runs on one and on two
 * processes (parallel::shared triangulation): the gathered profile must be
 * the same.
 */

#include <common/physics/boundary_displacement.h>

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>

using namespace dealii;

namespace
{
  template <int dim>
  class Field : public Function<dim>
  {
  public:
    Field()
      : Function<dim>(dim)
    {}

    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      if (c == 0)
        return 0.1 * p[0] * p[1] + 0.2;
      if (c == 1)
        return 0.05 * p[1] - 0.3 * p[0] * p[0];
      return 0.2 * p[2];
    }
  };



  /** Sample boundary @p id and log the count, the order, the largest
   * field error and, if @p radius > 0, the largest distance from the
   * circle of that radius. */
  template <int dim>
  void
  check(parallel::shared::Triangulation<dim> &tria,
        const unsigned int                    degree,
        const types::boundary_id              id,
        const double                          radius)
  {
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    const MappingQ<dim> mapping(degree);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    TrilinosWrappers::MPI::Vector owned(dof_handler.locally_owned_dofs(),
                                        MPI_COMM_WORLD);
    VectorTools::interpolate(mapping, dof_handler, Field<dim>(), owned);
    // Fully replicated, as the contact problem stores its displacement.
    TrilinosWrappers::MPI::Vector u(complete_index_set(dof_handler.n_dofs()),
                                    MPI_COMM_WORLD);
    u = owned;

    const auto samples =
      Common::Physics::boundary_displacements(mapping, dof_handler, u, id);
    const Field<dim> field;
    double           field_error = 0., radius_error = 0.;
    bool             sorted = true;
    for (unsigned int i = 0; i < samples.size(); ++i)
      {
        for (unsigned int c = 0; c < dim; ++c)
          field_error = std::max(field_error,
                                 std::abs(samples[i].displacement[c] -
                                          field.value(samples[i].position, c)));
        if (radius > 0.)
          radius_error =
            std::max(radius_error,
                     std::abs(samples[i].position.norm() - radius));
        if (i > 0 && samples[i].position[0] < samples[i - 1].position[0])
          sorted = false;
      }
    deallog << dim << "D, Q" << degree << ", boundary " << id << ": "
            << samples.size()
            << " samples, sorted by x: " << (sorted ? "yes" : "no")
            << ", field error below 1e-12: "
            << (field_error < 1e-12 ? "yes" : "no");
    if (radius > 0.)
      deallog << ", on the circle (1e-12): "
              << (radius_error < 1e-12 ? "yes" : "no");
    deallog << std::endl;
    deallog << "  first sample at " << samples.front().position << ", last at "
            << samples.back().position << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    initlog(6);

  {
    parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::quarter_hyper_shell(tria, Point<2>(), 1., 2., 3, true);
    tria.refine_global(1);
    check(tria, 2, 1, 2.);
  }
  {
    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {4u, 1u, 2u},
                                              Point<3>(),
                                              Point<3>(4., 1., 2.),
                                              true);
    check(tria, 1, 3, 0.);
  }
}
