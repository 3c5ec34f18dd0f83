/*
 * Benchmark 2's postprocessing at full load: the results against the
 * half-space solution and the MSC.Marc/Abaqus curves on the console, the
 * profile and reference CSV files, the plots, and summary.json.
 */
#include <common/io/plotting.h>
#include <common/physics/boundary_displacement.h>
#include <common/problems/contact_run.h>

#include "punch_problem.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace Punch3d
{
  namespace
  {
    /** MSC.Marc's u_z of the foundation top on the axis (doc/references.md 2.2,
     * mm), for mu = 0 and 0.1; NaN for other mu. */
    double
    marc_axis_displacement(const double mu)
    {
      if (mu == 0.)
        return -0.1310;
      if (std::abs(mu - 0.1) < 1e-12)
        return -0.1288;
      return std::numeric_limits<double>::quiet_NaN();
    }

    /** Component @p c of the displacement at radius @p r, interpolated
     * linearly between the samples of @p surface (sorted by r). */
    template <int dim>
    double
    surface_displacement_at(
      const std::vector<Common::Physics::BoundaryDisplacementPoint<dim>>
                        &surface,
      const double       r,
      const unsigned int c)
    {
      AssertThrow(!surface.empty(), ExcMessage("Empty surface profile."));
      if (r <= surface.front().position[0])
        return surface.front().displacement[c];
      for (unsigned int i = 1; i < surface.size(); ++i)
        if (r <= surface[i].position[0])
          {
            const double r0 = surface[i - 1].position[0];
            const double r1 = surface[i].position[0];
            const double w  = (r - r0) / (r1 - r0);
            return (1. - w) * surface[i - 1].displacement[c] +
                   w * surface[i].displacement[c];
          }
      return surface.back().displacement[c];
    }
  } // namespace



  template <int dim>
  void
  PunchProblem<dim>::output_results(
    const Common::Solvers::LoadSteppingStatistics &stepping)
  {
    using Common::IO::JsonObject;
    const auto &enforcement = contact_problem->enforcement();
    const auto &out         = parameters.output;
    const bool  root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const Results r  = evaluate_results(this->final_load_factor());
    const auto    half_space   = half_space_reference();
    const auto    fe_reference = Common::Analytic::fenet_punch_fe_reference();
    const double  mu           = parameters.contact.friction_coefficient;
    const bool    friction     = enforcement.has_friction();
    // The MSC.Marc and Abaqus results are those of the benchmark's bodies
    // and load; any other geometry (a hemispherical end: Hertz; a larger
    // foundation: the half-space limit) is compared with the half-space
    // solution only.
    const bool   benchmark_geometry = parameters.benchmark_bodies_and_load();
    const bool   sphere             = parameters.geometry.hemispherical_end();
    const double uz_marc            = benchmark_geometry ?
                                        marc_axis_displacement(mu) :
                                        std::numeric_limits<double>::quiet_NaN();
    // The MSC.Marc pressure nearest the axis, r = 0.5 mm (mu = 0.1; the
    // frictionless curve is not tabulated, and FE centre pressures differ
    // by less than their spread).
    const double p_centre_marc = fe_reference.front().pressure_marc;
    // The foundation top, r from the axis to the foundation's rim (3D: on
    // the plane z = 0, where u_x = u_r).
    auto surface =
      Common::Physics::boundary_displacements(mapping,
                                              dof_handler,
                                              contact_problem->displacement(),
                                              BoundaryIds::foundation_top);
    if (dim == 3)
      surface.erase(std::remove_if(surface.begin(),
                                   surface.end(),
                                   [this](const auto &p) {
                                     return std::abs(p.position[dim - 1]) >
                                            1e-8 *
                                              parameters.geometry.punch_radius;
                                   }),
                    surface.end());
    // The largest inward (toward the axis) radial displacement.
    double ur_min = 0., ur_min_radius = 0.;
    for (const auto &p : surface)
      if (p.displacement[0] < ur_min)
        {
          ur_min        = p.displacement[0];
          ur_min_radius = p.position[0];
        }
    const auto marc_surface =
      Common::Analytic::fenet_punch_marc_surface_displacements();
    const bool marc_has_mu = std::isfinite(uz_marc);
    const auto marc_uz     = [mu](const auto &p) {
      return mu == 0. ? p.uz_mu0 : p.uz_mu01;
    };
    const auto marc_ur = [mu](const auto &p) {
      return mu == 0. ? p.ur_mu0 : p.ur_mu01;
    };
    double marc_ur_min = 0.;
    for (const auto &p : marc_surface)
      marc_ur_min = std::min(marc_ur_min, marc_ur(p));
    const double force_error =
      std::abs(r.contact_force - r.applied_force) / r.applied_force;

    console.stream() << "Results at full load" << std::endl;
    console.print_quantity("Relative force balance error", "", force_error);
    console.print_quantity("Pressure at the centre",
                           "MPa",
                           r.centre_pressure,
                           benchmark_geometry ? "p/p_MARC" :
                           sphere             ? "p/p_Hertz" :
                                                "p/p_halfspace",
                           r.centre_pressure / (benchmark_geometry ?
                                                  p_centre_marc :
                                                  half_space.pressure(0.)));
    console.print_quantity("Contact radius",
                           "mm",
                           r.contact_radius,
                           "a/a_halfspace",
                           r.contact_radius / half_space.contact_radius());
    if (marc_has_mu)
      console.print_quantity("Foundation top on the axis, u_z",
                             "mm",
                             r.axis_displacement,
                             "uz/uz_MARC",
                             r.axis_displacement / uz_marc);
    if (marc_has_mu)
      {
        // Outside the contact zone the displacements depend on the total
        // load rather than on its distribution.
        for (const auto &p : marc_surface)
          if (p.r == 60. || p.r == 80.)
            console.print_quantity(
              "Foundation top at r = " + std::to_string(static_cast<int>(p.r)) +
                " mm, u_z",
              "mm",
              surface_displacement_at(surface, p.r, 1),
              "uz/uz_MARC",
              surface_displacement_at(surface, p.r, 1) / marc_uz(p));
        console.print_quantity("Foundation top, largest inward u_r",
                               "mm",
                               ur_min,
                               "ur/ur_MARC",
                               ur_min / marc_ur_min);
        console.print_quantity("  at radius", "mm", ur_min_radius);
      }
    if (friction)
      console.print_quantity("Peak tangential traction",
                             "MPa",
                             r.peak_tangential_traction);

    if (root)
      {
        Common::Contact::write_profile_csv(out.path("contact_profile.csv"),
                                           r.profile,
                                           0);
        std::ofstream reference(out.path("reference_profile.csv"));
        reference << "r,half_space_pressure\n" << std::setprecision(8);
        const double a_ref = half_space.contact_radius();
        for (unsigned int i = 0; i <= 600; ++i)
          {
            const double x = 1.25 * a_ref * i / 600.;
            reference << x << ',' << half_space.pressure(x) << '\n';
          }
        std::ofstream displacements(out.path("surface_displacement.csv"));
        displacements << "r,u_r,u_z\n" << std::setprecision(8);
        for (const auto &p : surface)
          displacements << p.position[0] << ',' << p.displacement[0] << ','
                        << p.displacement[1] << '\n';
        if (benchmark_geometry)
          {
            std::ofstream marc_displacements(
              out.path("marc_surface_displacement.csv"));
            marc_displacements << "r,u_r_mu0,u_z_mu0,u_r_mu01,u_z_mu01\n";
            // A value the reference does not give is an empty field (a
            // missing point to gnuplot and to CSV readers), not "nan".
            const auto field = [](const double value) {
              std::ostringstream text;
              if (std::isfinite(value))
                text << value;
              return text.str();
            };
            for (const auto &p : marc_surface)
              marc_displacements << p.r << ',' << field(p.ur_mu0) << ','
                                 << field(p.uz_mu0) << ',' << field(p.ur_mu01)
                                 << ',' << field(p.uz_mu01) << '\n';
            std::ofstream curves(out.path("fe_reference.csv"));
            curves << "r,pressure_marc,pressure_abaqus,"
                      "tangential_traction_marc,tangential_traction_abaqus\n";
            for (const auto &p : fe_reference)
              curves << p.r << ',' << p.pressure_marc << ','
                     << p.pressure_abaqus << ',' << p.traction_marc << ','
                     << p.traction_abaqus << '\n';
          }
      }

    if (out.write_plots && root)
      {
        const std::string fe_label =
          "FE, Q" + std::to_string(parameters.mesh.element_degree) +
          (dim == 2 ? " axisymmetric" : " 3D quarter, plane z = 0");
        const std::string  fe_style = "linespoints pt 7 ps 0.5";
        std::ostringstream mu_stream;
        mu_stream << mu;
        const std::string x_label =
          "r, distance from the axis (reference configuration) [mm]";
        const std::string x_range =
          "[0:" + std::to_string(1.25 * half_space.contact_radius()) + "]";
        std::vector<std::pair<std::string, Common::IO::PlotDescription>> plots;

        Common::IO::PlotDescription pressure;
        pressure.title =
          (benchmark_geometry ?
             "Contact pressure, rounded punch (benchmark 2), mu = " :
           sphere ? "Contact pressure, hemispherical punch (Hertz), mu = " :
                    "Contact pressure, rounded punch, mu = ") +
          mu_stream.str();
        pressure.x_label = x_label;
        pressure.y_label = "contact pressure [MPa]";
        pressure.x_range = x_range;
        pressure.series  = {
           {"reference_profile.csv",
            1,
            2,
           sphere ? "Hertz (half-space)" : "half-space",
            "lines lw 2"},
           {"fe_reference.csv",
            1,
            2,
            "MSC.Marc (mu = 0.1)",
            "points pt 6 ps 1.5"},
           {"fe_reference.csv", 1, 3, "Abaqus (mu = 0.1)", "points pt 4 ps 1.5"},
           {"contact_profile.csv", 1, 2, fe_label, fe_style}};
        // Only the benchmark's geometry has MSC.Marc and Abaqus curves.
        const auto drop_fe_references = [&](auto &series) {
          if (!benchmark_geometry)
            series.erase(
              std::remove_if(series.begin(),
                             series.end(),
                             [](const auto &curve) {
                               return curve.data_file.rfind("fe_", 0) == 0 ||
                                      curve.data_file.rfind("marc_", 0) == 0;
                             }),
              series.end());
        };
        drop_fe_references(pressure.series);
        plots.emplace_back("contact_pressure", pressure);

        Common::IO::PlotDescription traction;
        traction.title =
          "Tangential traction on the foundation, mu = " + mu_stream.str();
        traction.x_label = x_label;
        traction.y_label = "tangential traction (+r) [MPa]";
        traction.x_range = x_range;
        traction.series  = {
           {"fe_reference.csv",
            1,
            4,
            "MSC.Marc (mu = 0.1)",
            "points pt 6 ps 1.5"},
           {"fe_reference.csv", 1, 5, "Abaqus (mu = 0.1)", "points pt 4 ps 1.5"},
           {"contact_profile.csv", 1, 3, fe_label, fe_style}};
        drop_fe_references(traction.series);
        plots.emplace_back("tangential_traction", traction);

        Common::IO::PlotDescription slip;
        slip.title   = "Slip accumulated in contact, mu = " + mu_stream.str();
        slip.x_label = x_label;
        slip.y_label = "slip, punch relative to foundation, along +r [mm]";
        slip.x_range = x_range;
        slip.series  = {{"contact_profile.csv", 1, 4, fe_label, fe_style}};
        plots.emplace_back("slip", slip);

        // MSC.Marc's curves of this mu (columns 2-3 for mu = 0, 4-5 for
        // mu = 0.1); both for any other mu.
        const std::string foundation_x_label =
          "r, distance from the axis on the foundation top [mm]";
        for (const unsigned int c : {0u, 1u})
          {
            const std::string           name = c == 0 ? "u_r" : "u_z";
            Common::IO::PlotDescription plot;
            plot.title =
              "Foundation top, " + name + ", mu = " + mu_stream.str();
            plot.x_label = foundation_x_label;
            plot.y_label =
              name + (c == 0 ? " (+ away from the axis) [mm]" : " [mm]");
            plot.x_range =
              "[0:" + std::to_string(parameters.geometry.foundation_radius) +
              "]";
            for (const bool friction_curve : {false, true})
              if (!marc_has_mu || friction_curve == (mu != 0.))
                plot.series.push_back(
                  {"marc_surface_displacement.csv",
                   1,
                   (friction_curve ? 4u : 2u) + c,
                   friction_curve ? "MSC.Marc (mu = 0.1)" : "MSC.Marc (mu = 0)",
                   friction_curve ? "points pt 4 ps 1.5" :
                                    "points pt 6 ps 1.5"});
            plot.series.push_back(
              {"surface_displacement.csv", 1, 2 + c, fe_label, "lines lw 2"});
            drop_fe_references(plot.series);
            plots.emplace_back("surface_displacement_" + name, plot);
          }

        this->write_plots(plots);
      }

    // summary.json
    JsonObject case_description =
      Common::Problems::case_summary(parameters,
                                     parameters.mesh.element_degree,
                                     mpi_communicator);
    case_description.set("model", dim == 2 ? "axisymmetric" : "3d quarter")
      .set("punch",
           parameters.model.rigid_surface ? "rigid surface" :
           parameters.model.rigid_punch   ? "rigid" :
                                            "elastic")
      .set("global_refinements", parameters.mesh.n_global_refinements)
      .set("contact_refinements", parameters.mesh.n_contact_refinements)
      .set("edge_refinements", parameters.mesh.n_edge_refinements);

    const double     Hf = parameters.geometry.foundation_height;
    const double     a  = parameters.geometry.punch_radius;
    const JsonObject mesh =
      Common::Problems::mesh_summary<dim>(dof_handler,
                                          [Hf, a](const Point<dim> &p) {
                                            return std::abs(p[1] - Hf) +
                                                   std::max(0., radius(p) - a);
                                          });


    JsonObject results;
    results.set("pressure_at_centre_MPa", r.centre_pressure)
      .set("centre_node_radius_mm", r.centre_radius)
      .set("peak_pressure_MPa", r.peak_pressure)
      .set("peak_pressure_radius_mm", r.peak_radius)
      .set("contact_radius_mm", r.contact_radius)
      .set("foundation_top_axis_uz_mm", r.axis_displacement)
      .set("contact_force_N", r.contact_force)
      .set("applied_force_N", r.applied_force)
      .set("force_balance_relative_error", force_error)
      .set("peak_tangential_traction_MPa", r.peak_tangential_traction)
      .set("n_active_nodes", enforcement.n_active());
    if (friction)
      results.set("stick_radius_mm", r.stick_radius);
    JsonObject foundation_top;
    foundation_top.set("uz_axis_mm", r.axis_displacement)
      .set("uz_r20_mm", surface_displacement_at(surface, 20., 1))
      .set("uz_r40_mm", surface_displacement_at(surface, 40., 1))
      .set("uz_r60_mm", surface_displacement_at(surface, 60., 1))
      .set("uz_r80_mm", surface_displacement_at(surface, 80., 1))
      .set("min_ur_mm", ur_min)
      .set("min_ur_radius_mm", ur_min_radius);
    results.set("foundation_top", foundation_top);

    JsonObject reference;
    reference
      .set(
        "source",
        benchmark_geometry ?
          "half-space solution of a rounded flat punch (doc/references.md "
          "2.1); MSC.Marc/Abaqus curves of NAFEMS R0094 (doc/references.md "
          "2.2)" :
        sphere ?
          "Hertz point contact: the half-space solution of doc/references.md "
          "2.1 with flat radius b = 0" :
          "half-space solution of a rounded flat punch (doc/references.md "
          "2.1)")
      .set("half_space_contact_radius_mm", half_space.contact_radius())
      .set("half_space_pressure_at_centre_MPa", half_space.pressure(0.));
    if (benchmark_geometry)
      reference.set("marc_pressure_at_centre_MPa", p_centre_marc);
    if (marc_has_mu)
      {
        reference.set("marc_foundation_top_axis_uz_mm", uz_marc);
        JsonObject marc_top;
        for (const auto &p : marc_surface)
          if (p.r == 20. || p.r == 40. || p.r == 60. || p.r == 80.)
            marc_top.set("uz_r" + std::to_string(static_cast<int>(p.r)) + "_mm",
                         marc_uz(p));
        marc_top.set("min_ur_mm", marc_ur_min);
        reference.set("marc_foundation_top", marc_top);
      }

    JsonObject ratios;
    ratios
      .set("pressure_at_centre_half_space",
           r.centre_pressure / half_space.pressure(0.))
      .set("contact_radius_half_space",
           r.contact_radius / half_space.contact_radius());
    if (benchmark_geometry)
      ratios.set("pressure_at_centre_marc", r.centre_pressure / p_centre_marc);
    if (marc_has_mu)
      {
        ratios.set("foundation_top_axis_uz_marc",
                   r.axis_displacement / uz_marc);
        for (const auto &p : marc_surface)
          if (p.r == 60. || p.r == 80.)
            ratios.set("foundation_top_uz_r" +
                         std::to_string(static_cast<int>(p.r)) + "_marc",
                       surface_displacement_at(surface, p.r, 1) / marc_uz(p));
        ratios.set("foundation_top_min_ur_marc", ur_min / marc_ur_min);
      }

    this->write_summary(stepping,
                        {case_description, mesh, results, reference, ratios});
  }



  template void
  PunchProblem<2>::output_results(
    const Common::Solvers::LoadSteppingStatistics &);
  template void
  PunchProblem<3>::output_results(
    const Common::Solvers::LoadSteppingStatistics &);
} // namespace Punch3d
