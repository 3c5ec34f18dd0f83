/*
 * Non-matching contact patch test, plane strain: two elastic blocks, the
 * lower one [0,1]x[0,1] mm (E = 70000 MPa) and the upper one [0,1]x[1,2] mm
 * (E = 210000 MPa), both nu = 0.3, meshed with 4x4 and 3x3 coarse cells (one
 * global refinement), so that the meshes do not match along the interface
 * y = 1. The lower block rests on u_y = 0, both left sides are symmetry
 * lines (u_x = 0), and a uniform pressure p = 100 MPa acts on the top of the
 * upper block. The contact (secondary: top of the lower block, primary:
 * bottom of the upper block) is frictionless and enforced with condensed
 * dual Lagrange multipliers by the semismooth Newton method. The different
 * moduli make the interface slide. The exact solution, a uniform stress
 * sigma_yy = -p, lies in the finite element space, so for Q1 and Q2 the test
 * checks that (a) every active secondary node's recovered pressure equals p
 * to 1e-8 relative, (b) at every quadrature point of both bodies
 * sigma_yy = -p and sigma_xx = sigma_xy = 0 to 1e-8 relative to p, (c) the
 * total contact force equals p times the interface length to 1e-10 relative,
 * (d) the Newton method converges (the number of iterations is printed), and
 * (e) the interface slides freely: no tangential traction, and the mean
 * relative tangential displacement at each secondary node equals the exact
 * one to 1e-8 relative.
 */

#include <common/contact/contact_parameters.h>
#include <common/contact/contact_postprocessor.h>
#include <common/geometry/two_body_meshes.h>
#include <common/materials/linear_elastic.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/problems/small_strain_contact_problem.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  namespace BoundaryIds
  {
    constexpr types::boundary_id lower_bottom   = 1;
    constexpr types::boundary_id lower_top      = 2; // secondary
    constexpr types::boundary_id lower_symmetry = 3;
    constexpr types::boundary_id lower_side     = 4;
    constexpr types::boundary_id upper_bottom   = 5; // primary
    constexpr types::boundary_id upper_top      = 6; // loaded
    constexpr types::boundary_id upper_symmetry = 7;
    constexpr types::boundary_id upper_side     = 8;
  } // namespace BoundaryIds

  namespace MaterialIds
  {
    constexpr types::material_id lower = 1;
    constexpr types::material_id upper = 2;
  } // namespace MaterialIds

  constexpr double pressure_load    = 100.; // MPa
  constexpr double interface_length = 1.;   // mm
  constexpr double E_lower          = 70000.;
  constexpr double E_upper          = 210000.;
  constexpr double poisson_ratio    = 0.3;

  std::string
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }

  std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }

  std::string
  format(const double value, const unsigned int digits = 6)
  {
    std::ostringstream s;
    s << std::showpoint << std::setprecision(digits) << value;
    return s.str();
  }



  template <int dim>
  class PatchTest
  {
  public:
    explicit PatchTest(const unsigned int degree);

    void
    run();

  private:
    void
    make_grid();
    void
    setup_system();
    void
    assemble_load(const double                     load_factor,
                  const AffineConstraints<double> &c,
                  TrilinosWrappers::MPI::Vector   &rhs) const;
    void
    check_results(const Common::Solvers::NewtonStatistics &statistics);

    const unsigned int degree;
    MPI_Comm           mpi_communicator;

    parallel::shared::Triangulation<dim>                         triangulation;
    const FESystem<dim>                                          fe;
    const MappingQ<dim>                                          mapping;
    DoFHandler<dim>                                              dof_handler;
    std::unique_ptr<Common::Physics::SmallStrainElasticity<dim>> physics;

    Common::Contact::ContactParameters         contact;
    Common::Solvers::LinearSolverParameters    solver_parameters;
    Common::Solvers::NonlinearSolverParameters newton_parameters;
    AffineConstraints<double> constraints_dirichlet_and_hanging_nodes;
    std::unique_ptr<Common::Problems::SmallStrainContactProblem<dim>>
      contact_problem;
  };



  template <int dim>
  PatchTest<dim>::PatchTest(const unsigned int degree)
    : degree(degree)
    , mpi_communicator(MPI_COMM_WORLD)
    , triangulation(mpi_communicator)
    , fe(FE_Q<dim>(degree), dim)
    , mapping(degree)
    , dof_handler(triangulation)
  {
    contact.primary_boundary_id   = BoundaryIds::upper_bottom;
    contact.secondary_boundary_id = BoundaryIds::lower_top;
    contact.enforcement  = Common::Contact::Enforcement::lagrange_multiplier;
    contact.friction_law = Common::Contact::FrictionLaw::frictionless;
    contact.penalty_stiffness         = 1e6;
    contact.ncp_factor                = 1.;
    contact.search_distance           = 0.5;
    contact.max_active_set_iterations = 10;
    contact.accelerate_release        = true;

    solver_parameters.type           = Common::Solvers::LinearSolverType::mumps;
    solver_parameters.tolerance      = 1e-12;
    solver_parameters.max_iterations = 1000;
    newton_parameters.max_iterations = contact.max_active_set_iterations;
    newton_parameters.tolerance      = 1e-10;
  }



  // Lower block 4x4, upper block 3x3 coarse cells: the interface nodes do
  // not match (also after one global refinement: 8 against 6 faces).
  template <int dim>
  void
  PatchTest<dim>::make_grid()
  {
    Triangulation<dim> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower,
                                              {4u, 4u},
                                              Point<dim>(0., 0.),
                                              Point<dim>(1., 1.));
    GridGenerator::subdivided_hyper_rectangle(upper,
                                              {3u, 3u},
                                              Point<dim>(0., 1.),
                                              Point<dim>(1., 2.));
    for (const auto &cell : lower.active_cell_iterators())
      cell->set_material_id(MaterialIds::lower);
    for (const auto &cell : upper.active_cell_iterators())
      cell->set_material_id(MaterialIds::upper);
    Common::Geometry::join_bodies<dim>({&lower, &upper}, triangulation);

    const double tolerance = 1e-10;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<dim> c = cell->face(f)->center();
            if (cell->material_id() == MaterialIds::lower)
              cell->face(f)->set_boundary_id(
                std::abs(c[1]) < tolerance      ? BoundaryIds::lower_bottom :
                std::abs(c[1] - 1.) < tolerance ? BoundaryIds::lower_top :
                std::abs(c[0]) < tolerance      ? BoundaryIds::lower_symmetry :
                                                  BoundaryIds::lower_side);
            else
              cell->face(f)->set_boundary_id(
                std::abs(c[1] - 1.) < tolerance ? BoundaryIds::upper_bottom :
                std::abs(c[1] - 2.) < tolerance ? BoundaryIds::upper_top :
                std::abs(c[0]) < tolerance      ? BoundaryIds::upper_symmetry :
                                                  BoundaryIds::upper_side);
          }
    triangulation.refine_global(1);
  }



  template <int dim>
  void
  PatchTest<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    constraints_dirichlet_and_hanging_nodes.clear();
    constraints_dirichlet_and_hanging_nodes.reinit(
      complete_index_set(dof_handler.n_dofs()));
    DoFTools::make_hanging_node_constraints(
      dof_handler,
      constraints_dirichlet_and_hanging_nodes);
    const FEValuesExtractors::Scalar x_displacement(0);
    const FEValuesExtractors::Scalar y_displacement(1);
    VectorTools::interpolate_boundary_values(
      mapping,
      dof_handler,
      BoundaryIds::lower_bottom,
      Functions::ZeroFunction<dim>(dim),
      constraints_dirichlet_and_hanging_nodes,
      fe.component_mask(y_displacement));
    for (const auto id :
         {BoundaryIds::lower_symmetry, BoundaryIds::upper_symmetry})
      VectorTools::interpolate_boundary_values(
        mapping,
        dof_handler,
        id,
        Functions::ZeroFunction<dim>(dim),
        constraints_dirichlet_and_hanging_nodes,
        fe.component_mask(x_displacement));
    constraints_dirichlet_and_hanging_nodes.close();

    Common::Materials::LinearElasticParameters lower_parameters,
      upper_parameters;
    lower_parameters.youngs_modulus = E_lower;
    lower_parameters.poisson_ratio  = poisson_ratio;
    upper_parameters.youngs_modulus = E_upper;
    upper_parameters.poisson_ratio  = poisson_ratio;
    std::map<types::material_id, Common::Materials::LinearElastic<dim>>
      materials;
    materials.emplace(MaterialIds::lower,
                      Common::Materials::LinearElastic<dim>(lower_parameters));
    materials.emplace(MaterialIds::upper,
                      Common::Materials::LinearElastic<dim>(upper_parameters));
    physics =
      std::make_unique<Common::Physics::SmallStrainElasticity<dim>>(mapping,
                                                                    fe,
                                                                    materials);

    contact_problem =
      std::make_unique<Common::Problems::SmallStrainContactProblem<dim>>(
        dof_handler,
        mapping,
        *physics,
        contact,
        solver_parameters,
        newton_parameters,
        E_lower,
        mpi_communicator);
    contact_problem->setup(constraints_dirichlet_and_hanging_nodes);
  }



  // Consistent nodal forces of the uniform pressure on the top of the upper
  // block, traction t = (0, -p) times the load factor, distributed through
  // @p c. Not compressed.
  template <int dim>
  void
  PatchTest<dim>::assemble_load(const double                     load_factor,
                                const AffineConstraints<double> &c,
                                TrilinosWrappers::MPI::Vector   &rhs) const
  {
    const QGauss<dim - 1>                face_quadrature(degree + 1);
    FEFaceValues<dim>                    fe_face_values(mapping,
                                     fe,
                                     face_quadrature,
                                     update_values | update_JxW_values);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>                       cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    Tensor<1, dim>                       traction;
    traction[1] = -load_factor * pressure_load;
    const FEValuesExtractors::Vector displacement(0);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == BoundaryIds::upper_top)
            {
              fe_face_values.reinit(cell, f);
              cell_rhs = 0.;
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  cell_rhs(i) += fe_face_values[displacement].value(i, q) *
                                 traction * fe_face_values.JxW(q);
              cell->get_dof_indices(dof_indices);
              c.distribute_local_to_global(cell_rhs, dof_indices, rhs);
            }
  }



  template <int dim>
  void
  PatchTest<dim>::check_results(
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const auto  &coupling      = contact_problem->coupling();
    const auto  &enforcement   = contact_problem->enforcement();
    const auto  &solution      = contact_problem->displacement();
    const auto  &bulk_residual = contact_problem->bulk_residual();
    const double p             = pressure_load;

    // (a) Nodal pressures.
    unsigned int n_paired      = 0;
    double       max_deviation = 0., sum = 0.;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      {
        n_paired += coupling.row(j).has_partner;
        if (!enforcement.is_active(j))
          continue;
        const double pj = enforcement.pressure(j);
        sum += pj;
        max_deviation = std::max(max_deviation, std::abs(pj - p) / p);
      }
    const unsigned int n_active = enforcement.n_active();
    const double       mean     = n_active > 0 ? sum / n_active : 0.;
    const bool all_active       = n_active == coupling.n_rows() && n_active > 0;
    const bool pressures_exact  = max_deviation < 1e-8;
    deallog << "Secondary nodes " << coupling.n_rows() << ", paired "
            << n_paired << ", active " << n_active << std::endl;
    deallog << "All secondary nodes active: " << yes_no(all_active)
            << std::endl;
    deallog << "Mean contact pressure: " << format(mean) << " MPa" << std::endl;
    deallog << "max |p_j - p|/p < 1e-8: " << yes_no(pressures_exact)
            << std::endl;
    deallog << "(a) nodal pressures: "
            << pass_fail(all_active && pressures_exact) << std::endl;

    // (b) Uniform stress at every quadrature point of both bodies.
    const QGauss<dim>                    fe_quadrature(degree + 1);
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            fe_quadrature,
                            update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strains(fe_quadrature.size());
    double                               max_xx = 0., max_yy = 0., max_xy = 0.;
    unsigned int                         n_points = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strains);
          const auto &law = physics->material(cell->material_id());
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const SymmetricTensor<2, dim> sigma = law.stress(strains[q]);
              max_xx = std::max(max_xx, std::abs(sigma[0][0]) / p);
              max_yy = std::max(max_yy, std::abs(sigma[1][1] + p) / p);
              max_xy = std::max(max_xy, std::abs(sigma[0][1]) / p);
              ++n_points;
            }
        }
    const bool stress_uniform =
      max_xx < 1e-8 && max_yy < 1e-8 && max_xy < 1e-8 && n_points > 0;
    deallog << "Quadrature points checked: " << n_points << std::endl;
    deallog << "max |sigma_yy + p|/p < 1e-8: " << yes_no(max_yy < 1e-8)
            << std::endl;
    deallog << "max |sigma_xx|/p < 1e-8: " << yes_no(max_xx < 1e-8)
            << std::endl;
    deallog << "max |sigma_xy|/p < 1e-8: " << yes_no(max_xy < 1e-8)
            << std::endl;
    deallog << "(b) uniform stress: " << pass_fail(stress_uniform) << std::endl;

    // (c) Total contact force on the secondary surface: (0, -p L).
    const Tensor<1, dim> force =
      Common::Contact::total_contact_force(coupling, enforcement);
    const double applied     = p * interface_length;
    const bool   force_exact = std::abs(force[1] + applied) / applied < 1e-10 &&
                             std::abs(force[0]) / applied < 1e-10;
    deallog << "Total contact force F_y: " << format(force[1]) << " N/mm"
            << std::endl;
    deallog << "|F_y + p L|/(p L) < 1e-10 and |F_x|/(p L) < 1e-10: "
            << yes_no(force_exact) << std::endl;
    deallog << "(c) contact force: " << pass_fail(force_exact) << std::endl;

    // (d) Newton.
    deallog << "Newton iterations: " << statistics.n_iterations << std::endl;
    deallog << "Newton converged: " << yes_no(statistics.converged)
            << std::endl;
    deallog << "(d) Newton convergence: " << pass_fail(statistics.converged)
            << std::endl;

    // (e) Frictionless sliding: no tangential traction, and the mean
    // relative tangential displacement (primary minus secondary) of the
    // exact solution, (eps_xx,upper - eps_xx,lower) x, with
    // eps_xx = nu (1 + nu) p / E in plane strain.
    const double slip_rate =
      poisson_ratio * (1. + poisson_ratio) * p * (1. / E_upper - 1. / E_lower);
    const auto profile      = Common::Contact::contact_profile(coupling,
                                                          enforcement,
                                                          solution,
                                                          bulk_residual,
                                                          0);
    double     max_traction = 0., max_slip_error = 0., end_slip = 0.;
    for (const auto &point : profile)
      {
        max_traction =
          std::max(max_traction, std::abs(point.tangential_traction) / p);
        max_slip_error =
          std::max(max_slip_error,
                   std::abs(point.slip - slip_rate * point.position[0]) /
                     std::abs(slip_rate * interface_length));
        end_slip = point.slip;
      }
    const bool sliding_exact =
      !profile.empty() && max_traction < 1e-8 && max_slip_error < 1e-8;
    deallog << "Relative tangential displacement at x = 1: " << format(end_slip)
            << " mm (exact " << format(slip_rate * interface_length) << " mm)"
            << std::endl;
    deallog << "max |slip_j - slip_exact(x_j)|/|slip_exact(1)| < 1e-8: "
            << yes_no(max_slip_error < 1e-8) << std::endl;
    deallog << "max |tangential traction|/p < 1e-8: "
            << yes_no(max_traction < 1e-8) << std::endl;
    deallog << "(e) frictionless sliding: " << pass_fail(sliding_exact)
            << std::endl;
  }



  template <int dim>
  void
  PatchTest<dim>::run()
  {
    make_grid();
    setup_system();
    deallog << "Q" << degree << ": " << triangulation.n_active_cells()
            << " cells, " << dof_handler.n_dofs() << " DoFs, "
            << contact_problem->coupling().secondary_surface().n_faces()
            << " secondary and "
            << contact_problem->coupling().primary_surface().n_faces()
            << " primary faces" << std::endl;

    Common::Problems::ExternalLoad load;
    load.add = [this](const double                     load_factor,
                      const AffineConstraints<double> &c,
                      TrilinosWrappers::MPI::Vector   &vector) {
      assemble_load(load_factor, c, vector);
    };
    load.magnitude = [](const double load_factor) {
      return load_factor * pressure_load * interface_length;
    };
    ConditionalOStream quiet(std::cout, false);
    const auto         statistics = contact_problem->solve(1., load, quiet);
    if (!statistics.converged)
      deallog << "Newton failure: " << statistics.failure << std::endl;
    contact_problem->commit();
    check_results(statistics);
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
