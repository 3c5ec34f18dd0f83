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
#include <common/geometry/two_body_meshes.h>
#include <common/io/plotting.h>
#include <common/io/timer.h>
#include <common/physics/boundary_conditions.h>
#include <common/problems/load_steps.h>
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
  template <int dim>
  RollerProblem<dim>::RollerProblem(const Parameters &parameters)
    : parameters(parameters)
    , mpi_communicator(MPI_COMM_WORLD)
    , console(parameters.output.verbosity, mpi_communicator)
    , triangulation(mpi_communicator)
    , fe(FE_Q<dim>(parameters.mesh.element_degree), dim)
    , mapping(parameters.mesh.element_degree)
    , dof_handler(triangulation)
    , load_dof(numbers::invalid_dof_index)
  {}



  // The half model: the block occupies [0, W] x [0, H]; the roller is the
  // half disc x >= 0 of radius R centred at (0, H + R), touching the block
  // at the origin of the contact zone (0, H). The two bodies are joined
  // into one triangulation without merging the touching vertices. The
  // roller's boundary follows a spherical manifold and its interior a
  // transfinite interpolation, so refinement toward the contact point
  // keeps the cells well shaped.
  template <int dim>
  void
  RollerProblem<dim>::make_grid()
  {
    const double     R = parameters.geometry.roller_radius;
    const double     W = parameters.geometry.block_half_width;
    const double     H = parameters.geometry.block_height;
    const Point<dim> centre(0., H + R);

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

    triangulation.refine_global(parameters.mesh.n_global_refinements);
    const double L        = parameters.mesh.contact_zone_length;
    const auto   distance = [H, L](const Point<dim> &p) {
      const double dx = std::max(0., p[0] - L);
      return std::sqrt(dx * dx + (p[1] - H) * (p[1] - H));
    };
    Common::Geometry::refine_toward<dim>(triangulation,
                                         distance,
                                         parameters.mesh.n_contact_refinements,
                                         parameters.mesh.grading_factor);
  }



  template <int dim>
  void
  RollerProblem<dim>::setup_system()
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
    constraints_dirichlet_and_hanging_nodes.close();

    // The point load acts on the vertical DoF of the roller's top vertex.
    const Point<dim> top(0.,
                         parameters.geometry.block_height +
                           2. * parameters.geometry.roller_radius);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).distance(top) <
            1e-8 * parameters.geometry.roller_radius)
          load_dof = cell->vertex_dof_index(v, 1);
    AssertThrow(load_dof != numbers::invalid_dof_index,
                ExcMessage("No mesh vertex at the top of the roller."));

    std::map<types::material_id, Common::Materials::LinearElastic<dim>>
      materials;
    materials.emplace(MaterialIds::roller,
                      Common::Materials::LinearElastic<dim>(
                        parameters.roller_material));
    materials.emplace(MaterialIds::block,
                      Common::Materials::LinearElastic<dim>(
                        parameters.block_material));
    physics =
      std::make_unique<Common::Physics::SmallStrainElasticity<dim>>(mapping,
                                                                    fe,
                                                                    materials);

    contact_problem =
      std::make_unique<Common::Problems::SmallStrainContactProblem<dim>>(
        dof_handler,
        mapping,
        *physics,
        parameters.contact,
        parameters.linear_solver,
        parameters.nonlinear_solver,
        parameters.block_material.youngs_modulus,
        mpi_communicator);
    contact_problem->setup(constraints_dirichlet_and_hanging_nodes);
  }



  // The point force on the roller's top vertex, half of the benchmark's
  // force per thickness (half model).
  template <int dim>
  Common::Problems::ExternalLoad
  RollerProblem<dim>::external_load() const
  {
    const double force = 0.5 * parameters.loading.force_per_thickness;
    const types::global_dof_index dof = load_dof;
    const bool owned = dof_handler.locally_owned_dofs().is_element(dof);
    Common::Problems::ExternalLoad load;
    load.add = [force, dof, owned](const double                     load_factor,
                                   const AffineConstraints<double> &c,
                                   TrilinosWrappers::MPI::Vector   &vector) {
      if (owned)
        {
          Vector<double> f(1);
          f(0) = -load_factor * force;
          c.distribute_local_to_global(f,
                                       std::vector<types::global_dof_index>{
                                         dof},
                                       vector);
        }
    };
    load.magnitude = [force](const double load_factor) {
      return load_factor * force;
    };
    return load;
  }



  template <int dim>
  Common::Analytic::SpencePartialSlip
  RollerProblem<dim>::spence_reference() const
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



  template <int dim>
  typename RollerProblem<dim>::Results
  RollerProblem<dim>::evaluate_results(const double load_factor) const
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



  template <int dim>
  void
  RollerProblem<dim>::postprocess_step(
    const unsigned int                       step,
    const double                             load_factor,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const Results r = evaluate_results(load_factor);
    // Step counts beyond the nominal number come from cutbacks.
    console.stream() << "Load step " << step << " of "
                     << std::max(step, parameters.load_stepping.n_steps)
                     << ", load factor "
                     << Common::IO::Console::format(load_factor)
                     << ": Newton iterations " << statistics.n_iterations
                     << ", active contact nodes "
                     << contact_problem->enforcement().n_active() << std::endl;
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
    if (contact_problem->enforcement().touches_search_edge())
      console.stream() << "  Warning: the contact zone reaches the edge of "
                          "the search region; increase 'Search distance'."
                       << std::endl;
  }



  template <int dim>
  void
  RollerProblem<dim>::output_results(
    const Common::Solvers::LoadSteppingStatistics &stepping)
  {
    const auto &coupling    = contact_problem->coupling();
    const auto &enforcement = contact_problem->enforcement();
    const auto &out         = parameters.output;
    const bool  root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const Results r  = evaluate_results(1.);
    const auto   &hertz          = r.hertz;
    const auto   &profile        = r.profile;
    const double  peak           = r.peak_pressure;
    const double  half_width     = r.half_width;
    const double  force          = r.contact_force;
    const double  applied        = r.applied_force;
    double        reference_norm = 0.;
    const double  l2_error       = Common::Contact::pressure_l2_error<dim>(
      coupling,
      enforcement,
      [&hertz](const Point<dim> &x) { return hertz.pressure(x[0]); },
      reference_norm);

    console.stream() << "Results at full load" << std::endl;
    console.print_quantity("Relative force balance error",
                           "",
                           std::abs(force - applied) / applied < 1e-12 ?
                             0. :
                             std::abs(force - applied) / applied);
    console.print_quantity("Relative L2 error of the pressure",
                           "",
                           l2_error / reference_norm);

    const double mu       = parameters.contact.friction_coefficient;
    const bool   friction = enforcement.has_friction();
    const Common::Analytic::SpencePartialSlip spence = spence_reference();
    const bool                                has_slip_table =
      std::abs(mu - 0.1) < 1e-12 &&
      std::abs(std::abs(hertz.dundurs_beta()) - 1. / 7.) < 1e-6;
    const double a_ref = hertz.half_width();
    // Slip accumulated in contact for mu = 0.1 and beta = 1/7 (tabulated in
    // REFERENCES.md 1.3, scaled to this load and radius).
    const std::vector<std::pair<double, double>> spence_slip_table =
      has_slip_table ? Common::Analytic::spence_slip_table_mu01(
                         a_ref,
                         parameters.geometry.roller_radius) :
                       std::vector<std::pair<double, double>>();
    // Reference slip at x = a/2 (mm): S0 in closed form without friction,
    // the tabulated Spence value for mu = 0.1.
    const double slip_reference =
      mu == 0.       ? spence.frictionless_slip(0.5 * a_ref) :
      has_slip_table ? spence_slip_table[5].second :
                       std::numeric_limits<double>::quiet_NaN();

    // Spence's problem without the Goodman approximation, by boundary
    // elements on half-spaces (100 elements, 20 increments: c/a to about
    // 0.0125).
    double coupled_stick_ratio = 0., coupled_peak_pressure = 0.;
    if (friction)
      {
        const Common::Analytic::CoupledPartialSlip coupled(
          hertz.contact_modulus(),
          std::abs(hertz.dundurs_beta()),
          mu,
          parameters.geometry.roller_radius,
          parameters.loading.force_per_thickness,
          100,
          20,
          false);
        coupled_stick_ratio   = coupled.stick_half_width() / a_ref;
        coupled_peak_pressure = coupled.centre_pressure();
      }

    // Ratios need a non-zero reference: with equal materials (beta = 0)
    // the reference slip and tangential traction vanish.
    const bool has_slip_ratio =
      std::isfinite(slip_reference) && slip_reference != 0.;
    const double q_reference = spence.peak_tangential_traction();
    const bool   has_q_ratio = q_reference > 0.;
    if (has_slip_ratio)
      console.print_quantity("Slip at x = a/2",
                             "mm",
                             r.slip_at_half_contact,
                             "S/S_ref",
                             r.slip_at_half_contact / slip_reference);
    if (friction)
      {
        console.print_quantity("Stick ratio c/a",
                               "",
                               half_width > 0. ?
                                 r.stick_half_width / half_width :
                                 0.,
                               "Spence",
                               spence.stick_ratio());
        console.print_quantity("  exact-coupling half-space c/a",
                               "",
                               coupled_stick_ratio);
        console.print_quantity("  exact-coupling half-space p0",
                               "MPa",
                               coupled_peak_pressure,
                               "p0/p0_Hertz",
                               coupled_peak_pressure / hertz.peak_pressure());
        if (has_q_ratio)
          console.print_quantity("Peak tangential traction",
                                 "MPa",
                                 r.peak_tangential_traction,
                                 "q/q_Spence",
                                 r.peak_tangential_traction / q_reference);
        else
          console.print_quantity("Peak tangential traction",
                                 "MPa",
                                 r.peak_tangential_traction);
      }

    if (root)
      {
        Common::Contact::write_profile_csv(out.path("contact_profile.csv"),
                                           profile,
                                           0);
        std::ofstream reference(out.path("reference_profile.csv"));
        reference << "x,pressure,tangential_traction,frictionless_slip,"
                     "frictionless_relative_displacement,mu_pressure\n"
                  << std::setprecision(8);
        for (unsigned int i = 0; i <= 400; ++i)
          {
            const double x = 1.5 * a_ref * i / 400.;
            reference << x << ',' << hertz.pressure(x) << ','
                      << spence.tangential_traction(x) << ','
                      << spence.frictionless_slip(x) << ','
                      << spence.frictionless_relative_displacement(x) << ','
                      << mu * hertz.pressure(x) << '\n';
          }
        if (has_slip_table)
          {
            std::ofstream table(out.path("reference_slip_table.csv"));
            table << "x,slip\n" << std::setprecision(8);
            for (const auto &[x, S] : spence_slip_table)
              table << x << ',' << S << '\n';
          }
      }

    if (out.write_plots && root)
      {
        const std::string fe_label =
          "FE, Q" + std::to_string(parameters.mesh.element_degree);
        const std::string  fe_style = "linespoints pt 7 ps 0.5";
        std::ostringstream mu_stream;
        mu_stream << mu;
        const std::string mu_text = mu_stream.str();
        const std::string x_label = "x, distance from the contact centre "
                                    "(reference configuration) [mm]";
        const std::string x_range =
          "[0:" + std::to_string(1.5 * hertz.half_width()) + "]";
        std::vector<std::pair<std::string, Common::IO::PlotDescription>> plots;

        Common::IO::PlotDescription pressure;
        pressure.title   = "Contact pressure, cylinder on block (benchmark 1)";
        pressure.x_label = x_label;
        pressure.y_label = "contact pressure [MPa]";
        pressure.x_range = x_range;
        pressure.series  = {
           {"reference_profile.csv", 1, 2, "Hertz", "lines lw 2"},
           {"contact_profile.csv", 1, 2, fe_label, fe_style}};
        plots.emplace_back("contact_pressure", pressure);

        Common::IO::PlotDescription traction;
        traction.title   = "Tangential traction on the block, mu = " + mu_text;
        traction.x_label = x_label;
        traction.y_label = "tangential traction [MPa]";
        traction.x_range = x_range;
        traction.series  = {{"reference_profile.csv",
                             1,
                             3,
                            friction ? "Spence (increasing load)" : "zero",
                             "lines lw 2"},
                            {"contact_profile.csv", 1, 3, fe_label, fe_style}};
        if (friction)
          traction.series.push_back(
            {"reference_profile.csv", 1, 6, "mu p (Hertz)", "lines dt 2"});
        plots.emplace_back("tangential_traction", traction);

        Common::IO::PlotDescription slip;
        slip.title   = "Slip accumulated in contact, mu = " + mu_text;
        slip.x_label = x_label;
        slip.y_label = "slip, roller relative to block, along +x [mm]";
        slip.x_range = x_range;
        slip.series  = {{"contact_profile.csv", 1, 4, fe_label, fe_style}};
        if (mu == 0.)
          slip.series.insert(
            slip.series.begin(),
            {"reference_profile.csv", 1, 4, "closed form S_0", "lines lw 2"});
        if (has_slip_table)
          slip.series.insert(slip.series.begin(),
                             {"reference_slip_table.csv",
                              1,
                              2,
                              "Spence (tabulated, +-5 %)",
                              "points pt 6 ps 1.5"});
        plots.emplace_back("slip", slip);

        if (!Common::IO::write_plots(out.directory, plots))
          console.stream() << "  Note: gnuplot not available; plot scripts "
                              "written without PNG."
                           << std::endl;
      }

    // summary.json: the headline numbers with their references and the
    // case; written last, so that only a complete run leaves one.
    using Common::IO::JsonObject;
    JsonObject case_description;
    case_description.set("element_degree", parameters.mesh.element_degree)
      .set("n_global_refinements", parameters.mesh.n_global_refinements)
      .set("n_contact_refinements", parameters.mesh.n_contact_refinements)
      .set("enforcement",
           parameters.contact.enforcement ==
               Common::Contact::Enforcement::penalty ?
             "penalty" :
             "lagrange multiplier")
      .set("friction_law", friction ? "coulomb" : "frictionless")
      .set("friction_coefficient", mu)
      .set("n_load_steps", parameters.load_stepping.n_steps)
      .set("n_mpi_ranks", Utilities::MPI::n_mpi_processes(mpi_communicator));
    if (parameters.contact.enforcement == Common::Contact::Enforcement::penalty)
      case_description.set("penalty_stiffness_MPa_per_mm",
                           parameters.contact.penalty_stiffness);

    const auto contact_distance = [this](const Point<dim> &p) {
      return std::abs(p[1] - parameters.geometry.block_height) +
             std::max(0., p[0] - parameters.mesh.contact_zone_length);
    };
    JsonObject mesh;
    mesh.set("n_active_cells", triangulation.n_active_cells())
      .set("n_dofs", dof_handler.n_dofs())
      .set("smallest_cell_in_contact_zone_mm",
           Common::Geometry::smallest_cell_near<dim>(triangulation,
                                                     contact_distance));

    const JsonObject newton = Common::Problems::newton_summary(stepping);

    JsonObject results;
    results.set("peak_pressure_MPa", peak)
      .set("contact_half_width_mm", half_width)
      .set("contact_force_half_model_N_per_mm", force)
      .set("applied_force_half_model_N_per_mm", applied)
      .set("force_balance_relative_error", std::abs(force - applied) / applied)
      .set("pressure_l2_relative_error", l2_error / reference_norm)
      .set("n_active_nodes", enforcement.n_active())
      .set("peak_tangential_traction_MPa", r.peak_tangential_traction)
      .set("slip_at_half_width_mm", r.slip_at_half_contact);
    if (friction)
      results.set("stick_half_width_mm", r.stick_half_width)
        .set("stick_ratio_c_over_a",
             half_width > 0. ? r.stick_half_width / half_width : 0.);

    JsonObject reference;
    reference.set("source", "Hertz line contact, plane strain")
      .set("peak_pressure_MPa", hertz.peak_pressure())
      .set("contact_half_width_mm", hertz.half_width())
      .set("dundurs_beta", std::abs(hertz.dundurs_beta()));
    if (std::isfinite(slip_reference))
      reference.set("slip_at_half_width_mm", slip_reference)
        .set("slip_source",
             mu == 0. ? "closed form S0, REFERENCES.md sec. 1.3" :
                        "Spence, tabulated in REFERENCES.md sec. 1.3");
    if (friction)
      reference
        .set("friction_source",
             "Spence partial slip under increasing load (Goodman "
             "approximation)")
        .set("stick_ratio_c_over_a", spence.stick_ratio())
        .set("stick_half_width_mm", spence.stick_half_width())
        .set("peak_tangential_traction_MPa", spence.peak_tangential_traction())
        .set("coupled_source",
             "half-spaces without the Goodman approximation, boundary "
             "elements (common/analytic/coupled_partial_slip)")
        .set("coupled_stick_ratio_c_over_a", coupled_stick_ratio)
        .set("coupled_peak_pressure_MPa", coupled_peak_pressure);

    JsonObject ratios;
    ratios.set("peak_pressure", peak / hertz.peak_pressure())
      .set("contact_half_width", half_width / hertz.half_width());
    if (has_slip_ratio)
      ratios.set("slip_at_half_width", r.slip_at_half_contact / slip_reference);
    if (friction && has_q_ratio)
      ratios.set("peak_tangential_traction",
                 r.peak_tangential_traction / q_reference);
    if (friction)
      ratios.set("stick_ratio_difference",
                 (half_width > 0. ? r.stick_half_width / half_width : 0.) -
                   spence.stick_ratio());

    JsonObject summary;
    summary.set("benchmark", "cgs_roller")
      .set("case", case_description)
      .set("mesh", mesh)
      .set("newton", newton)
      .set("results", results)
      .set("reference", reference)
      .set("ratios", ratios)
      .set("timing_s", timings);
    if (root)
      summary.write(out.path("summary.json"));
  }



  template <int dim>
  void
  RollerProblem<dim>::run()
  {
    const auto start = std::chrono::steady_clock::now();
    console.stream() << "cgs_roller: elastic cylinder on elastic block, "
                        "Hertz line contact (plane strain, half model)"
                     << std::endl;
    make_grid();
    setup_system();
    timings.set("setup_s", Common::IO::seconds_since(start));
    if (!Common::Problems::begin_run<dim>(console,
                                          dof_handler,
                                          *contact_problem,
                                          parameters,
                                          {"summary.json",
                                           "contact_profile.csv",
                                           "reference_profile.csv",
                                           "reference_slip_table.csv",
                                           "contact_pressure.png",
                                           "contact_pressure.gp",
                                           "tangential_traction.png",
                                           "tangential_traction.gp",
                                           "slip.png",
                                           "slip.gp",
                                           "solution.pvd"}))
      return;
    const auto &out = parameters.output;

    const Common::Problems::ExternalLoad load = external_load();
    const auto stepping = Common::Problems::run_load_steps<dim>(
      *contact_problem,
      load,
      parameters.load_stepping,
      out,
      *physics,
      dof_handler,
      mapping,
      console,
      [this](const unsigned int                       step,
             const double                             load_factor,
             const Common::Solvers::NewtonStatistics &statistics) {
        postprocess_step(step, load_factor, statistics);
      },
      timings);
    const auto  &times              = contact_problem->times();
    const double contact_solve_time = times.contact_setup + times.newton;

    if (parameters.run_control.measure_contact_cost)
      {
        const double reference =
          contact_problem->time_fixed_active_set_solve(1., load);
        timings.set("fixed_active_set_solve_s", reference)
          .set("contact_cost_ratio", contact_solve_time / reference);
        console.stream() << "Cost of contact: " << std::fixed
                         << std::setprecision(2)
                         << contact_solve_time / reference
                         << " times one assembly and solve with the active set "
                            "held fixed"
                         << std::endl;
      }
    timings.set("total_s", Common::IO::seconds_since(start));
    output_results(stepping);
  }

  template class RollerProblem<2>;
} // namespace CgsRoller
