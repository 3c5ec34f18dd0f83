/*
 * Contact patch test on curved faces in 3D: two stacked quarter cylinders
 * of radius 1 mm (common/geometry/revolution.h), the lower one of height 1
 * mm (E = 70000 MPa, meridian 3 x 2 cells) and the upper one from y = 1 to
 * y = 1.5 mm (E = 210000 MPa, meridian 2 x 2 cells), nu = 0.3, y the axis.
 * Their interface faces (quarter discs: an inner square and ring cells
 * with arc edges) do not match. The lower cylinder rests on u_y = 0, the
 * planes x = 0 and z = 0 are symmetry planes, and p = 100 MPa acts on the
 * top; frictionless, dual Lagrange multipliers, Q1 and Q2 (isoparametric,
 * so the curved edges are chords with Q1 and parabolas with Q2). The exact
 * solution is uniaxial stress sigma_yy = -p. Checks: (a) the segmentation
 * covers every secondary face, so that every secondary node is paired and
 * in contact (faces with curved edges must not leave gaps); (b) the total
 * contact force equals p times the interface area (the area of the
 * discrete quarter disc) to 1e-10 relative; (c) every nodal pressure
 * equals p to 1e-9 relative with Q1 (plane faces: measured 3e-11 and 6e-11)
 * and 1e-4 with Q2 (curved edges are resolved by sub-squares and edge
 * points: measured 3.2e-5); (d) Newton converges on its residual test.
 * Everything is repeated with both cylinders moved 200 mm along the axis,
 * as far as the interface of benchmark 2 lies from the origin: the weighted
 * gaps must not depend on where the bodies are. Before the rows of M were
 * scaled to sum to D, their quadrature error made the gaps of the reference
 * geometry depend on the coordinates, and (c) measured 8e-7 and 1.6e-4 (Q1)
 * and 3.7e-5 and 1.3e-3 (Q2) at y = 1 and y = 201 mm.
 */

#include <common/contact/contact_geometry.h>
#include <common/contact/contact_postprocessor.h>
#include <common/geometry/revolution.h>
#include <common/geometry/two_body_meshes.h>
#include <common/materials/linear_elastic.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/boundary_loads.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/problems/contact_newton_problem.h>

#include "../tests.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <iostream>
#include <map>

using namespace dealii;

namespace
{
  constexpr int dim = 3;

  // Boundary ids: lower bottom, top, side; upper bottom, top, side; the
  // symmetry planes z = 0 and x = 0 of both bodies.
  enum : types::boundary_id
  {
    lower_bottom = 1,
    lower_top,
    lower_side,
    upper_bottom,
    upper_top,
    upper_side,
    plane_z0,
    plane_x0
  };

  /** A meridian rectangle [0,1] x [y0,y1] with nr x ny cells, boundary
   * ids bottom, top and side (the axis edge keeps id 0). */
  void
  make_meridian(Triangulation<2>        &meridian,
                const unsigned int       nr,
                const unsigned int       ny,
                const double             y0,
                const double             y1,
                const types::boundary_id bottom,
                const types::boundary_id top,
                const types::boundary_id side)
  {
    GridGenerator::subdivided_hyper_rectangle(meridian,
                                              {nr, ny},
                                              Point<2>(0., y0),
                                              Point<2>(1., y1));
    for (const auto &cell : meridian.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            face->set_boundary_id(std::abs(c[1] - y0) < 1e-12 ? bottom :
                                  std::abs(c[1] - y1) < 1e-12 ? top :
                                  std::abs(c[0] - 1.) < 1e-12 ? side :
                                                                0);
          }
  }

  void
  run(const unsigned int degree, const double offset)
  {
    const double E_lower = 70000., E_upper = 210000., nu = 0.3, p = 100.;
    parallel::shared::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    {
      Triangulation<2> lower_meridian, upper_meridian;
      make_meridian(lower_meridian,
                    3,
                    2,
                    0.,
                    1.,
                    lower_bottom,
                    lower_top,
                    lower_side);
      make_meridian(upper_meridian,
                    2,
                    2,
                    1.,
                    1.5,
                    upper_bottom,
                    upper_top,
                    upper_side);
      Triangulation<dim> lower, upper;
      Common::Geometry::revolve_quarter(lower_meridian,
                                        plane_z0,
                                        plane_x0,
                                        10,
                                        lower);
      Common::Geometry::revolve_quarter(upper_meridian,
                                        plane_z0,
                                        plane_x0,
                                        20,
                                        upper);
      for (const auto &cell : lower.active_cell_iterators())
        cell->set_material_id(1);
      for (const auto &cell : upper.active_cell_iterators())
        cell->set_material_id(2);
      Common::Geometry::join_bodies<dim>({&lower, &upper}, triangulation);
    }
    // Along the axis, which keeps the surfaces of revolution.
    GridTools::shift(Point<dim>(0., offset, 0.), triangulation);

    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    const MappingQ<dim> mapping(degree);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    Common::Physics::make_homogeneous_constraints<dim>(mapping,
                                                       dof_handler,
                                                       {},
                                                       {{1, {lower_bottom}},
                                                        {2, {plane_z0}},
                                                        {0, {plane_x0}}},
                                                       constraints);
    constraints.close();

    Common::Materials::LinearElasticParameters lower_parameters,
      upper_parameters;
    lower_parameters.youngs_modulus = E_lower;
    lower_parameters.poisson_ratio  = nu;
    upper_parameters.youngs_modulus = E_upper;
    upper_parameters.poisson_ratio  = nu;
    std::map<types::material_id, Common::Materials::LinearElastic<dim>>
      materials;
    materials.emplace(1,
                      Common::Materials::LinearElastic<dim>(lower_parameters));
    materials.emplace(2,
                      Common::Materials::LinearElastic<dim>(upper_parameters));
    Common::Physics::SmallStrainElasticity<dim>
      physics(mapping, fe, materials, Common::Physics::Kinematics::cartesian);

    Common::Contact::ContactParameters contact;
    contact.primary_boundary_id   = upper_bottom;
    contact.secondary_boundary_id = lower_top;
    contact.enforcement     = Common::Contact::Enforcement::lagrange_multiplier;
    contact.friction_law    = Common::Contact::FrictionLaw::frictionless;
    contact.ncp_factor      = 1.;
    contact.search_distance = 0.5;
    contact.accelerate_release = true;
    Common::Solvers::LinearSolverParameters solver_parameters;
    solver_parameters.type = Common::Solvers::LinearSolverType::mumps;
    Common::Solvers::NonlinearSolverParameters newton_parameters;
    newton_parameters.max_iterations = 10;
    newton_parameters.tolerance      = 1e-10;

    Common::Contact::ReferenceMortarGeometry<dim> geometry(
      dof_handler,
      mapping,
      contact.secondary_boundary_id,
      contact.primary_boundary_id,
      contact.search_distance,
      false);
    Common::Problems::ContactNewtonProblem<dim> problem(dof_handler,
                                                        mapping,
                                                        physics,
                                                        geometry,
                                                        contact,
                                                        solver_parameters,
                                                        newton_parameters,
                                                        E_lower,
                                                        MPI_COMM_WORLD);
    problem.setup(constraints);

    // The interface area of the discrete geometry: the secondary surface.
    double            area = 0.;
    const QGauss<2>   face_quadrature(degree + 2);
    FEFaceValues<dim> fe_face_values(mapping,
                                     fe,
                                     face_quadrature,
                                     update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == lower_top)
          {
            fe_face_values.reinit(cell, face);
            for (const unsigned int q :
                 fe_face_values.quadrature_point_indices())
              area += fe_face_values.JxW(q);
          }

    Common::Problems::ExternalLoad load;
    load.add = [&](const Common::Solvers::LoadState &state,
                   const AffineConstraints<double>  &c,
                   TrilinosWrappers::MPI::Vector    &rhs) {
      Common::Physics::add_boundary_pressure(
        mapping,
        dof_handler,
        upper_top,
        state.load_factor() * p,
        Common::Physics::Kinematics::cartesian,
        c,
        rhs);
    };
    load.magnitude = [&](const Common::Solvers::LoadState &state) {
      return state.load_factor() * p * area;
    };
    ConditionalOStream quiet(std::cout, false);
    const auto         statistics =
      problem.solve(Common::Solvers::LoadState::with_load_factor(1.),
                    load,
                    quiet);

    const auto  &coupling    = problem.coupling();
    const auto  &enforcement = problem.enforcement();
    unsigned int n_paired    = 0;
    double       max_error   = 0.;
    for (unsigned int j = 0; j < coupling.n_rows(); ++j)
      {
        n_paired += coupling.row(j).has_partner;
        if (enforcement.is_active(j))
          max_error =
            std::max(max_error, std::abs(enforcement.pressure(j) - p) / p);
      }
    const Tensor<1, dim> force =
      Common::Contact::total_contact_force(coupling, enforcement);
    const double tolerance = degree == 1 ? 1e-9 : 1e-4;

    deallog << "Q" << degree << ", interface at y = " << 1. + offset
            << " mm: " << triangulation.n_active_cells() << " cells, "
            << dof_handler.n_dofs() << " DoFs, "
            << coupling.secondary_surface().n_faces() << " secondary and "
            << coupling.primary_surface().n_faces() << " primary faces"
            << std::endl;
    deallog << "(a) secondary nodes " << coupling.n_rows() << ", paired "
            << n_paired << ", in contact " << enforcement.n_active() << ": "
            << (n_paired == coupling.n_rows() &&
                    enforcement.n_active() == n_paired ?
                  "PASS" :
                  "FAIL")
            << std::endl;
    deallog << "(b) contact force / (p A) - 1 below 1e-10: "
            << (std::abs(-force[1] / (p * area) - 1.) < 1e-10 &&
                    std::abs(force[0]) < 1e-10 * p * area &&
                    std::abs(force[2]) < 1e-10 * p * area ?
                  "PASS" :
                  "FAIL")
            << std::endl;
    deallog << "(c) largest nodal pressure error below " << tolerance << ": "
            << (n_paired > 0 && max_error < tolerance ? "PASS" : "FAIL")
            << std::endl;
    deallog << "(d) Newton converged on the residual: "
            << (statistics.converged && !statistics.converged_on_step ? "PASS" :
                                                                        "FAIL")
            << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();
  for (const unsigned int degree : {1u, 2u})
    for (const double offset : {0., 200.})
      run(degree, offset);
}
