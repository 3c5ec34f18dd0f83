/*
 * Benchmark 4's postprocessing at full load: the contact arc, pressure,
 * circumferential traction and slip against theta on the sheet's
 * mid-plane and on its face, the displacements of pin and lug, the force
 * balance; CSV files, plots and summary.json. No published curve exists:
 * the cosine bearing law (doc/references.md 4) is drawn as a guide only.
 */
#include <common/io/plotting.h>
#include <common/problems/contact_run.h>

#include "pin_problem.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace LoadedPin
{
  using Common::IO::JsonObject;

  namespace
  {
    /** Write the points of @p line as CSV (degrees, mm, MPa). */
    void
    write_line_csv(const std::string    &filename,
                   const PinContactLine &line,
                   const double          mu)
    {
      std::ofstream csv(filename);
      csv << "theta_deg,phi_deg,x,y,z,pressure,q_theta,q_z,q_over_mu_p,"
             "slip_theta,accumulated_slip_theta,gap,status\n"
          << std::setprecision(10);
      for (const auto &p : line.points)
        csv << p.theta << ',' << 180. - p.theta << ',' << p.position[0] << ','
            << p.position[1] << ',' << p.position[2] << ',' << p.pressure << ','
            << p.q_theta << ',' << p.q_z << ','
            << (mu > 0. && p.pressure > 0. ?
                  std::abs(p.q_theta) / (mu * p.pressure) :
                  0.)
            << ',' << p.slip_theta << ',' << p.accumulated_slip_theta << ','
            << p.gap << ',' << p.status << '\n';
    }

    /** The scalars of one line for summary.json. */
    JsonObject
    line_summary(const PinContactLine &line, const bool friction)
    {
      JsonObject json;
      json.set("z_mm", line.z)
        .set("arc_end_theta_deg", line.arc_end_theta)
        .set("peak_pressure_MPa", line.peak_pressure)
        .set("peak_pressure_theta_deg", line.peak_pressure_theta)
        .set("fitted_peak_pressure_MPa", line.fitted_peak_pressure)
        .set("fitted_peak_pressure_theta_deg", line.fitted_peak_pressure_theta)
        .set("peak_traction_MPa", line.peak_traction)
        .set("peak_traction_theta_deg", line.peak_traction_theta)
        .set("max_slip_mm", line.max_slip);
      if (friction)
        json.set("stick_end_theta_deg", line.stick_end_theta);
      return json;
    }
  } // namespace



  void
  PinProblem::output_results(
    const Common::Solvers::LoadSteppingStatistics &stepping)
  {
    const auto  &out  = parameters.output;
    const auto  &g    = parameters.geometry;
    const bool   root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const double mu   = parameters.contact.friction_coefficient;
    const bool   friction     = contact_problem->enforcement().has_friction();
    const double applied      = applied_force(final_load_factor());
    const double force        = contact_resultant();
    const double balance      = std::abs(force - applied) / applied;
    const PinContactLine mid  = contact_line(0.);
    const PinContactLine face = contact_line(0.5 * g.sheet_thickness);
    // The cosine bearing law of a neat pin in a large plate, contact over
    // +-90 degrees: p = p_max cos(phi), p_max = 2F / (pi R t) with the
    // full model's force (doc/references.md 4).
    const double cosine_peak =
      2. * parameters.loading.total_force /
      (numbers::PI * g.hole_radius * g.sheet_thickness);
    const double u_pin     = displacement_at(pin_centre_dof);
    const double u_bearing = displacement_at(bearing_point_dof);
    const double u_tip     = displacement_at(lug_tip_dof);

    console.stream() << "Results at full load" << std::endl;
    console.print_quantity("Relative force balance error",
                           "",
                           balance < 1e-12 ? 0. : balance);
    for (const auto *line : {&mid, &face})
      {
        const std::string where = line == &mid ? ", mid-plane" : ", sheet face";
        console.print_quantity("Contact arc end" + where,
                               "deg",
                               line->arc_end_theta);
        console.print_quantity("Peak pressure" + where,
                               "MPa",
                               line->peak_pressure,
                               "p/p_cosine",
                               line->peak_pressure / cosine_peak);
        console.print_quantity("  at theta", "deg", line->peak_pressure_theta);
        console.print_quantity("Peak pressure, parabola" + where,
                               "MPa",
                               line->fitted_peak_pressure);
        console.print_quantity("  at theta",
                               "deg",
                               line->fitted_peak_pressure_theta);
        if (friction)
          {
            console.print_quantity("Peak traction" + where,
                                   "MPa",
                                   line->peak_traction);
            console.print_quantity("  at theta",
                                   "deg",
                                   line->peak_traction_theta);
            console.print_quantity("Stick zone end" + where,
                                   "deg",
                                   line->stick_end_theta);
          }
        console.print_quantity("Largest |slip|" + where, "mm", line->max_slip);
      }
    console.print_quantity("Pin centre, u_x", "mm", u_pin);
    console.print_quantity("Sheet bearing point, u_x", "mm", u_bearing);
    console.print_quantity("Lug tip, u_x", "mm", u_tip);

    if (root)
      {
        write_line_csv(out.path("contact_profile.csv"), mid, mu);
        write_line_csv(out.path("contact_profile_sheet_face.csv"), face, mu);
        std::ofstream reference(out.path("reference_profile.csv"));
        reference << "theta_deg,cosine_law_pressure\n" << std::setprecision(8);
        for (unsigned int i = 0; i <= 180; ++i)
          {
            const double theta = i;
            const double phi   = (180. - theta) * numbers::PI / 180.;
            reference << theta << ','
                      << (theta >= 90. ? cosine_peak * std::cos(phi) : 0.)
                      << '\n';
          }
      }

    if (out.write_plots && root)
      {
        std::ostringstream mu_text;
        mu_text << mu;
        const std::string fe =
          "FE, Q" + std::to_string(parameters.mesh.element_degree) + ", ";
        const std::string style   = "linespoints pt 7 ps 0.5";
        const std::string x_label = "theta, from the point facing the clamp "
                                    "[deg]";
        std::vector<std::pair<std::string, Common::IO::PlotDescription>> plots;
        const auto two_lines = [&](const unsigned int column) {
          return std::vector<Common::IO::PlotSeries>{
            {"contact_profile.csv", 1, column, fe + "mid-plane z = 0", style},
            {"contact_profile_sheet_face.csv",
             1,
             column,
             fe + "sheet face z = t/2",
             "linespoints pt 4 ps 0.5"}};
        };
        Common::IO::PlotDescription pressure;
        pressure.title   = "Contact pressure on the pin, mu = " + mu_text.str();
        pressure.x_label = x_label;
        pressure.y_label = "contact pressure [MPa]";
        pressure.x_range = "[0:180]";
        pressure.series  = two_lines(6);
        pressure.series.push_back({"reference_profile.csv",
                                   1,
                                   2,
                                   "cosine bearing law (guide)",
                                   "lines lw 2 dt 2"});
        plots.emplace_back("contact_pressure", pressure);

        Common::IO::PlotDescription traction;
        traction.title =
          "Circumferential traction on the pin, mu = " + mu_text.str();
        traction.x_label = x_label;
        traction.y_label = "q, along increasing theta [MPa]";
        traction.x_range = "[0:180]";
        traction.series  = two_lines(7);
        plots.emplace_back("tangential_traction", traction);

        Common::IO::PlotDescription slip;
        slip.title = "Circumferential relative displacement, pin minus "
                     "sheet, mu = " +
                     mu_text.str();
        slip.x_label = x_label;
        slip.y_label = "s, along increasing theta [mm]";
        slip.x_range = "[0:180]";
        slip.series  = two_lines(10);
        plots.emplace_back("slip", slip);
        this->write_plots(plots);
      }

    JsonObject case_description =
      Common::Problems::case_summary(parameters,
                                     parameters.mesh.element_degree,
                                     mpi_communicator);
    case_description.set("model", "3d quarter")
      .set("total_force_N", parameters.loading.total_force)
      .set("clearance_mm", g.clearance)
      .set("global_refinements", parameters.mesh.n_global_refinements)
      .set("contact_refinements", parameters.mesh.n_contact_refinements)
      .set("sheet_layers", parameters.mesh.n_sheet_layers)
      .set("pin_layers", parameters.mesh.n_pin_layers)
      .set("arc_end_refinements", parameters.mesh.n_arc_end_refinements)
      .set("arc_end_refinement_angle_deg", parameters.mesh.arc_end_angle);
    const JsonObject mesh =
      Common::Problems::mesh_summary<dim>(dof_handler,
                                          [g](const Point<dim> &p) {
                                            return contact_distance(g, p);
                                          });

    JsonObject results;
    results.set("contact_force_x_N", force)
      .set("applied_force_x_N", applied)
      .set("force_balance_relative_error", balance)
      .set("mid_plane", line_summary(mid, friction))
      .set("sheet_face", line_summary(face, friction))
      .set("pin_centre_ux_mm", u_pin)
      .set("sheet_bearing_point_ux_mm", u_bearing)
      .set("lug_tip_ux_mm", u_tip)
      .set("n_active_nodes", contact_problem->enforcement().n_active());
    JsonObject reference;
    reference
      .set("source",
           "none published; cosine bearing law of a neat pin in a large "
           "plate as a guide (doc/references.md 4)")
      .set("cosine_law_peak_pressure_MPa", cosine_peak);
    JsonObject ratios;
    ratios.set("mid_plane_peak_pressure_cosine_law",
               mid.peak_pressure / cosine_peak);
    write_summary(stepping,
                  {case_description, mesh, results, reference, ratios});
  }
} // namespace LoadedPin
