/*
 * Benchmark 1 of the FENET/NAFEMS advanced contact benchmarks: an elastic
 * cylinder (steel, diameter 100 mm) pressed onto an elastic block
 * (aluminium, 200 x 200 mm) by a point force on its top, plane strain.
 * Half model about the vertical symmetry line. The contact pressure is
 * compared with the Hertz line-contact solution; see README.md.
 */
#include "roller_problem.h"

#include <common/analytic/coupled_partial_slip.h>
#include <common/contact/contact_postprocessor.h>
#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/two_body_meshes.h>
#include <common/io/plotting.h>
#include <common/io/timer.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/solid_model.h>
#include <common/problems/contact_run.h>
#include <common/solvers/linear_solver.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <fstream>
#include <limits>
#include <sstream>

namespace CgsRoller
{
  RollerProblem::RollerProblem(const Parameters &parameters)
    : ContactApplication<2>(parameters,
                            parameters.mesh.element_degree,
                            "cgs_roller")
    , parameters(parameters)
    , load_dof(numbers::invalid_dof_index)
  {}



  std::string
  RollerProblem::title() const
  {
    return "cgs_roller: elastic cylinder on elastic block, Hertz line "
           "contact (plane strain, half model)";
  }



  std::vector<std::string>
  RollerProblem::result_files() const
  {
    return {"reference_slip_table.csv"};
  }



  // The half model: the block occupies [0, W] x [0, H]; the roller is the
  // half disc x >= 0 of radius R centred at (0, H + R), touching the block
  // at the origin of the contact zone (0, H). The two bodies are joined
  // into one triangulation without merging the touching vertices. The
  // roller's boundary follows a spherical manifold and its interior a
  // transfinite interpolation, so refinement toward the contact point
  // keeps the cells well shaped.
  void
  RollerProblem::make_grid()
  {
    const double     R = parameters.geometry.roller_radius;
    const double     W = parameters.geometry.block_half_width;
    const double     H = parameters.geometry.block_height;
    const Point<dim> centre(0., H + R + parameters.geometry.initial_gap);

    Triangulation<dim> block;
    const double       coarse_size = R / 2.;
    GridGenerator::subdivided_hyper_rectangle(
      block,
      {std::max(1u, static_cast<unsigned int>(std::round(W / coarse_size))),
       std::max(1u, static_cast<unsigned int>(std::round(H / coarse_size)))},
      Point<dim>(0., 0.),
      Point<dim>(W, H));

    Triangulation<dim> roller;
    GridGenerator::half_hyper_ball(roller, Point<dim>(), R);
    // Keep the half x >= 0.
    bool left_half = false;
    for (const auto &v : roller.get_vertices())
      left_half = left_half || v[0] < -1e-10 * R;
    if (left_half)
      GridTools::rotate(numbers::PI, roller);
    GridTools::shift(centre, roller);

    for (const auto &cell : block.active_cell_iterators())
      cell->set_material_id(MaterialIds::block);
    for (const auto &cell : roller.active_cell_iterators())
      cell->set_material_id(MaterialIds::roller);

    Common::Geometry::join_bodies<dim>({&block, &roller}, triangulation);

    const double tolerance = 1e-8 * R;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (cell->material_id() == MaterialIds::roller)
          cell->set_all_manifold_ids(1);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<dim> c = cell->face(f)->center();
              if (cell->material_id() == MaterialIds::block)
                cell->face(f)->set_boundary_id(
                  std::abs(c[1]) < tolerance     ? BoundaryIds::block_bottom :
                  std::abs(c[1] - H) < tolerance ? BoundaryIds::block_top :
                  std::abs(c[0]) < tolerance     ? BoundaryIds::block_symmetry :
                                                   BoundaryIds::block_side);
              else if (std::abs(c[0]) < tolerance)
                cell->face(f)->set_boundary_id(BoundaryIds::roller_symmetry);
              else
                {
                  cell->face(f)->set_boundary_id(BoundaryIds::roller_surface);
                  cell->face(f)->set_manifold_id(0);
                }
            }
      }
    triangulation.set_manifold(0, SphericalManifold<dim>(centre));
    TransfiniteInterpolationManifold<dim> transfinite;
    transfinite.initialize(triangulation);
    triangulation.set_manifold(1, transfinite);

    const double L        = parameters.mesh.contact_zone_length;
    const auto   distance = [H, L](const Point<dim> &p) {
      const double dx = std::max(0., p[0] - L);
      return std::sqrt(dx * dx + (p[1] - H) * (p[1] - H));
    };
    Common::Geometry::refine_planned<dim>(
      triangulation,
      parameters.mesh.n_global_refinements,
      "Mesh: 'Number of global refinements'",
      {{distance,
        parameters.mesh.n_contact_refinements,
        parameters.mesh.grading_factor,
        "Mesh: 'Number of global refinements', "
        "'Number of contact refinements' "
        "and 'Grading factor'"}});
    parameters.mesh.apply_variations<dim>(triangulation,
                                          distance,
                                          MaterialIds::roller,
                                          MaterialIds::block);
  }



  void
  RollerProblem::setup_system()
  {
    dof_handler.distribute_dofs(fe);

    // Hanging nodes of the graded mesh, and homogeneous Dirichlet
    // conditions on the Newton increment: fixed block bottom, u_x = 0 on
    // both symmetry lines.
    Common::Physics::make_homogeneous_constraints<dim>(
      mapping,
      dof_handler,
      {BoundaryIds::block_bottom},
      {{0, {BoundaryIds::block_symmetry, BoundaryIds::roller_symmetry}}},
      constraints_dirichlet_and_hanging_nodes);

    // The point load acts on the vertical DoF of the roller's top vertex.
    const Point<dim> top(0.,
                         parameters.geometry.block_height +
                           2. * parameters.geometry.roller_radius +
                           parameters.geometry.initial_gap);
    load_dof =
      Common::Geometry::vertex_dof(dof_handler,
                                   top,
                                   1,
                                   1e-8 * parameters.geometry.roller_radius,
                                   "the top of the roller");

    setup_contact_problem(Common::Physics::create_solid_operator<dim>(
                            parameters.solid,
                            mapping,
                            fe,
                            {{MaterialIds::roller, parameters.roller_material},
                             {MaterialIds::block, parameters.block_material}}),
                          Common::Contact::create_mortar_geometry<dim>(
                            dof_handler,
                            mapping,
                            parameters.contact,
                            parameters.solid.finite_strain(),
                            false),
                          parameters.block_material.youngs_modulus);
  }



  // The point force on the roller's top vertex, half of the benchmark's
  // force per thickness (half model).
  Common::Problems::ExternalLoad
  RollerProblem::external_load() const
  {
    return Common::Problems::point_load(
      dof_handler,
      load_dof,
      -0.5 * parameters.loading.force_per_thickness);
  }



  Common::Analytic::SpencePartialSlip
  RollerProblem::spence_reference() const
  {
    const Common::Analytic::HertzLineContact hertz(
      parameters.roller_material.youngs_modulus,
      parameters.roller_material.poisson_ratio,
      parameters.block_material.youngs_modulus,
      parameters.block_material.poisson_ratio,
      parameters.geometry.roller_radius,
      parameters.loading.force_per_thickness);
    return Common::Analytic::SpencePartialSlip(
      hertz.half_width(),
      hertz.peak_pressure(),
      parameters.geometry.roller_radius,
      hertz.dundurs_beta(),
      parameters.contact.friction_coefficient);
  }



  RollerProblem::Results
  RollerProblem::evaluate_results(const double load_factor) const
  {
    const double force = load_factor * parameters.loading.force_per_thickness;
    Results      r{Common::Analytic::HertzLineContact(
                parameters.roller_material.youngs_modulus,
                parameters.roller_material.poisson_ratio,
                parameters.block_material.youngs_modulus,
                parameters.block_material.poisson_ratio,
                parameters.geometry.roller_radius,
                force),
              Common::Contact::contact_profile(contact_problem->coupling(),
                                               contact_problem->enforcement(),
                                               contact_problem->displacement(),
                                               contact_problem->bulk_residual(),
                                               0),
              0.,
              0.,
              0.,
              0.5 * force,
              0.,
              0.,
              0.};
    for (const auto &p : r.profile)
      {
        r.peak_pressure = std::max(r.peak_pressure, p.pressure);
        r.peak_tangential_traction =
          std::max(r.peak_tangential_traction, std::abs(p.tangential_traction));
      }
    r.half_width       = Common::Contact::contact_extent(r.profile, 0);
    r.stick_half_width = Common::Contact::stick_extent(r.profile, 0);
    // Accumulated slip at x = a/2, interpolated linearly between nodes.
    const double x_half = 0.5 * r.half_width;
    for (unsigned int i = 0; i + 1 < r.profile.size(); ++i)
      if (r.profile[i].position[0] <= x_half &&
          r.profile[i + 1].position[0] > x_half)
        {
          const double x0 = r.profile[i].position[0];
          const double x1 = r.profile[i + 1].position[0];
          r.slip_at_half_contact =
            r.profile[i].slip + (x_half - x0) / (x1 - x0) *
                                  (r.profile[i + 1].slip - r.profile[i].slip);
        }
    r.contact_force =
      -Common::Contact::total_contact_force(contact_problem->coupling(),
                                            contact_problem->enforcement())[1];
    return r;
  }



  void
  RollerProblem::postprocess_step(
    const Common::Solvers::StepInfo         &step,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const Results r = evaluate_results(step.state.load_factor());
    Common::Problems::print_step(console, step, statistics, *contact_problem);
    const bool friction = contact_problem->enforcement().has_friction();
    console.print_quantity("Contact force, half model",
                           "N/mm",
                           r.contact_force,
                           "F/F_applied",
                           r.contact_force / r.applied_force);
    console.print_quantity("Contact half-width a",
                           "mm",
                           r.half_width,
                           "a/a_Hertz",
                           r.half_width / r.hertz.half_width());
    console.print_quantity("Peak pressure p0",
                           "MPa",
                           r.peak_pressure,
                           "p0/p0_Hertz",
                           r.peak_pressure / r.hertz.peak_pressure());
    if (friction)
      console.print_quantity("Stick zone half-width c",
                             "mm",
                             r.stick_half_width,
                             "c/a",
                             r.half_width > 0. ?
                               r.stick_half_width / r.half_width :
                               0.);
    Common::Problems::warn_if_search_edge_reached(console, *contact_problem);
  }



} // namespace CgsRoller
