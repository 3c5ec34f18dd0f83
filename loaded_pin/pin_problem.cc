/*
 * Benchmark 4 of the FENET/NAFEMS advanced contact benchmarks: mesh,
 * boundary conditions, load and the contact results along the hole; see
 * README.md.
 */
#include "pin_problem.h"

#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/two_body_meshes.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/solid_model.h>
#include <common/problems/contact_run.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace LoadedPin
{
  PinProblem::PinProblem(const Parameters &parameters)
    : Base(parameters, parameters.mesh.element_degree, "loaded_pin")
    , parameters(parameters)
    , load_dof(numbers::invalid_dof_index)
    , pin_centre_dof(numbers::invalid_dof_index)
    , bearing_point_dof(numbers::invalid_dof_index)
    , lug_tip_dof(numbers::invalid_dof_index)
  {}



  std::string
  PinProblem::title() const
  {
    return "loaded_pin: steel pin pulled in the hole of an aluminium lug "
           "(3D quarter model)";
  }



  std::vector<std::string>
  PinProblem::result_files() const
  {
    return {"contact_profile_sheet_face.csv"};
  }



  void
  PinProblem::make_grid()
  {
    make_quarter_mesh(parameters.geometry,
                      parameters.mesh.options(),
                      triangulation);
  }



  void
  PinProblem::setup_system()
  {
    dof_handler.distribute_dofs(fe);

    // Homogeneous Dirichlet conditions on the Newton increment: the
    // clamped end of the sheet, u_y = 0 on y = 0 and u_z = 0 on z = 0 (both
    // bodies). The pin's x translation is held by contact alone.
    Common::Physics::make_homogeneous_constraints<dim>(
      mapping,
      dof_handler,
      {BoundaryIds::clamped},
      {{1, {BoundaryIds::symmetry_y0}}, {2, {BoundaryIds::symmetry_z0}}},
      constraints_dirichlet_and_hanging_nodes);

    const auto  &g         = parameters.geometry;
    const double tolerance = 1e-8 * g.hole_radius;
    const auto   x_dof     = [&](const Point<dim>        &p,
                           const types::material_id material,
                           const std::string       &what) {
      return Common::Geometry::vertex_dof(dof_handler,
                                          p,
                                          0,
                                          tolerance,
                                          what,
                                          material);
    };
    load_dof = x_dof(Point<dim>(0., 0., 0.5 * g.pin_length),
                     MaterialIds::pin,
                     "the centre of the pin's end face");
    pin_centre_dof =
      x_dof(Point<dim>(0., 0., 0.), MaterialIds::pin, "the centre of the pin");
    bearing_point_dof = x_dof(Point<dim>(g.hole_radius, 0., 0.),
                              MaterialIds::sheet,
                              "the sheet's bearing point");
    lug_tip_dof       = x_dof(Point<dim>(g.outer_radius, 0., 0.),
                        MaterialIds::sheet,
                        "the lug's tip");

    setup_contact_problem(Common::Physics::create_solid_operator<dim>(
                            parameters.solid,
                            mapping,
                            fe,
                            {{MaterialIds::pin, parameters.pin_material},
                             {MaterialIds::sheet, parameters.sheet_material}}),
                          Common::Contact::create_mortar_geometry<dim>(
                            dof_handler,
                            mapping,
                            parameters.contact,
                            parameters.solid.finite_strain(),
                            false),
                          parameters.sheet_material.youngs_modulus);
  }



  double
  PinProblem::applied_force(const double load_factor) const
  {
    return 0.25 * load_factor * parameters.loading.total_force;
  }



  // The quarter model carries half of one end face's force (its centre
  // lies on the symmetry plane y = 0): a quarter of the total, along +x.
  Common::Problems::ExternalLoad
  PinProblem::external_load() const
  {
    return Common::Problems::point_load(dof_handler,
                                        load_dof,
                                        applied_force(1.));
  }



  double
  PinProblem::displacement_at(const types::global_dof_index dof) const
  {
    const auto  &u = contact_problem->displacement();
    const double local =
      dof_handler.locally_owned_dofs().is_element(dof) ? u(dof) : 0.;
    return Utilities::MPI::sum(local, mpi_communicator);
  }



  double
  PinProblem::contact_resultant() const
  {
    return Common::Contact::total_contact_force(
      contact_problem->coupling(),
      contact_problem->enforcement())[0];
  }



  PinContactLine
  PinProblem::contact_line(const double z) const
  {
    PinContactLine line;
    line.z = z;
    const auto profile =
      Common::Contact::contact_profile(contact_problem->coupling(),
                                       contact_problem->enforcement(),
                                       contact_problem->displacement(),
                                       contact_problem->bulk_residual(),
                                       0);
    const double tolerance = 1e-8 * parameters.geometry.hole_radius;
    std::vector<Common::Contact::ContactPointResult<dim>> along_phi;
    for (const auto &p : profile)
      if (std::abs(p.position[2] - z) < tolerance)
        {
          const double         phi = std::atan2(p.position[1], p.position[0]);
          const Tensor<1, dim> e_theta({std::sin(phi), -std::cos(phi), 0.});
          PinContactPoint      point;
          point.theta    = 180. - phi * 180. / numbers::PI;
          point.position = p.position;
          point.pressure = p.pressure;
          // The sheet is the secondary side: the traction on the pin is
          // the opposite of the one on the sheet.
          point.q_theta    = -(p.tangential_traction_vector * e_theta);
          point.q_z        = -p.tangential_traction_vector[2];
          point.slip_theta = p.relative_displacement_vector * e_theta;
          point.accumulated_slip_theta = p.slip_vector * e_theta;
          point.gap                    = p.gap;
          point.status                 = p.status;
          line.points.push_back(point);

          // The same point with its arc angle from the bearing point in
          // place of x, for the contact and stick extents.
          auto by_phi        = p;
          by_phi.position[0] = 180. - point.theta;
          along_phi.push_back(by_phi);
        }
    std::sort(line.points.begin(),
              line.points.end(),
              [](const auto &a, const auto &b) { return a.theta > b.theta; });
    std::sort(along_phi.begin(),
              along_phi.end(),
              [](const auto &a, const auto &b) {
                return a.position[0] < b.position[0];
              });
    if (line.points.empty())
      return line;

    for (const auto &p : line.points)
      {
        if (p.pressure > line.peak_pressure)
          {
            line.peak_pressure       = p.pressure;
            line.peak_pressure_theta = p.theta;
          }
        if (std::abs(p.q_theta) > line.peak_traction)
          {
            line.peak_traction       = std::abs(p.q_theta);
            line.peak_traction_theta = p.theta;
          }
        line.max_slip = std::max(line.max_slip, std::abs(p.slip_theta));
      }
    // The parabola through the largest nodal pressure and its neighbours.
    line.fitted_peak_pressure       = line.peak_pressure;
    line.fitted_peak_pressure_theta = line.peak_pressure_theta;
    for (unsigned int i = 1; i + 1 < line.points.size(); ++i)
      if (line.points[i].pressure == line.peak_pressure)
        {
          const double x0 = line.points[i - 1].theta,
                       y0 = line.points[i - 1].pressure;
          const double x1 = line.points[i].theta, y1 = line.points[i].pressure;
          const double x2 = line.points[i + 1].theta,
                       y2 = line.points[i + 1].pressure;
          // Divided differences: p(x) = y1 + b (x - x1) + c (x - x1)^2.
          const double d01 = (y1 - y0) / (x1 - x0);
          const double d12 = (y2 - y1) / (x2 - x1);
          const double c   = (d12 - d01) / (x2 - x0);
          const double b   = d01 + c * (x1 - x0);
          if (c < 0.)
            {
              const double x                  = std::clamp(x1 - 0.5 * b / c,
                                          std::min(x0, x2),
                                          std::max(x0, x2));
              line.fitted_peak_pressure_theta = x;
              line.fitted_peak_pressure =
                y1 + b * (x - x1) + c * (x - x1) * (x - x1);
            }
          break;
        }

    const double phi_0 = along_phi.front().position[0];
    line.arc_end_theta =
      180. - phi_0 - Common::Contact::contact_extent(along_phi, 0);
    if (contact_problem->enforcement().has_friction())
      line.stick_end_theta =
        180. - phi_0 - Common::Contact::stick_extent(along_phi, 0);
    return line;
  }



  void
  PinProblem::postprocess_step(
    const Common::Solvers::StepInfo         &step,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    Common::Problems::print_step(console, step, statistics, *contact_problem);
    const double applied = applied_force(step.state.load_factor());
    const double force   = contact_resultant();
    console.print_quantity("Contact force, x",
                           "N",
                           force,
                           "F/F_applied",
                           force / applied);
    const PinContactLine mid = contact_line(0.);
    console.print_quantity("Contact arc end, mid-plane",
                           "deg",
                           mid.arc_end_theta);
    console.print_quantity("Peak pressure, mid-plane",
                           "MPa",
                           mid.peak_pressure);
    console.print_quantity("  at theta", "deg", mid.peak_pressure_theta);
    console.print_quantity("Pin centre, u_x",
                           "mm",
                           displacement_at(pin_centre_dof));
    Common::Problems::warn_if_search_edge_reached(console, *contact_problem);
  }
} // namespace LoadedPin
