/*
 * Axisymmetric small-strain elasticity (Physics::Kinematics::axisymmetric)
 * against Lame's thick-walled cylinder: inner radius 1 mm, outer radius
 * 2 mm, height 1 mm with u_z = 0 on top and bottom (plane strain along the
 * axis), E = 70000 MPa, nu = 0.3, internal pressure p = 100 MPa applied
 * with Physics::add_boundary_pressure. Exact:
 * u_r = (1 + nu) p a^2 / (E (b^2 - a^2)) ((1 - 2 nu) r + b^2 / r).
 * The displacement is not in the finite element space (b^2/r), so the test
 * checks that the maximum nodal error of u_r relative to u_r(a) falls below
 * 1e-3 (Q1) and 1e-5 (Q2) on 4 x 2 cells refined twice, and that it
 * falls with refinement at least 3.5 (Q1) and 7 (Q2) times per halving;
 * and that the reaction on the inner wall balances the applied force
 * p 2 pi a h to 1e-10.
 */

#include <common/materials/linear_elastic.h>
#include <common/physics/boundary_loads.h>
#include <common/physics/small_strain_elasticity.h>

#include "../tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/logstream.h>
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
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>

using namespace dealii;

namespace
{
  constexpr double a = 1., b = 2., height = 1., E = 70000., nu = 0.3, p = 100.;

  double
  exact_ur(const double r)
  {
    return (1. + nu) * p * a * a / (E * (b * b - a * a)) *
           ((1. - 2. * nu) * r + b * b / r);
  }

  // Largest nodal error of u_r relative to u_r(a).
  double
  solve(const unsigned int degree, const unsigned int n_refinements)
  {
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {4u, 2u},
                                              Point<2>(a, 0.),
                                              Point<2>(b, height),
                                              true);
    // Colorized ids: 0 inner wall, 1 outer wall, 2 bottom, 3 top; one
    // material.
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    tria.refine_global(n_refinements);

    const FESystem<2> fe(FE_Q<2>(degree), 2);
    const MappingQ<2> mapping(degree);
    DoFHandler<2>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);

    AffineConstraints<double>        constraints;
    const FEValuesExtractors::Scalar z_displacement(1);
    for (const types::boundary_id id : {2, 3})
      VectorTools::interpolate_boundary_values(mapping,
                                               dof_handler,
                                               id,
                                               Functions::ZeroFunction<2>(2),
                                               constraints,
                                               fe.component_mask(
                                                 z_displacement));
    constraints.close();

    Common::Materials::LinearElasticParameters parameters;
    parameters.youngs_modulus = E;
    parameters.poisson_ratio  = nu;
    std::map<types::material_id, Common::Materials::LinearElastic<2>> laws;
    laws.emplace(0, Common::Materials::LinearElastic<2>(parameters));
    Common::Physics::SmallStrainElasticity<2>
      physics(mapping, fe, laws, Common::Physics::Kinematics::axisymmetric);

    const IndexSet         owned = dof_handler.locally_owned_dofs();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, dsp, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector u(owned, MPI_COMM_WORLD), rhs(u);
    physics.assemble_system(dof_handler, constraints, u, matrix, rhs);
    Common::Physics::add_boundary_pressure(
      mapping,
      dof_handler,
      0,
      p,
      Common::Physics::Kinematics::axisymmetric,
      constraints,
      rhs);
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    SolverControl                                  control(1, 0., false, false);
    TrilinosWrappers::SolverDirect::AdditionalData data;
    TrilinosWrappers::SolverDirect                 direct(control, data);
    direct.solve(matrix, u, rhs);
    constraints.distribute(u);

    // Nodal errors at the vertices (and Q2 midpoints) via support points.
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    double max_error = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_component_index(i).first == 0)
            {
              const double r = points[dofs[i]][0];
              max_error =
                std::max(max_error,
                         std::abs(u(dofs[i]) - exact_ur(r)) / exact_ur(a));
            }
      }

    // Reaction on the inner wall: the internal force on its r-DoFs.
    TrilinosWrappers::MPI::Vector internal(owned, MPI_COMM_WORLD);
    AffineConstraints<double>     none;
    none.close();
    physics.assemble_internal_force(dof_handler, none, u, internal);
    internal.compress(VectorOperation::add);
    std::map<types::global_dof_index, double> inner;
    VectorTools::interpolate_boundary_values(mapping,
                                             dof_handler,
                                             0,
                                             Functions::ZeroFunction<2>(2),
                                             inner,
                                             fe.component_mask(
                                               FEValuesExtractors::Scalar(0)));
    double reaction = 0.;
    for (const auto &entry : inner)
      reaction += internal(entry.first);
    const double applied = p * 2. * numbers::PI * a * height;
    deallog << "Q" << degree << ", " << n_refinements
            << " refinements: |reaction / applied force - 1| < 1e-10: "
            << (std::abs(reaction / applied - 1.) < 1e-10 ? "PASS" : "FAIL")
            << std::endl;
    return max_error;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();

  for (const unsigned int degree : {1u, 2u})
    {
      const double coarse = solve(degree, 1);
      const double fine   = solve(degree, 2);
      const double bound  = degree == 1 ? 1e-3 : 1e-5;
      const double rate   = degree == 1 ? 3.5 : 7.;
      deallog << "Q" << degree << ": max nodal error of u_r / u_r(a) < "
              << std::scientific << std::setprecision(0) << bound << ": "
              << (fine < bound ? "PASS" : "FAIL") << std::endl;
      deallog << "Q" << degree << ": error falls at least " << std::fixed
              << std::setprecision(1) << rate << " times per halving: "
              << (coarse / fine > rate ? "PASS" : "FAIL") << std::endl;
    }
}
