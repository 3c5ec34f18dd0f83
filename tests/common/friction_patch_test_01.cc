/*
 * Coulomb friction patch test, plane strain: two elastic blocks with
 * non-matching meshes, the lower one [0,1]x[0,1] mm and the upper one
 * [0,1]x[1,1.25] mm (thin, so that the moment of the shear does not lift
 * the trailing edge), both E = 70000 MPa and nu = 0.3 (equal materials: a
 * normal load alone creates no tangential traction). The lower block rests on
 * u_y = 0 with u_x = 0 at the origin; a uniform pressure p = 100 MPa acts on
 * the top of the upper block, whose top is then moved horizontally by a
 * prescribed displacement U. The contact (secondary: top of the lower block,
 * primary: bottom of the upper block) obeys exact Coulomb friction with
 * mu = 0.3, enforced with condensed dual Lagrange multipliers by the
 * semismooth Newton method, in load steps (U = 0, then U = 1e-3, 1e-2 mm; the
 * limit is reached near 5e-3 mm). For Q1 and Q2 the test checks (a) after the
 * normal load every node is closed and sticks, and the tangential contact force
 * equals the horizontal reaction on the top (1e-8 relative to mu p L; it is not
 * zero, since the top is held while the interface expands); (b) for a small U
 * every closed node sticks and the tangential contact force lies strictly below
 * mu p L and equals the horizontal reaction on the top (1e-8 relative); (c) for
 * a large U every closed node slips in the direction of U and the tangential
 * contact force equals mu p L and the reaction to 1e-8 relative: the interface
 * transmits exactly the Coulomb limit; (d) every step converges (iterations
 * printed).
 */

#include "two_block_patch.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

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
    explicit PatchTest(const unsigned int degree)
      : patch(degree, setting, Common::Contact::FrictionLaw::coulomb, mu)
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

    Patch<dim>                           patch;
    std::vector<types::global_dof_index> top_x_dofs;
  };



  // The lower block rests on u_y = 0 with u_x = 0 at the origin; the
  // x-displacement of the top of the upper block is prescribed (its value
  // is set per load step through ExternalLoad::prescribed_displacements).
  template <int dim>
  void
  PatchTest<dim>::setup_system()
  {
    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints);
    patch.add_lower_support(constraints);
    const FEValuesExtractors::Scalar          x_displacement(0);
    std::map<types::global_dof_index, double> top_x;
    VectorTools::interpolate_boundary_values(patch.mapping,
                                             patch.dof_handler,
                                             BoundaryIds::upper_top,
                                             Functions::ZeroFunction<dim>(dim),
                                             top_x,
                                             patch.fe.component_mask(
                                               x_displacement));
    for (const auto &entry : top_x)
      {
        top_x_dofs.push_back(entry.first);
        constraints.add_line(entry.first);
      }
    for (const auto &cell : patch.dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).norm() < 1e-10)
          {
            const auto dof = cell->vertex_dof_index(v, 0);
            if (!constraints.is_constrained(dof))
              constraints.add_line(dof);
          }
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
    const auto  &coupling    = patch.contact_problem->coupling();
    const auto  &enforcement = patch.contact_problem->enforcement();
    const double limit       = mu * setting.pressure * interface_length;

    // Tangential and normal contact force on the secondary surface, and
    // the status of the closed nodes.
    double       tangential = 0., normal = 0.;
    unsigned int n_closed = 0, n_stick = 0, n_slip_forward = 0;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      {
        const auto &row = coupling.row(j);
        normal += enforcement.pressure(j) * row.weight;
        tangential += enforcement.tangential_traction(j)[0] * row.weight;
        if (!enforcement.is_active(j))
          continue;
        ++n_closed;
        const auto status = enforcement.status(j);
        n_stick += (status == Common::Contact::PointStatus::stick);
        n_slip_forward += (status == Common::Contact::PointStatus::slip &&
                           enforcement.tangential_traction(j)[0] > 0.);
      }

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
    double reaction = 0.;
    for (const auto dof : top_x_dofs)
      reaction += internal(dof);

    deallog << name << ": U = " << U << " mm, Newton iterations "
            << statistics.n_iterations << ", converged "
            << yes_no(statistics.converged) << std::endl;
    deallog << "  closed nodes " << n_closed << ", sticking " << n_stick
            << ", slipping forward " << n_slip_forward << std::endl;
    deallog << "  normal contact force / (p L) = "
            << format(normal / (setting.pressure * interface_length))
            << std::endl;
    deallog << "  tangential contact force / (mu p L) = "
            << format(tangential / limit, 4) << std::endl;
    const bool balance = std::abs(reaction - tangential) < 1e-8 * limit;
    deallog << "  |reaction - tangential force| < 1e-8 mu p L: "
            << yes_no(balance) << std::endl;

    bool passed = statistics.converged && n_closed == coupling.n_rows();
    if (U == 0.)
      passed = passed && balance && n_stick == n_closed;
    else if (U < 1e-2)
      passed = passed && balance && n_stick == n_closed &&
               std::abs(tangential) < limit;
    else
      {
        const bool exact = std::abs(tangential - limit) < 1e-8 * limit;
        deallog << "  |tangential force - mu p L| < 1e-8 mu p L: "
                << yes_no(exact) << std::endl;
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
      [this, &U](const double,
                 std::map<types::global_dof_index, double> &values) {
        for (const auto dof : top_x_dofs)
          values[dof] = U;
      };
    ConditionalOStream                                quiet(std::cout, false);
    const std::vector<std::pair<std::string, double>> steps = {
      {"(a) normal load, stick", 0.},
      {"(b) small shift, stick", 1e-3},
      {"(c) large shift, slip at the Coulomb limit", 1e-2}};
    for (const auto &[name, shift] : steps)
      {
        U                     = shift;
        const auto statistics = patch.contact_problem->solve(1., load, quiet);
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
  std::ofstream                    logfile("output");
  deallog.attach(logfile);
  deallog.depth_console(0);

  for (const unsigned int degree : {1u, 2u})
    {
      PatchTest<2> test(degree);
      test.run();
    }
}
