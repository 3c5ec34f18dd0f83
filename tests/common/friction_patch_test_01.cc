/*
 * Coulomb friction patch test, plane strain and 3D: two elastic blocks with
 * non-matching meshes, the lower one [0,1]^dim mm and the upper one of
 * height 0.25 mm on top of it (thin, so that the moment of the shear does
 * not lift the trailing edge), both E = 70000 MPa and nu = 0.3 (equal
 * materials: a normal load alone creates no tangential traction). The
 * lower block rests on zero vertical displacement with u_x = 0 at the
 * origin in 2D, and is clamped at its bottom in 3D (a point support is too
 * soft there); a uniform pressure p = 100 MPa acts on the top of
 * the upper block, whose top is then moved horizontally by a prescribed
 * displacement U d (d = e_x in 2D, (0.8, 0.6, 0) in 3D, so that the slip
 * runs oblique to both meshes). The contact (secondary: top of the lower
 * block, primary: bottom of the upper block) obeys exact Coulomb friction
 * with mu = 0.3, enforced with condensed dual Lagrange multipliers by the
 * semismooth Newton method, in load steps (U = 0, then U = 1e-3, 1e-2 mm;
 * the limit is reached near 5e-3 mm). For Q1 and Q2 the test checks (a)
 * after the normal load every paired node is closed and sticks, and the
 * tangential contact force equals the horizontal reaction on the top (1e-8
 * relative to mu p A; it is not zero, since the top is held while the
 * interface expands); (b) for a small U every closed node sticks and the
 * tangential contact force lies strictly below mu p A and equals the
 * horizontal reaction on the top (1e-8 relative); (c) for a large U every
 * closed node slips forward (t . d > 0) and is everywhere at its Coulomb
 * limit, |t_j| = mu p_j to 1e-8 relative, the tangential contact force
 * equals the reaction, and in 2D it is mu p A d (in 3D the slip direction
 * varies slightly over the interface); (d) every step converges
 * (iterations printed; the 3D slip direction turns, which the Newton
 * method linearises). The 3D checks run again with parts of both contact
 * surfaces refined once more (TwoBlockPatch::Patch::make_grid_and_dofs()),
 * so that both carry hanging nodes.
 */

#include "../tests.h"
#include "two_block_patch.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include <array>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace dealii;
using namespace TwoBlockPatch;

namespace
{
  // Equal materials; the upper block is thin.
  const Setting    setting{70000., 70000., 0.3, 0.25, 100.};
  constexpr double mu = 0.3;



  template <int dim>
  class PatchTest
  {
  public:
    PatchTest(const unsigned int degree, const bool refine_locally = false)
      : patch(degree, setting, Common::Contact::FrictionLaw::coulomb, mu)
      , refine_locally(refine_locally)
    {}

    void
    run();

  private:
    void
    setup_system();
    void
    check_step(const std::string                       &name,
               const double                             U,
               const Common::Solvers::NewtonStatistics &statistics);

    Patch<dim> patch;
    /** Refine parts of both contact surfaces (hanging nodes in 3D). */
    const bool refine_locally;
    /** Horizontal DoFs of the top of the upper block, per component. */
    std::array<std::vector<types::global_dof_index>, dim - 1> top_dofs;
  };



  // Direction of the prescribed shift: oblique to both meshes in 3D.
  template <int dim>
  Tensor<1, dim>
  shift_direction()
  {
    Tensor<1, dim> d;
    d[0] = dim == 2 ? 1. : 0.8;
    if (dim == 3)
      d[1] = 0.6;
    return d;
  }



  // The lower block rests on zero vertical displacement; the horizontal
  // displacement of the top of the upper block is prescribed (set per load
  // step through ExternalLoad::prescribed_displacements).
  template <int dim>
  void
  PatchTest<dim>::setup_system()
  {
    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints, refine_locally);
    patch.add_lower_support(constraints);
    for (unsigned int c = 0; c < dim - 1; ++c)
      {
        const FEValuesExtractors::Scalar          component(c);
        std::map<types::global_dof_index, double> top;
        VectorTools::interpolate_boundary_values(
          patch.mapping,
          patch.dof_handler,
          BoundaryIds::upper_top,
          Functions::ZeroFunction<dim>(dim),
          top,
          patch.fe.component_mask(component));
        for (const auto &entry : top)
          {
            top_dofs[c].push_back(entry.first);
            constraints.add_line(entry.first);
          }
      }
    // 2D: u_x = 0 at the origin. 3D: the whole bottom is clamped, since a
    // point support is too soft in 3D to hold the lower block.
    if (dim == 2)
      {
        for (const auto &cell : patch.dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).norm() < 1e-10)
              {
                const auto dof = cell->vertex_dof_index(v, 0);
                if (!constraints.is_constrained(dof))
                  constraints.add_line(dof);
              }
      }
    else
      VectorTools::interpolate_boundary_values(patch.mapping,
                                               patch.dof_handler,
                                               BoundaryIds::lower_bottom,
                                               Functions::ZeroFunction<dim>(
                                                 dim),
                                               constraints);
    constraints.close();
    patch.setup_problem(constraints);
  }



  template <int dim>
  void
  PatchTest<dim>::check_step(
    const std::string                       &name,
    const double                             U,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const auto          &coupling    = patch.contact_problem->coupling();
    const auto          &enforcement = patch.contact_problem->enforcement();
    const double         area        = interface_area(setting, dim);
    const double         limit       = mu * setting.pressure * area;
    const Tensor<1, dim> d           = shift_direction<dim>();

    // Tangential and normal contact force on the secondary surface, and
    // the status of the closed nodes; a node slips forward if its traction
    // points along d (to 1e-8).
    Tensor<1, dim> tangential_force;
    double         normal = 0., max_limit_error = 0.;
    unsigned int   n_closed = 0, n_stick = 0, n_slip_forward = 0;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      {
        const auto          &row = coupling.row(j);
        const Tensor<1, dim> t   = enforcement.tangential_traction(j);
        normal += enforcement.pressure(j) * row.weight;
        tangential_force += t * row.weight;
        if (!enforcement.is_active(j))
          continue;
        ++n_closed;
        const auto status = enforcement.status(j);
        n_stick += (status == Common::Contact::PointStatus::stick);
        n_slip_forward +=
          (status == Common::Contact::PointStatus::slip && t * d > 0.);
        max_limit_error =
          std::max(max_limit_error,
                   std::abs(t.norm() - mu * enforcement.pressure(j)) /
                     (mu * setting.pressure));
      }
    const double tangential = tangential_force * d;

    // Horizontal reaction on the top: the internal force on its x-DoFs.
    TrilinosWrappers::MPI::Vector internal(
      patch.dof_handler.locally_owned_dofs(),
      patch.mpi_communicator);
    AffineConstraints<double> none;
    none.close();
    patch.physics->assemble_internal_force(
      patch.dof_handler,
      none,
      patch.contact_problem->displacement(),
      internal);
    internal.compress(VectorOperation::add);
    Tensor<1, dim> reaction;
    for (unsigned int c = 0; c < dim - 1; ++c)
      for (const auto dof : top_dofs[c])
        reaction[c] += internal(dof);

    deallog << name << ": U = " << U << " mm, Newton iterations "
            << statistics.n_iterations << ", converged "
            << yes_no(statistics.converged) << std::endl;
    deallog << "  closed nodes " << n_closed << ", sticking " << n_stick
            << ", slipping forward " << n_slip_forward << std::endl;
    deallog << "  normal contact force / (p A) = "
            << format(normal / (setting.pressure * area)) << std::endl;
    // Round-off level (no tangential load) is printed as a bound.
    deallog << "  tangential contact force along d / (mu p A) = "
            << (std::abs(tangential / limit) < 1e-12 ?
                  std::string("below 1e-12") :
                  format(tangential / limit, 4))
            << std::endl;
    const bool balance = (reaction - tangential_force).norm() < 1e-8 * limit;
    deallog << "  |reaction - tangential force| < 1e-8 mu p A: "
            << yes_no(balance) << std::endl;

    unsigned int n_paired = 0;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      n_paired += coupling.row(j).has_partner;
    bool passed = statistics.converged && n_closed == n_paired;
    if (U == 0.)
      passed = passed && balance && n_stick == n_closed;
    else if (U < 1e-2)
      passed = passed && balance && n_stick == n_closed &&
               std::abs(tangential) < limit;
    else
      {
        // Every node at its Coulomb limit, |t_j| = mu p_j; in 2D, where
        // all slip along d, the total is mu p A d.
        bool exact = max_limit_error < 1e-8;
        deallog << "  max | |t_j| - mu p_j | < 1e-8 mu p: " << yes_no(exact)
                << std::endl;
        if (dim == 2)
          {
            const bool total =
              (tangential_force - limit * d).norm() < 1e-8 * limit;
            deallog << "  |tangential force - mu p A d| < 1e-8 mu p A: "
                    << yes_no(total) << std::endl;
            exact = exact && total;
          }
        passed = passed && balance && exact && n_slip_forward == n_closed;
      }
    deallog << "  " << name << ": " << pass_fail(passed) << std::endl;
  }



  template <int dim>
  void
  PatchTest<dim>::run()
  {
    setup_system();
    Common::Problems::ExternalLoad load = patch.external_load();
    double                         U    = 0.;
    load.prescribed_displacements =
      [this, &U](const Common::Solvers::LoadState &,
                 std::map<types::global_dof_index, double> &values) {
        const Tensor<1, dim> d = shift_direction<dim>();
        for (unsigned int c = 0; c < dim - 1; ++c)
          for (const auto dof : top_dofs[c])
            values[dof] = U * d[c];
      };
    ConditionalOStream                                quiet(std::cout, false);
    const std::vector<std::pair<std::string, double>> steps = {
      {"(a) normal load, stick", 0.},
      {"(b) small shift, stick", 1e-3},
      {"(c) large shift, slip at the Coulomb limit", 1e-2}};
    for (const auto &[name, shift] : steps)
      {
        U                     = shift;
        const auto statistics = patch.contact_problem->solve(
          Common::Solvers::LoadState::with_load_factor(1.),
          load,
          quiet);
        if (!statistics.converged)
          deallog << "Newton failure: " << statistics.failure << std::endl;
        patch.contact_problem->commit();
        check_step(name, U, statistics);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();

  deallog << "Plane strain" << std::endl;
  for (const unsigned int degree : {1u, 2u})
    {
      PatchTest<2> test(degree);
      test.run();
    }
  deallog << "3D, shift along (0.8, 0.6, 0)" << std::endl;
  for (const unsigned int degree : {1u, 2u})
    {
      PatchTest<3> test(degree);
      test.run();
    }
  deallog << "3D with hanging nodes on both contact surfaces" << std::endl;
  for (const unsigned int degree : {1u, 2u})
    {
      PatchTest<3> test(degree, true);
      test.run();
    }
}
