/*
 * Algebraic multigrid with the rigid-body modes as near null space
 * ('cg amg' and 'gmres amg' of Common::Solvers::LinearSolver, modes from
 * Common::Physics::rigid_body_modes) on small-strain elasticity
 * (E = 210000 MPa, nu = 0.3) with Q2 elements: a 2D plane-strain strip
 * [0, 4] x [0, 1] of 32 x 8 cells and a 3D bar [0, 4] x [0, 1] x [0, 1] of
 * 12 x 3 x 3 cells, clamped at x = 0 and loaded by nodal forces of -1 N
 * along y.
 * (a) Every mode (dim translations, and 1 or 3 rotations) lies in the null
 *     space of the unconstrained stiffness matrix: |K m| <= 1e-10 |K| |m|
 *     (|K| the largest absolute row sum), which fails for any field that
 *     is not a rigid motion (e.g. a rotation with a misplaced component).
 * (b) 'cg amg' and 'gmres amg' with all modes, and 'cg amg' with the
 *     translations only, reproduce the MUMPS solution to 1e-8 relative
 *     (the Krylov tolerance is 1e-12), and so do the other direct solvers,
 *     'umfpack' and 'klu'.
 * (c) With the rotations the conjugate gradients need fewer iterations
 *     than with the translations only.
 * (d) A non-symmetric matrix, like a friction tangent (every free x row
 *     coupled to the y DoF of its node by 0.3 times its diagonal):
 *     'gmres amg' reproduces the MUMPS solution to 1e-8 relative.
 */

#include <common/physics/rigid_body.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/solvers/linear_solver.h>

#include "../tests.h"

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <string>

using namespace dealii;

namespace
{
  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }



  template <int dim>
  void
  run()
  {
    deallog << "dim = " << dim << std::endl;
    Triangulation<dim>        triangulation;
    std::vector<unsigned int> subdivisions(dim, dim == 2 ? 8 : 3);
    subdivisions[0] = (dim == 2 ? 32 : 12);
    Point<dim> corner;
    for (unsigned int d = 0; d < dim; ++d)
      corner[d] = 1.;
    corner[0] = 4.;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              subdivisions,
                                              Point<dim>(),
                                              corner,
                                              true);
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->set_material_id(0); // colorize also numbers the cells

    const FESystem<dim> fe(FE_Q<dim>(2), dim);
    const MappingQ<dim> mapping(2);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const IndexSet all = complete_index_set(dof_handler.n_dofs());

    std::map<types::material_id, Common::Materials::LinearElastic<dim>>
                                               materials;
    Common::Materials::LinearElasticParameters steel;
    steel.youngs_modulus = 210000.; // MPa
    steel.poisson_ratio  = 0.3;
    materials.emplace(0, Common::Materials::LinearElastic<dim>(steel));
    Common::Physics::SmallStrainElasticity<dim> physics(mapping, fe, materials);

    const auto modes =
      Common::Physics::rigid_body_modes(mapping, dof_handler, true);
    deallog << "modes: " << modes.size() << std::endl;

    // (a) The modes span the null space of the free body.
    {
      AffineConstraints<double> none;
      none.close();
      DynamicSparsityPattern dsp(all);
      DoFTools::make_sparsity_pattern(dof_handler, dsp);
      TrilinosWrappers::SparseMatrix K;
      K.reinit(all, all, dsp, MPI_COMM_WORLD);
      TrilinosWrappers::MPI::Vector u(all, MPI_COMM_WORLD), r(u), m(u), Km(u);
      physics.assemble_system(dof_handler, none, u, K, r);
      K.compress(VectorOperation::add);
      double worst = 0.;
      for (const auto &mode : modes)
        {
          for (unsigned int i = 0; i < mode.size(); ++i)
            m(i) = mode[i];
          K.vmult(Km, m);
          worst =
            std::max(worst, Km.l2_norm() / (K.linfty_norm() * m.l2_norm()));
        }
      deallog << "(a) |K m| / (|K| |m|) <= 1e-10: " << pass_fail(worst < 1e-10)
              << std::endl;
    }

    // The clamped bar.
    AffineConstraints<double> constraints;
    VectorTools::interpolate_boundary_values(mapping,
                                             dof_handler,
                                             0,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();
    DynamicSparsityPattern dsp(all);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    TrilinosWrappers::SparseMatrix A;
    A.reinit(all, all, dsp, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector u(all, MPI_COMM_WORLD), b(u);
    physics.assemble_system(dof_handler, constraints, u, A, b);
    A.compress(VectorOperation::add);
    b = 0.;
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          if (fe.system_to_component_index(i).first == 1 &&
              !constraints.is_constrained(dof_indices[i]))
            b(dof_indices[i]) = -1.; // N
      }

    Common::Solvers::LinearSolverParameters parameters;
    parameters.tolerance      = 1e-12;
    parameters.max_iterations = 1000;
    parameters.type           = Common::Solvers::LinearSolverType::mumps;
    TrilinosWrappers::MPI::Vector reference(u);
    Common::Solvers::solve_linear_system(parameters, A, reference, b);

    const std::vector<std::vector<double>> translations(modes.begin(),
                                                        modes.begin() + dim);
    const auto solve = [&](const Common::Solvers::LinearSolverType type,
                           const std::vector<std::vector<double>> &near_null,
                           const std::string                      &label) {
      parameters.type = type;
      Common::Solvers::LinearSolver solver(parameters);
      solver.set_near_null_space(near_null, dim);
      TrilinosWrappers::MPI::Vector x(u);
      const unsigned int            iterations = solver.solve(A, x, b);
      x -= reference;
      deallog << label << " agrees with MUMPS to 1e-8: "
              << pass_fail(x.l2_norm() <= 1e-8 * reference.l2_norm())
              << std::endl;
      return iterations;
    };
    const unsigned int cg_modes =
      solve(Common::Solvers::LinearSolverType::cg_amg, modes, "(b) cg amg");
    solve(Common::Solvers::LinearSolverType::gmres_amg, modes, "(b) gmres amg");
    solve(Common::Solvers::LinearSolverType::umfpack, modes, "(b) umfpack");
    solve(Common::Solvers::LinearSolverType::klu, modes, "(b) klu");
    const unsigned int cg_translations =
      solve(Common::Solvers::LinearSolverType::cg_amg,
            translations,
            "(b) cg amg with the translations only");
    deallog << "(c) fewer iterations with the rotations: "
            << pass_fail(cg_modes < cg_translations) << std::endl;

    // (d) Non-symmetric.
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          if (fe.system_to_component_index(i).first == 0 &&
              !constraints.is_constrained(dof_indices[i]))
            {
              const unsigned int j = fe.component_to_system_index(
                1,
                fe.system_to_component_index(i).second);
              A.set(dof_indices[i],
                    dof_indices[j],
                    0.3 * A.diag_element(dof_indices[i]));
            }
      }
    A.compress(VectorOperation::insert);
    parameters.type = Common::Solvers::LinearSolverType::mumps;
    Common::Solvers::solve_linear_system(parameters, A, reference, b);
    solve(Common::Solvers::LinearSolverType::gmres_amg,
          modes,
          "(d) non-symmetric: gmres amg");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  run<2>();
  run<3>();
}
