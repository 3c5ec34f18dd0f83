/*
 * Benchmark 1's postprocessing at full load: the results against the Hertz
 * and Spence solutions (and the exact-coupling half-space solution) on the
 * console, the profile and reference CSV files, the plots, and
 * summary.json.
 */
#include <common/analytic/coupled_partial_slip.h>
#include <common/io/plotting.h>
#include <common/problems/contact_run.h>

#include "roller_problem.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace CgsRoller
{
  void
  RollerProblem::output_results(
    const Common::Solvers::LoadSteppingStatistics &stepping)
  {
    const auto &coupling    = contact_problem->coupling();
    const auto &enforcement = contact_problem->enforcement();
    const auto &out         = parameters.output;
    const bool  root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const Results r  = evaluate_results(final_load_factor());
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
    // doc/references.md 1.3, scaled to this load and radius).
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
    // Spence's traction is not available where the stick zone fills the
    // contact in double precision (|beta|/mu < 0.082).
    const bool   has_spence_traction = spence.has_traction();
    const double q_reference =
      has_spence_traction ? spence.peak_tangential_traction() : 0.;
    const bool has_q_ratio = q_reference > 0.;
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
            reference << x << ',' << hertz.pressure(x) << ',';
            if (has_spence_traction)
              reference << spence.tangential_traction(x);
            reference << ',' << spence.frictionless_slip(x) << ','
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
        traction.series  = {{"contact_profile.csv", 1, 3, fe_label, fe_style}};
        if (has_spence_traction)
          traction.series.insert(traction.series.begin(),
                                 {"reference_profile.csv",
                                  1,
                                  3,
                                  friction ? "Spence (increasing load)" :
                                             "zero",
                                  "lines lw 2"});
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

        this->write_plots(plots);
      }

    // summary.json: the headline numbers with their references and the
    // case; written last, so that only a complete run leaves one.
    using Common::IO::JsonObject;
    JsonObject case_description =
      Common::Problems::case_summary(parameters,
                                     parameters.mesh.element_degree,
                                     mpi_communicator);
    case_description
      .set("n_global_refinements", parameters.mesh.n_global_refinements)
      .set("n_contact_refinements", parameters.mesh.n_contact_refinements);

    const auto contact_distance = [this](const Point<dim> &p) {
      return std::abs(p[1] - parameters.geometry.block_height) +
             std::max(0., p[0] - parameters.mesh.contact_zone_length);
    };
    const JsonObject mesh =
      Common::Problems::mesh_summary<dim>(dof_handler, contact_distance);


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
             mu == 0. ? "closed form S0, doc/references.md sec. 1.3" :
                        "Spence, tabulated in doc/references.md sec. 1.3");
    if (friction)
      {
        reference
          .set("friction_source",
               "Spence partial slip under increasing load (Goodman "
               "approximation)")
          .set("stick_ratio_c_over_a", spence.stick_ratio())
          .set("stick_half_width_mm", spence.stick_half_width());
        if (has_spence_traction)
          reference.set("peak_tangential_traction_MPa", q_reference);
        reference
          .set("coupled_source",
               "half-spaces without the Goodman approximation, boundary "
               "elements (common/analytic/coupled_partial_slip)")
          .set("coupled_stick_ratio_c_over_a", coupled_stick_ratio)
          .set("coupled_peak_pressure_MPa", coupled_peak_pressure);
      }

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

    write_summary(stepping,
                  {case_description, mesh, results, reference, ratios});
  }
} // namespace CgsRoller
