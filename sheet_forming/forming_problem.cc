/*
 * Benchmark 3 of the FENET/NAFEMS advanced contact benchmarks: mesh,
 * tools, boundary conditions, load program and the per-step record; see
 * README.md.
 */
#include "forming_problem.h"

#include <common/geometry/two_body_meshes.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/boundary_displacement.h>
#include <common/physics/solid_model.h>
#include <common/problems/contact_run.h>

#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>

namespace SheetForming
{
  template <int dim>
  FormingProblem<dim>::FormingProblem(const Parameters &parameters)
    : Base(parameters, parameters.mesh.element_degree, "sheet_forming")
    , parameters(parameters)
    , hold_dof(numbers::invalid_dof_index)
  {}



  template <int dim>
  std::string
  FormingProblem<dim>::title() const
  {
    return std::string("sheet_forming: aluminium strip bent by a rigid punch "
                       "into a rigid die, then released (") +
           (dim == 2 ? "plane strain half model" :
                       "3D strip, quarter model, edge free") +
           ")";
  }



  template <int dim>
  double
  FormingProblem<dim>::full_strip_factor() const
  {
    return dim == 2 ? 2. * parameters.geometry.width : 4.;
  }



  template <int dim>
  std::vector<std::string>
  FormingProblem<dim>::result_files() const
  {
    std::vector<std::string> files = {"punch_force.csv",
                                      "punch_force.png",
                                      "punch_force.gp"};
    for (const std::string tag : {"formed", "released"})
      for (const std::string &stem : {"strip_" + tag,
                                      "tools_" + tag,
                                      "contact_" + tag + "_top",
                                      "contact_" + tag + "_bottom"})
        files.push_back(stem + ".csv");
    // The contact plots of a state with no paired node (the released
    // strip, the tools withdrawn) are not drawn.
    for (const std::string tag : {"formed", "released"})
      for (const std::string &stem : {"shape_" + tag,
                                      "contact_" + tag + "_pressure",
                                      "contact_" + tag + "_slip"})
        {
          files.push_back(stem + ".png");
          files.push_back(stem + ".gp");
        }
    return files;
  }



  // The sheet 0 <= x <= L/2, 0 <= y <= t (0 <= z <= W/2 in 3D), and one
  // carrier cell per tool apart from it: the carriers' nodes are the
  // tools' reference nodes.
  template <int dim>
  void
  FormingProblem<dim>::make_grid()
  {
    const auto               &g           = parameters.geometry;
    const auto               &m           = parameters.mesh;
    std::vector<unsigned int> repetitions = {m.n_cells_length,
                                             m.n_cells_thickness};
    Point<dim>                upper;
    upper[0] = g.sheet_half_length;
    upper[1] = g.thickness;
    if constexpr (dim == 3)
      {
        repetitions.push_back(m.n_cells_width);
        upper[2] = 0.5 * g.width;
      }
    Triangulation<dim> sheet, punch, die;
    GridGenerator::subdivided_hyper_rectangle(sheet,
                                              repetitions,
                                              Point<dim>(),
                                              upper);
    const double tolerance = 1e-8 * g.thickness;
    for (const auto &cell : sheet.active_cell_iterators())
      {
        cell->set_material_id(MaterialIds::sheet);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const auto c = face->center();
              if (dim == 3 && std::abs(c[dim - 1]) < tolerance)
                face->set_boundary_id(BoundaryIds::width_symmetry);
              else if (dim == 3 &&
                       std::abs(c[dim - 1] - upper[dim - 1]) < tolerance)
                face->set_boundary_id(BoundaryIds::edge);
              else
                face->set_boundary_id(
                  std::abs(c[0]) < tolerance ? BoundaryIds::symmetry :
                  std::abs(c[0] - g.sheet_half_length) < tolerance ?
                                               BoundaryIds::end :
                                               BoundaryIds::surface);
            }
      }
    Common::Geometry::perturb_interior_vertices(
      sheet,
      parameters.mesh.interior_perturbation,
      "Mesh: 'Interior node perturbation'");
    // Carriers left of the axis, clear of the sheet and the tools' paths:
    // cubes of the sheet's thickness (squares in 2D) with their lower
    // corner at (x, y, 0).
    const double size = g.thickness;
    const auto   place =
      [size](Triangulation<dim> &carrier, const double x, const double y) {
        Point<dim> lower, upper;
        lower[0] = x;
        lower[1] = y;
        for (unsigned int d = 0; d < dim; ++d)
          upper[d] = lower[d] + size;
        GridGenerator::hyper_rectangle(carrier, lower, upper);
      };
    place(punch, -g.die_radius - 10., 10.);
    place(die, -g.die_radius - 10., -10.);
    for (const auto &cell : punch.active_cell_iterators())
      cell->set_material_id(MaterialIds::punch_carrier);
    for (const auto &cell : die.active_cell_iterators())
      cell->set_material_id(MaterialIds::die_carrier);
    Common::Geometry::join_bodies<dim>({&sheet, &punch, &die}, triangulation);
  }



  // The punch: a circle of radius Rp about (0, t + Rp), touching the
  // sheet's top on the axis (raised by the initial gap of the robustness
  // tests), continued upward by its vertical side. The
  // die, material below: the flat top y = 0 from outside the sheet's end,
  // the shoulder fillet about (R2 + R3, -R3) and the cavity about
  // (0, -R3). Both arcs reach a little past the axis. A profile keeps its
  // body on its left.
  template <int dim>
  std::vector<Common::Contact::RigidTool<dim>>
  FormingProblem<dim>::make_tools() const
  {
    const auto    &g    = parameters.geometry;
    const double   pi   = numbers::PI;
    const double   past = 0.2; // rad past the axis
    const double   Rp   = g.punch_radius;
    const double   R2   = g.die_radius;
    const double   R3   = g.shoulder_radius;
    const double   xs   = g.shoulder_centre_x();
    const Point<2> punch_centre(0., g.punch_centre_y());

    Common::Contact::RigidProfile punch;
    punch.add_arc(punch_centre, Rp, -0.5 * pi - past, 0.);
    punch.add_line(Point<2>(Rp, punch_centre[1]),
                   Point<2>(Rp, punch_centre[1] + 2. * Rp));

    Common::Contact::RigidProfile die;
    die.add_line(Point<2>(g.sheet_half_length + 2. * R2, 0.), Point<2>(xs, 0.));
    die.add_arc(Point<2>(xs, -R3), R3, 0.5 * pi, pi);
    die.add_arc(Point<2>(0., -R3), R2, 0., -0.5 * pi - past);

    // In 3D both extruded along z, wider than the strip.
    const auto extrude = Common::Contact::ProfileSweep::extrusion_along_z;
    std::vector<Common::Contact::RigidTool<dim>> tools(2);
    tools[0].name = "punch";
    tools[0].surface =
      std::make_shared<const Common::Contact::RigidSurface<dim>>(punch,
                                                                 extrude);
    tools[0].reference_node_dofs = punch_carrier.reference_node_dofs;
    tools[0].centre[1]           = punch_centre[1];
    tools[1].name                = "die";
    tools[1].surface =
      std::make_shared<const Common::Contact::RigidSurface<dim>>(die, extrude);
    tools[1].reference_node_dofs = die_carrier.reference_node_dofs;
    tools[1].centre[1]           = -R3;
    return tools;
  }



  template <int dim>
  void
  FormingProblem<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);

    // u_x = 0 on the symmetry plane (and u_z = 0 on the one across the
    // width in 3D); the tools' carriers move as the load program
    // prescribes. Nothing else holds the sheet.
    std::vector<std::pair<unsigned int, std::vector<types::boundary_id>>>
      zero_components = {{0, {BoundaryIds::symmetry}}};
    if (dim == 3)
      zero_components.push_back({dim - 1, {BoundaryIds::width_symmetry}});
    Common::Physics::make_homogeneous_constraints<dim>(
      mapping,
      dof_handler,
      {},
      zero_components,
      constraints_dirichlet_and_hanging_nodes);
    punch_carrier = Common::Physics::add_prescribed_translation_constraints(
      dof_handler,
      MaterialIds::punch_carrier,
      constraints_dirichlet_and_hanging_nodes);
    die_carrier = Common::Physics::add_prescribed_translation_constraints(
      dof_handler,
      MaterialIds::die_carrier,
      constraints_dirichlet_and_hanging_nodes);

    // The node held by the release: on the axis, nearest the mid-plane
    // (not a contact node); in 3D on the plane z = 0. With the symmetry
    // planes it removes the only rigid motion left, along y.
    const auto  &g = parameters.geometry;
    const double h = g.thickness / (parameters.mesh.n_cells_thickness *
                                    parameters.mesh.element_degree);
    const double y_hold =
      std::max(h,
               std::min(g.thickness - h,
                        h * std::round(0.5 * g.thickness / h)));
    hold_dof = numbers::invalid_dof_index;
    {
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      Point<dim>                           target;
      target[1] = y_hold;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->material_id() == MaterialIds::sheet &&
            cell->center()[0] <
              g.sheet_half_length / parameters.mesh.n_cells_length)
          {
            const auto &points = fe.get_unit_support_points();
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (fe.system_to_component_index(i).first == 1 &&
                  mapping.transform_unit_to_real_cell(cell, points[i])
                      .distance(target) < 1e-8 * g.thickness)
                hold_dof = dofs[i];
          }
      AssertThrow(hold_dof != numbers::invalid_dof_index,
                  ExcMessage("No node on the axis at mid-thickness."));
    }

    const double E = parameters.sheet_material.youngs_modulus;
    auto         geometry =
      std::make_unique<Common::Contact::CurrentMortarGeometry<dim>>(
        dof_handler,
        mapping,
        BoundaryIds::surface,
        make_tools(),
        parameters.contact.search_distance,
        false);
    geometry->set_rigid_tool_gap(parameters.contact.rigid_tool_gap);
    this->setup_contact_problem(
      Common::Physics::create_solid_operator<dim>(
        parameters.solid,
        mapping,
        fe,
        {{MaterialIds::sheet, parameters.sheet_material},
         {MaterialIds::punch_carrier, parameters.sheet_material},
         {MaterialIds::die_carrier, parameters.sheet_material}}),
      std::move(geometry),
      E);
  }



  // No applied forces: the tools move. The scale of the residuals is the
  // force per unit depth that strains the sheet's section by 1e-3 (times
  // the half-width in 3D).
  template <int dim>
  Common::Problems::ExternalLoad
  FormingProblem<dim>::external_load() const
  {
    Common::Problems::ExternalLoad load;
    load.add = [](const Common::Solvers::LoadState &,
                  const AffineConstraints<double> &,
                  TrilinosWrappers::MPI::Vector &) {
    };
    const double scale = 1e-3 * parameters.sheet_material.youngs_modulus *
                         parameters.geometry.thickness *
                         (dim == 3 ? 0.5 * parameters.geometry.width : 1.);
    load.magnitude = [scale](const Common::Solvers::LoadState &) {
      return scale;
    };
    load.prescribed_displacements =
      [this](const Common::Solvers::LoadState          &state,
             std::map<types::global_dof_index, double> &values) {
        Tensor<1, dim> punch, die;
        punch[1] = -state.value("Punch displacement");
        die[1]   = -state.value("Die displacement");
        punch_carrier.prescribe(punch, values);
        die_carrier.prescribe(die, values);
      };
    return load;
  }



  template <int dim>
  Point<2>
  FormingProblem<dim>::deformed_point(const double s,
                                      const double y,
                                      const double z) const
  {
    Point<dim> X;
    X[0] = s;
    X[1] = y;
    if (dim == 3)
      X[dim - 1] = z;
    const Tensor<1, dim> u =
      Common::Physics::displacement_at(mapping,
                                       dof_handler,
                                       contact_problem->displacement(),
                                       X,
                                       "a point of the sheet");
    return Point<2>(s + u[0], y + u[1]);
  }



  template <int dim>
  FlangeAngles
  FormingProblem<dim>::flange_angles(const double z) const
  {
    const auto  &g     = parameters.geometry;
    const double L     = g.sheet_half_length;
    const double mid   = 0.5 * g.thickness;
    const auto   end   = deformed_point(L, mid, z);
    const auto   angle = [&](const Point<2> &start) {
      const Tensor<1, 2> d = end - start;
      return std::atan2(std::abs(d[0]), d[1]) * 180. / numbers::PI;
    };
    FlangeAngles result;
    result.chord =
      angle(deformed_point(parameters.release.chord_start, mid, z));
    result.end_tangent =
      angle(deformed_point(L - parameters.release.end_tangent_length, mid, z));
    return result;
  }



  template <int dim>
  void
  FormingProblem<dim>::postprocess_step(
    const Common::Solvers::StepInfo         &step,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    Common::Problems::print_step(console, step, statistics, *contact_problem);

    // Forces of the sheet on the tools, and the support's reaction on the
    // sheet at the held node (the only vertical support): the sheet is in
    // equilibrium if they balance.
    const auto &geometry =
      static_cast<const Common::Contact::CurrentMortarGeometry<dim> &>(
        *contact_geometry);
    const auto loads =
      geometry.tool_loads(contact_problem->enforcement().state(),
                          dof_handler.locally_owned_dofs(),
                          mpi_communicator);
    const double full = full_strip_factor();
    ForceRecord  record;
    record.time               = step.state.time;
    record.punch_displacement = step.state.value("Punch displacement");
    record.die_displacement   = step.state.value("Die displacement");
    record.punch_force        = full * loads[0].force[1];
    record.die_force          = full * loads[1].force[1];
    record.hold_force =
      held ? full * contact_problem->reaction_force({hold_dof},
                                                    step.state,
                                                    external_load()) :
             0.;
    // Relative to the largest force so far: once the tools have let go,
    // every force is round-off, and so is their balance.
    double largest = std::max({std::abs(record.punch_force),
                               std::abs(record.die_force),
                               std::abs(record.hold_force)});
    for (const auto &earlier : forces)
      largest = std::max(largest, std::abs(earlier.punch_force));
    record.balance =
      largest > 0. ?
        std::abs(record.punch_force + record.die_force - record.hold_force) /
          largest :
        0.;
    forces.push_back(record);

    console.print_quantity("Punch displacement",
                           "mm",
                           record.punch_displacement);
    console.print_quantity("Punch force (full strip)", "N", record.punch_force);
    console.print_quantity("Die force (full strip)", "N", record.die_force);
    if (held)
      console.print_quantity("Held node reaction", "N", record.hold_force);
    const FlangeAngles angles = flange_angles();
    console.print_quantity("Flange angle (chord)", "deg", angles.chord);

    // The end of forming: keep the formed state's angles and shape, then
    // hold the axis node for the release.
    const unsigned int release = parameters.release.release_stage;
    if (release > 0 && !formed &&
        std::abs(step.state.time - (release - 1.)) < 1e-9)
      {
        formed         = true;
        forming_angles = angles;
        if (dim == 3)
          forming_angles_edge = flange_angles(0.5 * parameters.geometry.width);
        stroke       = record.punch_displacement;
        formed_shape = capture_shape();
        contact_problem->hold_dofs({hold_dof});
        held = true;
        console.stream() << "  Forming ends: the sheet's axis node at "
                            "mid-thickness is held for the release."
                         << std::endl;
      }
    Common::Problems::warn_if_search_edge_reached(console, *contact_problem);
  }



  template class FormingProblem<2>;
  template class FormingProblem<3>;
} // namespace SheetForming
