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
  constexpr double E_upper          = 70000.;
  constexpr double poisson_ratio    = 0.3;
  constexpr double mu               = 0.3;
  constexpr double upper_height     = 0.25; // mm

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
    check_step(const std::string                       &name,
               const double                             U,
               const Common::Solvers::NewtonStatistics &statistics);

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
    std::vector<types::global_dof_index>       top_x_dofs;
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
    contact.friction_law = Common::Contact::FrictionLaw::coulomb;
    contact.friction_coefficient      = mu;
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
                                              Point<dim>(1.,
                                                         1. + upper_height));
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
                std::abs(c[1] - 1. - upper_height) < tolerance ?
                                                  BoundaryIds::upper_top :
                std::abs(c[0]) < tolerance ? BoundaryIds::upper_symmetry :
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
    std::map<types::global_dof_index, double> top_x;
    VectorTools::interpolate_boundary_values(mapping,
                                             dof_handler,
                                             BoundaryIds::upper_top,
                                             Functions::ZeroFunction<dim>(dim),
                                             top_x,
                                             fe.component_mask(x_displacement));
    for (const auto &entry : top_x)
      {
        top_x_dofs.push_back(entry.first);
        constraints_dirichlet_and_hanging_nodes.add_line(entry.first);
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).norm() < 1e-10)
          {
            const auto dof = cell->vertex_dof_index(v, 0);
            if (!constraints_dirichlet_and_hanging_nodes.is_constrained(dof))
              constraints_dirichlet_and_hanging_nodes.add_line(dof);
          }
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
  PatchTest<dim>::check_step(
    const std::string                       &name,
    const double                             U,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const auto  &coupling    = contact_problem->coupling();
    const auto  &enforcement = contact_problem->enforcement();
    const double limit       = mu * pressure_load * interface_length;

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
    TrilinosWrappers::MPI::Vector internal(dof_handler.locally_owned_dofs(),
                                           mpi_communicator);
    AffineConstraints<double>     none;
    none.close();
    physics->assemble_internal_force(dof_handler,
                                     none,
                                     contact_problem->displacement(),
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
            << format(normal / (pressure_load * interface_length)) << std::endl;
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
    double U = 0.;
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
        const auto statistics = contact_problem->solve(1., load, quiet);
        if (!statistics.converged)
          deallog << "Newton failure: " << statistics.failure << std::endl;
        contact_problem->commit();
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
