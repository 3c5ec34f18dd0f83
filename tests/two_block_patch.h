/*
 * Shared set-up of the two-block contact patch tests (tests/common): two
 * elastic blocks with non-matching meshes, the lower one [0,1]^dim mm (4
 * coarse cells per direction) and the upper one on top of it, of height H
 * (3 coarse cells per direction), one global refinement in 2D, and a
 * uniform pressure on the top of the upper block. The last coordinate is
 * vertical: y in 2D (plane strain or axisymmetric), z in 3D. Contact:
 * secondary = top of the lower block, primary = bottom of the upper block,
 * dual Lagrange multipliers, semismooth Newton. Each test adds its own
 * Dirichlet conditions and checks.
 */
#ifndef tests_two_block_patch_h
#define tests_two_block_patch_h

#include <common/contact/contact_geometry.h>
#include <common/contact/contact_parameters.h>
#include <common/contact/current_mortar_geometry.h>
#include <common/contact/normal_enforcement.h>
#include <common/geometry/two_body_meshes.h>
#include <common/materials/linear_elastic.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/problems/contact_newton_problem.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
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
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace TwoBlockPatch
{
  using namespace dealii;

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
    // 3D only: the symmetry planes y = 0.
    constexpr types::boundary_id lower_symmetry_y = 9;
    constexpr types::boundary_id upper_symmetry_y = 10;
  } // namespace BoundaryIds

  namespace MaterialIds
  {
    constexpr types::material_id lower = 1;
    constexpr types::material_id upper = 2;
  } // namespace MaterialIds

  constexpr double interface_length = 1.; // mm

  inline std::string
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }

  inline std::string
  pass_fail(const bool b)
  {
    return b ? "PASS" : "FAIL";
  }

  inline std::string
  format(const double value, const unsigned int digits = 6)
  {
    std::ostringstream s;
    s << std::showpoint << std::setprecision(digits) << value;
    return s.str();
  }

  /** Data of the two blocks (MPa, mm). With axisymmetric kinematics the
   * blocks are two stacked cylinders of radius 1 about the axis x = 0. */
  struct Setting
  {
    double                      E_lower;
    double                      E_upper;
    double                      poisson_ratio;
    double                      upper_height;
    double                      pressure;
    Common::Physics::Kinematics kinematics =
      Common::Physics::Kinematics::cartesian;
  };

  /** Steel on aluminium, p = 100 MPa, unit heights: plane strain. */
  inline const Setting plane_strain_stack{70000., 210000., 0.3, 1., 100.};
  /** The same as two stacked cylinders of radius 1 (axisymmetric). */
  inline const Setting axisymmetric_stack{
    70000.,
    210000.,
    0.3,
    1.,
    100.,
    Common::Physics::Kinematics::axisymmetric};

  /** Title line of a setting's part of a test log. */
  inline std::string
  title(const Setting &setting)
  {
    return setting.kinematics == Common::Physics::Kinematics::axisymmetric ?
             "Axisymmetric: two cylinders of radius 1 on the axis x = 0" :
             "Plane strain";
  }

  /** Loaded area of the interface: L (mm, per unit thickness, 2D),
   * pi L^2 (mm^2, axisymmetric) or L^2 (mm^2, 3D). */
  inline double
  interface_area(const Setting &setting, const unsigned int dim = 2)
  {
    return setting.kinematics == Common::Physics::Kinematics::axisymmetric ?
             numbers::PI * interface_length * interface_length :
             std::pow(interface_length, dim - 1.);
  }

  /**
   * The two blocks, their discretisation and the contact problem.
   */
  template <int dim>
  class Patch
  {
  public:
    Patch(const unsigned int                 degree,
          const Setting                     &setting,
          const Common::Contact::FrictionLaw friction_law,
          const double                       friction_coefficient)
      : degree(degree)
      , setting(setting)
      , mpi_communicator(MPI_COMM_WORLD)
      , triangulation(mpi_communicator)
      , fe(FE_Q<dim>(degree), dim)
      , mapping(degree)
      , dof_handler(triangulation)
    {
      contact.primary_boundary_id   = BoundaryIds::upper_bottom;
      contact.secondary_boundary_id = BoundaryIds::lower_top;
      contact.enforcement  = Common::Contact::Enforcement::lagrange_multiplier;
      contact.friction_law = friction_law;
      contact.friction_coefficient  = friction_coefficient;
      contact.penalty_stiffness     = 1e6;
      contact.ncp_factor            = 1.;
      contact.tangential_ncp_factor = 0.5;
      contact.search_distance       = 0.5;
      contact.accelerate_release    = true;

      solver_parameters.type      = Common::Solvers::LinearSolverType::mumps;
      solver_parameters.tolerance = 1e-12;
      solver_parameters.max_iterations = 1000;
      newton_parameters.max_iterations = 10;
      newton_parameters.tolerance      = 1e-10;
    }

    /**
     * Mesh both blocks (the interface nodes do not match, also after the
     * global refinement: 8 against 6 faces), set boundary ids, distribute
     * DoFs and start @p constraints with the hanging-node constraints.
     * If @p refine_locally, the cells of the lower block with centre
     * x < 1/2 (and y < 1/2 in 3D) and z > 1/2, and those of the upper
     * block's bottom layer with centre x > 1/2, are refined once more,
     * which in 3D leaves hanging nodes on both contact surfaces (and none
     * on the top of the upper block).
     */
    void
    make_grid_and_dofs(AffineConstraints<double> &constraints,
                       const bool                 refine_locally = false)
    {
      Triangulation<dim> lower, upper;
      const double       top = 1. + setting.upper_height;
      Point<dim>         lower_top, upper_bottom, upper_top;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower_top[d]    = 1.;
          upper_bottom[d] = d == dim - 1 ? 1. : 0.;
          upper_top[d]    = d == dim - 1 ? top : 1.;
        }
      GridGenerator::subdivided_hyper_rectangle(lower,
                                                std::vector<unsigned int>(dim,
                                                                          4u),
                                                Point<dim>(),
                                                lower_top);
      GridGenerator::subdivided_hyper_rectangle(upper,
                                                std::vector<unsigned int>(dim,
                                                                          3u),
                                                upper_bottom,
                                                upper_top);
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
              const Point<dim> c    = cell->face(f)->center();
              const double     z    = c[dim - 1];
              const bool symmetry_y = dim == 3 && std::abs(c[1]) < tolerance;
              if (cell->material_id() == MaterialIds::lower)
                cell->face(f)->set_boundary_id(
                  std::abs(z) < tolerance      ? BoundaryIds::lower_bottom :
                  std::abs(z - 1.) < tolerance ? BoundaryIds::lower_top :
                  std::abs(c[0]) < tolerance   ? BoundaryIds::lower_symmetry :
                  symmetry_y                   ? BoundaryIds::lower_symmetry_y :
                                                 BoundaryIds::lower_side);
              else
                cell->face(f)->set_boundary_id(
                  std::abs(z - 1.) < tolerance  ? BoundaryIds::upper_bottom :
                  std::abs(z - top) < tolerance ? BoundaryIds::upper_top :
                  std::abs(c[0]) < tolerance    ? BoundaryIds::upper_symmetry :
                  symmetry_y ? BoundaryIds::upper_symmetry_y :
                               BoundaryIds::upper_side);
            }
      if (dim == 2)
        triangulation.refine_global(1);
      if (refine_locally)
        {
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              const Point<dim> c = cell->center();
              const double     z = c[dim - 1];
              if (cell->material_id() == MaterialIds::lower ?
                    (c[0] < 0.5 && (dim == 2 || c[1] < 0.5) && z > 0.5) :
                    (c[0] > 0.5 && z - 1. < cell->extent_in_direction(dim - 1)))
                cell->set_refine_flag();
            }
          triangulation.execute_coarsening_and_refinement();
        }

      dof_handler.distribute_dofs(fe);
      constraints.clear();
      constraints.reinit(complete_index_set(dof_handler.n_dofs()));
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    }

    /** Zero vertical displacement on the bottom of the lower block. */
    void
    add_lower_support(AffineConstraints<double> &constraints) const
    {
      const FEValuesExtractors::Scalar y_displacement(dim - 1);
      VectorTools::interpolate_boundary_values(
        mapping,
        dof_handler,
        BoundaryIds::lower_bottom,
        Functions::ZeroFunction<dim>(dim),
        constraints,
        fe.component_mask(y_displacement));
    }

    /** u_x = 0 on the symmetry lines (planes) x = 0 of both blocks, and
     * in 3D u_y = 0 on the planes y = 0. */
    void
    add_symmetry(AffineConstraints<double> &constraints) const
    {
      std::vector<std::pair<unsigned int, std::vector<types::boundary_id>>>
        planes = {
          {0, {BoundaryIds::lower_symmetry, BoundaryIds::upper_symmetry}}};
      if (dim == 3)
        planes.push_back(
          {1, {BoundaryIds::lower_symmetry_y, BoundaryIds::upper_symmetry_y}});
      Common::Physics::add_zero_component_constraints(mapping,
                                                      dof_handler,
                                                      planes,
                                                      constraints);
    }


    /**
     * Materials, physics and the contact problem, with the closed
     * Dirichlet and hanging-node @p constraints; the solid is the
     * small-strain elastic one of the setting, or @p solid if given.
     */
    void
    setup_problem(
      const AffineConstraints<double>                     &constraints,
      std::unique_ptr<Common::Physics::SolidOperator<dim>> solid = nullptr)
    {
      other_solid = std::move(solid);
      Common::Materials::LinearElasticParameters lower_parameters,
        upper_parameters;
      lower_parameters.youngs_modulus = setting.E_lower;
      lower_parameters.poisson_ratio  = setting.poisson_ratio;
      upper_parameters.youngs_modulus = setting.E_upper;
      upper_parameters.poisson_ratio  = setting.poisson_ratio;
      std::map<types::material_id, Common::Materials::LinearElastic<dim>>
        materials;
      materials.emplace(MaterialIds::lower,
                        Common::Materials::LinearElastic<dim>(
                          lower_parameters));
      materials.emplace(MaterialIds::upper,
                        Common::Materials::LinearElastic<dim>(
                          upper_parameters));
      physics = std::make_unique<Common::Physics::SmallStrainElasticity<dim>>(
        mapping,
        fe,
        materials,
        setting.kinematics);

      const bool axisymmetric =
        setting.kinematics == Common::Physics::Kinematics::axisymmetric;
      // Finite-strain kinematics only matter to the choice of geometry.
      contact.configuration =
        current_configuration ?
          Common::Contact::ContactConfiguration::current :
          Common::Contact::ContactConfiguration::reference;
      contact_geometry =
        Common::Contact::create_mortar_geometry<dim>(dof_handler,
                                                     mapping,
                                                     contact,
                                                     current_configuration,
                                                     axisymmetric);
      contact_problem =
        std::make_unique<Common::Problems::ContactNewtonProblem<dim>>(
          dof_handler,
          mapping,
          other_solid ? *other_solid : *physics,
          *contact_geometry,
          contact,
          solver_parameters,
          newton_parameters,
          setting.E_lower,
          mpi_communicator);
      contact_problem->setup(constraints);

      deallog << "Q" << degree << ": " << triangulation.n_active_cells()
              << " cells, " << dof_handler.n_dofs() << " DoFs, "
              << contact_problem->coupling().secondary_surface().n_faces()
              << " secondary and "
              << contact_problem->coupling().primary_surface().n_faces()
              << " primary faces" << std::endl;
    }

    /**
     * The uniform pressure on the top of the upper block: consistent nodal
     * forces of the traction (0, -p) times the load factor, distributed
     * through the constraints (with the ring measure if axisymmetric); the
     * load magnitude is p times interface_area().
     */
    Common::Problems::ExternalLoad
    external_load() const
    {
      Common::Problems::ExternalLoad load;
      load.add = [this](const Common::Solvers::LoadState &state,
                        const AffineConstraints<double>  &c,
                        TrilinosWrappers::MPI::Vector    &rhs) {
        const QGauss<dim - 1> face_quadrature(degree + 1);
        FEFaceValues<dim>     fe_face_values(mapping,
                                         fe,
                                         face_quadrature,
                                         update_values | update_JxW_values |
                                           update_quadrature_points);
        const unsigned int    dofs_per_cell = fe.n_dofs_per_cell();
        Vector<double>        cell_rhs(dofs_per_cell);
        std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
        Tensor<1, dim>                       traction;
        traction[dim - 1] = -state.load_factor() * setting.pressure;
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
                                     traction * fe_face_values.JxW(q) *
                                     Common::Physics::measure_factor(
                                       setting.kinematics,
                                       fe_face_values.quadrature_point(q));
                  cell->get_dof_indices(dof_indices);
                  c.distribute_local_to_global(cell_rhs, dof_indices, rhs);
                }
      };
      const double force = setting.pressure * interface_area(setting, dim);
      load.magnitude     = [force](const Common::Solvers::LoadState &state) {
        return state.load_factor() * force;
      };
      return load;
    }

    /** Solve at full load with the external load of external_load(),
     * log a failure, and accept the state. */
    Common::Solvers::NewtonStatistics
    solve_and_commit()
    {
      ConditionalOStream quiet(std::cout, false);
      const auto         statistics =
        contact_problem->solve(Common::Solvers::LoadState::with_load_factor(1.),
                               external_load(),
                               quiet);
      if (!statistics.converged)
        deallog << "Newton failure: " << statistics.failure << std::endl;
      contact_problem->commit();
      return statistics;
    }

    const unsigned int degree;
    const Setting      setting;
    MPI_Comm           mpi_communicator;

    parallel::shared::Triangulation<dim>                         triangulation;
    const FESystem<dim>                                          fe;
    const MappingQ<dim>                                          mapping;
    DoFHandler<dim>                                              dof_handler;
    std::unique_ptr<Common::Physics::SmallStrainElasticity<dim>> physics;
    /** The solid given to setup_problem(), if any. */
    std::unique_ptr<Common::Physics::SolidOperator<dim>> other_solid;

    Common::Contact::ContactParameters         contact;
    Common::Solvers::LinearSolverParameters    solver_parameters;
    Common::Solvers::NonlinearSolverParameters newton_parameters;
    /** Contact in the current configuration (CurrentMortarGeometry)
     * instead of the reference one; set before setup_problem(). */
    bool current_configuration = false;
    std::unique_ptr<Common::Contact::ContactGeometry<dim>> contact_geometry;
    std::unique_ptr<Common::Problems::ContactNewtonProblem<dim>>
      contact_problem;
  };



  /** Secondary node at (x, 1). */
  template <int dim>
  inline unsigned int
  secondary_node_at(const Patch<dim> &patch, const double x)
  {
    const auto &surface = patch.contact_problem->coupling().secondary_surface();
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      if (std::abs(surface.node(j).position[0] - x) < 1e-10)
        return j;
    AssertThrow(false, ExcMessage("No secondary node at this x."));
    return 0;
  }

  /**
   * The run of the tests with fixed secondary nodes: the plane-strain patch
   * (lower support, symmetry line x = 0, mu = 0.3 if Coulomb) with, in
   * addition, the components of the secondary nodes at (x, 1) that
   * @p fixed lists held at zero; every touching node closed at the start.
   * Logs each fixed node's status (and, with one fixed component, whether
   * contact holds u_x to the primary's mean motion), the nodes sticking
   * without a normal row, with @p count_unconstrained the closed nodes
   * without a constraint, and whether Newton converges at full load.
   */
  inline void
  run_with_fixed_secondary_nodes(
    const unsigned int                 degree,
    const Common::Contact::FrictionLaw friction_law,
    const std::vector<std::pair<double, std::vector<unsigned int>>> &fixed,
    const bool count_unconstrained)
  {
    Patch<2> patch(degree, plane_strain_stack, friction_law, 0.3);
    AffineConstraints<double> base;
    patch.make_grid_and_dofs(base);
    patch.add_lower_support(base);
    patch.add_symmetry(base);
    base.close();
    patch.setup_problem(base);

    // The same constraints and, in addition, the fixed components of the
    // chosen secondary nodes.
    AffineConstraints<double> constraints;
    constraints.reinit(complete_index_set(patch.dof_handler.n_dofs()));
    std::vector<unsigned int> nodes;
    for (const auto &[x, components] : fixed)
      {
        const unsigned int j = secondary_node_at(patch, x);
        nodes.push_back(j);
        const auto &dofs =
          patch.contact_problem->coupling().secondary_surface().node(j).dofs;
        for (const unsigned int c : components)
          constraints.add_line(dofs[c]);
      }
    constraints.merge(base, AffineConstraints<double>::left_object_wins, true);
    constraints.close();
    patch.setup_problem(constraints);

    const auto &enforcement = patch.contact_problem->enforcement();
    const auto &coupling    = patch.contact_problem->coupling();
    AffineConstraints<double> with_contact;
    with_contact.reinit(complete_index_set(patch.dof_handler.n_dofs()));
    with_contact.merge(constraints);
    enforcement.add_constraints(with_contact,
                                patch.contact_problem->displacement());
    with_contact.close();

    const auto &lagrange =
      dynamic_cast<const Common::Contact::DualLagrangeEnforcement<2> &>(
        enforcement.normal_enforcement());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const unsigned int j    = nodes[i];
        const auto        &dofs = coupling.secondary_surface().node(j).dofs;
        deallog << "node x = " << fixed[i].first << ": "
                << Common::Contact::to_string(enforcement.status(j));
        if (fixed[i].second.size() == 1)
          {
            // u_x: constrained by contact to the primary's mean motion?
            const auto *entries = with_contact.get_constraint_entries(dofs[0]);
            double      sum     = 0.;
            if (entries)
              for (const auto &entry : *entries)
                sum += entry.second;
            deallog << ", u_x held by contact: "
                    << yes_no(entries != nullptr && !entries->empty() &&
                              std::abs(sum - 1.) < 1e-12);
          }
        deallog << std::endl;
      }
    deallog << "sticking without normal row: "
            << lagrange.diagnostics().n_stick_without_normal;
    if (count_unconstrained)
      deallog << ", closed without constraint: "
              << lagrange.diagnostics().n_unconstrained;
    deallog << std::endl;

    const auto statistics = patch.solve_and_commit();
    deallog << "converged: " << yes_no(statistics.converged) << std::endl;
  }
} // namespace TwoBlockPatch

#endif
