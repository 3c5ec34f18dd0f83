/*
 * Benchmark 5 results: the history of point A and of the roller's loads,
 * the creep ratio, and summary.json with the published DX(A) beside ours.
 */
#include <common/contact/contact_postprocessor.h>
#include <common/io/json_writer.h>
#include <common/physics/boundary_displacement.h>
#include <common/problems/contact_run.h>

#include "rolling_problem.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

namespace ReynoldsRoller
{
  namespace
  {
    /** The published DX(A) after 360 degrees (mm) and its band (relative):
     * ../shared/specs/reynolds_roller.md section 1 (code_aster ssnp157a,
     * NAFEMS). */
    constexpr double published_dx_a   = -175.0;
    constexpr double published_band   = 0.02;
    constexpr double published_angle  = 360.;
    const char      *published_source = "NAFEMS value quoted by code_aster "
                                        "test ssnp157a (VALE_REFE = -175.0, "
                                        "2 %), ../shared/specs/"
                                        "reynolds_roller.md section 1";
  } // namespace



  template <int dim>
  void
  RollingProblem<dim>::write_half_turn_profile(const double angle)
  {
    const auto &out = parameters.output;
    // In 3D the nodes of the face z = 0, read as a plane-strain profile.
    const auto profile = Common::Contact::plane_section(
      Common::Contact::contact_profile(contact_problem->coupling(),
                                       contact_problem->enforcement(),
                                       contact_problem->displacement(),
                                       contact_problem->bulk_residual(),
                                       0),
      0.,
      parameters.geometry.thickness);
    // The zone and a roller radius on either side of it, by the closed
    // nodes' reference positions.
    double first = std::numeric_limits<double>::infinity(), last = -first;
    for (const auto &p : profile)
      if (p.status != "open")
        {
          first = std::min(first, p.position[0]);
          last  = std::max(last, p.position[0]);
        }
    if (!std::isfinite(first))
      return;
    const double R  = parameters.geometry.roller_radius;
    const double mu = parameters.contact.friction_coefficient;
    std::vector<std::array<double, 7>> rows;
    for (const auto &p : profile)
      if (p.position[0] >= first - R && p.position[0] <= last + R)
        {
          // The current position: collective over the ranks.
          Point<dim> X;
          X[0] = p.position[0];
          X[1] = p.position[1];
          const double x =
            X[0] +
            Common::Physics::displacement_at(mapping,
                                             dof_handler,
                                             contact_problem->displacement(),
                                             X,
                                             "a node of the strip's top")[0];
          rows.push_back({{x,
                           p.position[0],
                           p.pressure,
                           p.tangential_traction,
                           mu * p.pressure,
                           p.slip,
                           p.status == "open"  ? 0. :
                           p.status == "stick" ? 1. :
                                                 2.}});
        }
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    {
      std::ofstream csv(out.path("contact_half_turn.csv"));
      csv << "x_mm,x_reference_mm,pressure_MPa,tangential_traction_MPa,"
             "mu_pressure_MPa,slip_mm,status\n"
          << std::setprecision(10);
      for (const auto &r : rows)
        {
          for (unsigned int c = 0; c < r.size(); ++c)
            csv << (c > 0 ? "," : "") << r[c];
          csv << '\n';
        }
    }
    if (!out.write_plots)
      return;
    std::ostringstream at;
    at << "roller angle " << angle << " deg";
    Common::IO::PlotDescription tractions;
    tractions.title = "Contact tractions on the strip's top, " + at.str() +
                      " (stick where |q| < mu p)";
    tractions.x_label = "x, current [mm]";
    tractions.y_label = "traction [MPa]";
    tractions.series  = {
       {"contact_half_turn.csv", 1, 3, "pressure p", "linespoints pt 7 ps 0.5"},
       {"contact_half_turn.csv",
        1,
        4,
        "tangential traction q",
        "linespoints pt 5 ps 0.5"},
       {"contact_half_turn.csv", 1, 5, "mu p (slip bound)", "lines dt 2"}};
    Common::IO::PlotDescription status;
    status.title   = "Contact status and slip, " + at.str();
    status.x_label = "x, current [mm]";
    status.y_label = "status (0 open, 1 stick, 2 slip); slip [mm]";
    status.series  = {{"contact_half_turn.csv", 1, 7, "status", "steps lw 2"},
                      {"contact_half_turn.csv",
                       1,
                       6,
                       "slip accumulated in contact",
                       "linespoints pt 7 ps 0.4"}};
    write_plots({{"contact_half_turn_tractions", tractions},
                 {"contact_half_turn_slip", status}});
  }



  template <int dim>
  void
  RollingProblem<dim>::output_results(
    const Common::Solvers::LoadSteppingStatistics &stepping)
  {
    const auto  &out  = parameters.output;
    const bool   root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const double R    = parameters.geometry.roller_radius;
    AssertThrow(!records.empty(), ExcMessage("No accepted step."));
    const StepRecord &last = records.back();

    double worst_balance = 0., pressed_force = 0., pressed_ux = 0.,
           worst_dilatation = 0.;
    for (const auto &r : records)
      {
        worst_balance    = std::max(worst_balance, r.balance);
        worst_dilatation = std::max(worst_dilatation, r.dilatation_error);
        if (r.angle == 0.)
          {
            pressed_force = r.roller_force[1];
            pressed_ux    = r.corner_ux[0];
          }
      }
    // Creep ratio DX(A) / (-R theta) once the roller has turned (the
    // benchmark's: DX(A) includes the strip's spread while pressed), and
    // the same for the motion while turning only.
    const auto creep = [R](const StepRecord &r, const double offset) {
      const double travel = R * r.angle * numbers::PI / 180.;
      return travel > 0. ? (r.corner_ux[0] - offset) / -travel : 0.;
    };
    // Means over the turn (steps with the roller turned).
    double       mean_force = 0., mean_torque = 0.;
    unsigned int n_turned = 0;
    for (const auto &r : records)
      if (r.angle > 0.)
        {
          mean_force += r.roller_force[1];
          mean_torque += r.roller_moment;
          ++n_turned;
        }
    if (n_turned > 0)
      {
        mean_force /= n_turned;
        mean_torque /= n_turned;
      }

    // Steadiness of the rolling: the creep ratio of A's motion in each
    // 45-degree window of the last half turn, u_x(A) interpolated linearly
    // in the roller angle between accepted steps; the spread is
    // (largest - smallest) / mean.
    std::vector<double> window_ratios;
    double              window_spread = 0.;
    const auto          ux_at         = [this](const double angle) {
      for (unsigned int i = 1; i < records.size(); ++i)
        if (records[i].angle >= angle && records[i - 1].angle < angle)
          {
            const StepRecord &a = records[i - 1], &b = records[i];
            const double      w = (angle - a.angle) / (b.angle - a.angle);
            return (1. - w) * a.corner_ux[0] + w * b.corner_ux[0];
          }
      return records.back().corner_ux[0];
    };
    if (last.angle >= 180. + 45.)
      {
        for (unsigned int k = 0; k < 4; ++k)
          {
            const double start = last.angle - 180. + 45. * k;
            window_ratios.push_back((ux_at(start + 45.) - ux_at(start)) /
                                    -(R * 45. * numbers::PI / 180.));
          }
        const auto [lo, hi] =
          std::minmax_element(window_ratios.begin(), window_ratios.end());
        window_spread =
          (*hi - *lo) /
          (0.25 *
           std::accumulate(window_ratios.begin(), window_ratios.end(), 0.));
      }

    if (root)
      {
        std::ofstream csv(out.path("history.csv"));
        csv << "time,indentation_mm,roller_angle_deg,ux_A_mm,"
               "ux_bottom_left_mm,ux_top_right_mm,ux_bottom_right_mm,"
               "creep_ratio,roller_force_x_N_per_mm,"
               "roller_force_y_N_per_mm,driving_torque_N,"
               "balance_relative_error,rolling_creep_ratio,"
               "dilatation_error\n"
            << std::setprecision(10);
        for (const auto &r : records)
          {
            csv << r.time << ',' << r.indentation << ',' << r.angle;
            for (const double u : r.corner_ux)
              csv << ',' << u;
            csv << ',' << creep(r, 0.) << ',' << r.roller_force[0] << ','
                << r.roller_force[1] << ',' << r.roller_moment << ','
                << r.balance << ',' << creep(r, pressed_ux) << ','
                << r.dilatation_error << '\n';
          }
      }
    if (root && out.write_plots)
      {
        Common::IO::PlotDescription ratio;
        ratio.title   = "Creep ratio DX(A) / (-R theta)";
        ratio.x_label = "roller angle [deg]";
        ratio.y_label = "creep ratio";
        ratio.series  = {{"history.csv",
                          3,
                          8,
                          "DX(A) / (-R theta)",
                          "linespoints pt 7 ps 0.4"},
                         {"history.csv",
                          3,
                          13,
                          "while turning: (DX(A) - DX(A)_pressed) / (-R theta)",
                          "linespoints pt 6 ps 0.4"}};
        Common::IO::PlotDescription loads;
        loads.title   = "Loads on the roller (per mm of depth)";
        loads.x_label = "roller angle [deg]";
        loads.y_label = "force [N/mm], torque [N]";
        loads.series  = {
           {"history.csv", 3, 10, "force, y", "lines lw 2"},
           {"history.csv", 3, 9, "force, x", "lines lw 2"},
           {"history.csv", 3, 11, "driving torque", "lines lw 2 dt 2"}};
        Common::IO::PlotDescription dx;
        dx.title   = "x displacement of the strip's corners";
        dx.x_label = "roller angle [deg]";
        dx.y_label = "u_x [mm]";
        dx.series  = {{"history.csv", 3, 4, "A (top left)", "lines lw 2"},
                      {"history.csv", 3, 6, "top right", "lines lw 2 dt 2"}};
        write_plots(
          {{"creep", ratio}, {"roller_loads", loads}, {"corners", dx}});
      }

    console.stream() << "\nResults" << std::endl;
    console.print_quantity("Roller angle (clockwise)", "deg", last.angle);
    console.print_quantity("Point A, u_x", "mm", last.corner_ux[0]);
    const bool full_turn = std::abs(last.angle - published_angle) < 1e-9;
    if (full_turn)
      console.print_quantity("DX(A) / DX(A)_ref",
                             "",
                             last.corner_ux[0] / published_dx_a);
    console.print_quantity("Creep ratio", "", creep(last, 0.));
    console.print_quantity("Creep ratio while turning",
                           "",
                           creep(last, pressed_ux));
    if (!window_ratios.empty())
      console.print_quantity(
        "Creep ratio spread, last 180 deg (45-deg windows)",
        "",
        window_spread);
    console.print_quantity("Vertical force, pressed", "N/mm", pressed_force);
    console.print_quantity("Largest force balance error", "", worst_balance);
    console.print_quantity("Largest |J - 1|", "", worst_dilatation);

    using Common::IO::JsonObject;
    JsonObject case_description =
      Common::Problems::case_summary(parameters,
                                     parameters.mesh.element_degree,
                                     mpi_communicator);
    case_description
      .set("dimension", dim == 2 ? "plane strain" : "3d extrusion")
      .set("n_cells_along_length", parameters.mesh.n_cells_length)
      .set("n_cells_through_thickness", parameters.mesh.n_cells_thickness)
      .set("roller", "rigid")
      .set("bottom_free_in_x_from_stage",
           parameters.supports.bottom_free_stage);
    const double top              = 0.5 * parameters.geometry.thickness;
    const auto   contact_distance = [top](const Point<dim> &p) {
      return std::abs(p[1] - top);
    };
    const JsonObject mesh =
      Common::Problems::mesh_summary<dim>(dof_handler, contact_distance);

    JsonObject results;
    results.set("roller_angle_deg", last.angle)
      .set("dx_A_mm", last.corner_ux[0])
      .set("dx_bottom_left_mm", last.corner_ux[1])
      .set("dx_top_right_mm", last.corner_ux[2])
      .set("dx_bottom_right_mm", last.corner_ux[3])
      .set("dx_A_pressed_mm", pressed_ux)
      .set("creep_ratio", creep(last, 0.))
      .set("creep_ratio_while_turning", creep(last, pressed_ux))
      .set("vertical_force_pressed_N_per_mm", pressed_force)
      .set("mean_vertical_force_turning_N_per_mm", mean_force)
      .set("mean_driving_torque_turning_N", mean_torque)
      .set("max_force_balance_relative_error", worst_balance)
      .set("max_dilatation_error", worst_dilatation);

    if (!window_ratios.empty())
      {
        for (unsigned int k = 0; k < window_ratios.size(); ++k)
          results.set("creep_ratio_last_half_turn_window_" +
                        std::to_string(k + 1),
                      window_ratios[k]);
        results.set("creep_ratio_last_half_turn_spread", window_spread);
      }

    JsonObject reference, ratios;
    reference.set("source", published_source)
      .set("dx_A_mm", published_dx_a)
      .set("band_relative", published_band)
      .set("roller_angle_deg", published_angle);
    if (full_turn)
      ratios.set("dx_A_over_reference", last.corner_ux[0] / published_dx_a);

    if (dim == 3)
      case_description.set("width_mm", parameters.geometry.width)
        .set("n_cells_across_width", parameters.mesh.n_cells_width);
    write_summary(stepping,
                  {case_description, mesh, results, reference, ratios});
  }



  template void
  RollingProblem<2>::write_half_turn_profile(const double);
  template void
  RollingProblem<3>::write_half_turn_profile(const double);
  template void
  RollingProblem<2>::output_results(
    const Common::Solvers::LoadSteppingStatistics &);
  template void
  RollingProblem<3>::output_results(
    const Common::Solvers::LoadSteppingStatistics &);
} // namespace ReynoldsRoller
