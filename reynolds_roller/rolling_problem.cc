/*
 * Benchmark 5 of the FENET/NAFEMS advanced contact benchmarks: mesh,
 * roller, supports, load program and the per-step record; see README.md.
 */
#include "rolling_problem.h"

#include <common/geometry/two_body_meshes.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/boundary_displacement.h>
#include <common/physics/finite_strain_solid.h>
#include <common/physics/solid_model.h>
#include <common/problems/contact_run.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace ReynoldsRoller
{
  template <int dim>
  RollingProblem<dim>::RollingProblem(const Parameters &parameters)
    : Base(parameters, parameters.mesh.element_degree, "reynolds_roller")
    , parameters(parameters)
  {}



  template <int dim>
  std::string
  RollingProblem<dim>::title() const
  {
    return std::string("reynolds_roller: ") +
           (parameters.geometry.elastic_roller ? "elastic" : "rigid") +
           " steel roller pressed into a rubber strip and turned (" +
           (dim == 2 ? "plane strain" : "3D extrusion, u_z = 0 on its faces") +
           ")";
  }



  template <int dim>
  double
  RollingProblem<dim>::depth() const
  {
    return dim == 3 ? parameters.geometry.width : 1.;
  }



  template <int dim>
  Tensor<1, 2>
  RollingProblem<dim>::per_unit_depth(const Tensor<1, dim> &force) const
  {
    return Tensor<1, 2>({force[0], force[1]}) / depth();
  }



  template <int dim>
  std::vector<std::string>
  RollingProblem<dim>::result_files() const
  {
    return {"history.csv",
            "creep.png",
            "creep.gp",
            "roller_loads.png",
            "roller_loads.gp",
            "corners.png",
            "corners.gp",
            "contact_half_turn.csv",
            "contact_half_turn_tractions.png",
            "contact_half_turn_tractions.gp",
            "contact_half_turn_slip.png",
            "contact_half_turn_slip.gp"};
  }



  template <int dim>
  std::array<Point<dim>, n_corners>
  RollingProblem<dim>::corners() const
  {
    const auto                                        &g = parameters.geometry;
    const double                                       h = 0.5 * g.thickness;
    std::array<Point<dim>, n_corners>                  points;
    const std::array<std::array<double, 2>, n_corners> xy = {
      {{{-g.length_behind, h}},
       {{-g.length_behind, -h}},
       {{g.length_ahead, h}},
       {{g.length_ahead, -h}}}};
    for (unsigned int c = 0; c < n_corners; ++c)
      for (unsigned int d = 0; d < 2; ++d)
        points[c][d] = xy[c][d];
    return points;
  }



  // The strip [-L1, L2] x [-H/2, H/2] (x [0, W] in 3D) and, apart from
  // it, one carrier cell whose first vertex is the roller's reference
  // node.
  template <int dim>
  void
  RollingProblem<dim>::make_grid()
  {
    const auto               &g           = parameters.geometry;
    const double              h           = 0.5 * g.thickness;
    const auto               &m           = parameters.mesh;
    std::vector<unsigned int> repetitions = {m.n_cells_length,
                                             m.n_cells_thickness};
    Point<dim>                lower, upper, carrier_lower, carrier_upper;
    lower[0]         = -g.length_behind;
    lower[1]         = -h;
    upper[0]         = g.length_ahead;
    upper[1]         = h;
    carrier_lower[0] = -g.length_behind - 2. * g.thickness;
    carrier_lower[1] = -h;
    carrier_upper[0] = -g.length_behind - g.thickness;
    carrier_upper[1] = 0.;
    if constexpr (dim == 3)
      {
        repetitions.push_back(m.n_cells_width);
        upper[2]         = g.width;
        carrier_upper[2] = g.width;
      }
    Triangulation<dim> strip, carrier;
    GridGenerator::subdivided_hyper_rectangle(strip, repetitions, lower, upper);
    const double tolerance = 1e-8 * g.thickness;
    for (const auto &cell : strip.active_cell_iterators())
      {
        cell->set_material_id(MaterialIds::strip);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const auto c = face->center();
              const bool side =
                dim == 3 && (std::abs(c[dim - 1]) < tolerance ||
                             std::abs(c[dim - 1] - upper[dim - 1]) < tolerance);
              face->set_boundary_id(
                side                           ? BoundaryIds::sides :
                std::abs(c[1] + h) < tolerance ? BoundaryIds::bottom :
                std::abs(c[1] - h) < tolerance ? BoundaryIds::top :
                                                 BoundaryIds::ends);
            }
      }
    Common::Geometry::perturb_interior_vertices(
      strip,
      m.interior_perturbation,
      "Mesh: 'Interior node perturbation'");
    if (g.elastic_roller)
      {
        // The ring from the hub to the rim about the axis (concentric
        // shells, evenly spaced: the skewness is near zero), its cells on
        // a spherical manifold.
        if constexpr (dim == 2)
          GridGenerator::concentric_hyper_shells(carrier,
                                                 roller_centre(),
                                                 g.hub_radius,
                                                 g.roller_radius,
                                                 m.n_cells_across_ring,
                                                 1e-3,
                                                 m.n_cells_around_roller,
                                                 false);
        for (const auto &cell : carrier.active_cell_iterators())
          {
            cell->set_material_id(MaterialIds::roller);
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                face->set_boundary_id(face->center().distance(roller_centre()) <
                                          0.5 *
                                            (g.hub_radius + g.roller_radius) ?
                                        BoundaryIds::roller_hub :
                                        BoundaryIds::roller_rim);
          }
      }
    else
      {
        // Behind the strip's left end, clear of the roller.
        GridGenerator::hyper_rectangle(carrier, carrier_lower, carrier_upper);
        for (const auto &cell : carrier.active_cell_iterators())
          cell->set_material_id(MaterialIds::roller_carrier);
      }
    Common::Geometry::join_bodies<dim>({&strip, &carrier}, triangulation);
  }



  template <int dim>
  Point<dim>
  RollingProblem<dim>::roller_centre() const
  {
    Point<dim>  centre;
    const auto &g = parameters.geometry;
    centre[1]     = 0.5 * g.thickness + g.roller_radius + g.initial_gap;
    return centre;
  }



  template <int dim>
  double
  RollingProblem<dim>::contact_modulus() const
  {
    const double rubber = parameters.rubber_material.youngs_modulus;
    if (!parameters.geometry.elastic_roller)
      return rubber;
    const double roller = parameters.roller_material.youngs_modulus;
    return 1. / (1. / rubber + 1. / roller);
  }



  template <int dim>
  Common::Contact::RigidTool<dim>
  RollingProblem<dim>::make_roller() const
  {
    const auto    &g = parameters.geometry;
    const double   R = g.roller_radius;
    const Point<2> centre(roller_centre()[0], roller_centre()[1]);
    // A full circle, counterclockwise (the roller on its left); its seam
    // starts behind the contact zone and meets the strip only after most
    // of a turn, where the circle is as smooth as anywhere.
    const double                  start = -0.5 * numbers::PI - 1.;
    Common::Contact::RigidProfile circle;
    circle.add_arc(centre, R, start, start + 2. * numbers::PI);

    Common::Contact::RigidTool<dim> roller;
    roller.name    = "roller";
    roller.surface = std::make_shared<const Common::Contact::RigidSurface<dim>>(
      circle,
      Common::Contact::ProfileSweep::extrusion_along_z);
    roller.reference_node_dofs = roller_carrier.reference_node_dofs;
    roller.centre[0]           = centre[0];
    roller.centre[1]           = centre[1];
    // The channel is clockwise in degrees; the tool's angle is
    // counterclockwise in radians.
    roller.rotation = [](const Common::Solvers::LoadState &state) {
      return -state.value("Roller angle") * numbers::PI / 180.;
    };
    return roller;
  }



  template <int dim>
  void
  RollingProblem<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);

    // The bottom's y DoFs carry the indentation; the roller's carrier is
    // fixed (the axis does not move); in 3D the z faces are held in z.
    std::vector<std::pair<unsigned int, std::vector<types::boundary_id>>>
      zero_components = {{1, {BoundaryIds::bottom}}};
    if (dim == 3)
      zero_components.push_back({dim - 1, {BoundaryIds::sides}});
    // The elastic roller's hub is turned rigidly: every DoF of its nodes
    // is prescribed.
    std::vector<types::boundary_id> clamped;
    if (parameters.geometry.elastic_roller)
      clamped.push_back(BoundaryIds::roller_hub);
    Common::Physics::make_homogeneous_constraints<dim>(
      mapping,
      dof_handler,
      clamped,
      zero_components,
      constraints_dirichlet_and_hanging_nodes);
    hub_dofs.clear();
    if (parameters.geometry.elastic_roller)
      {
        const IndexSet hub =
          DoFTools::extract_boundary_dofs(dof_handler,
                                          fe.component_mask(
                                            FEValuesExtractors::Vector(0)),
                                          {BoundaryIds::roller_hub});
        const auto                          &base = fe.base_element(0);
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        std::set<types::global_dof_index>    seen;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->material_id() == MaterialIds::roller && cell->at_boundary())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fe.system_to_base_index(i).first.first == 0 &&
                    hub.is_element(dofs[i]) && seen.insert(dofs[i]).second)
                  hub_dofs.push_back(
                    {dofs[i],
                     fe.system_to_component_index(i).first,
                     mapping.transform_unit_to_real_cell(
                       cell,
                       base.get_unit_support_points()[fe.system_to_base_index(i)
                                                        .second])});
            }
      }
    else
      roller_carrier = Common::Physics::add_prescribed_translation_constraints(
        dof_handler,
        MaterialIds::roller_carrier,
        constraints_dirichlet_and_hanging_nodes);
    {
      const FEValuesExtractors::Scalar x(0), y(1);
      const IndexSet                   bottom_x =
        DoFTools::extract_boundary_dofs(dof_handler,
                                        fe.component_mask(x),
                                        {BoundaryIds::bottom});
      const IndexSet bottom_y =
        DoFTools::extract_boundary_dofs(dof_handler,
                                        fe.component_mask(y),
                                        {BoundaryIds::bottom});
      // Every rank passes the same lists to hold_dofs().
      bottom_x_dofs.clear();
      bottom_y_dofs.clear();
      for (const auto dof : bottom_x)
        bottom_x_dofs.push_back(dof);
      for (const auto dof : bottom_y)
        bottom_y_dofs.push_back(dof);
    }

    auto geometry =
      parameters.geometry.elastic_roller ?
        std::make_unique<Common::Contact::CurrentMortarGeometry<dim>>(
          dof_handler,
          mapping,
          BoundaryIds::top,
          BoundaryIds::roller_rim,
          parameters.contact.search_distance,
          false) :
        std::make_unique<Common::Contact::CurrentMortarGeometry<dim>>(
          dof_handler,
          mapping,
          BoundaryIds::top,
          std::vector<Common::Contact::RigidTool<dim>>{make_roller()},
          parameters.contact.search_distance,
          false);
    if (!parameters.geometry.elastic_roller)
      geometry->set_rigid_tool_gap(parameters.contact.rigid_tool_gap);
    // The carrier cell of the rigid roller is prescribed throughout: any
    // law does; the elastic roller is steel.
    this->setup_contact_problem(
      Common::Physics::create_solid_operator<dim>(
        parameters.solid,
        mapping,
        fe,
        {{MaterialIds::strip, parameters.rubber_material},
         parameters.geometry.elastic_roller ?
           std::make_pair(MaterialIds::roller, parameters.roller_material) :
           std::make_pair(MaterialIds::roller_carrier,
                          parameters.rubber_material)}),
      std::move(geometry),
      contact_modulus());

    // Held in x while pressing.
    if (parameters.supports.bottom_free_stage != 1)
      {
        contact_problem->hold_dofs(bottom_x_dofs);
        bottom_held = true;
      }
  }



  // No applied forces: the bottom moves and the roller turns. The scale of
  // the residuals is the force per unit depth that strains the rubber
  // under the roller by 10 % over the roller's radius, about the roller's
  // force at the benchmark's indentation (3 mm of 20: 15 %), so that the
  // round-off of the residuals stays below the Newton tolerance.
  template <int dim>
  Common::Problems::ExternalLoad
  RollingProblem<dim>::external_load() const
  {
    Common::Problems::ExternalLoad load;
    // Once the bottom is free in x: the support's reaction there, less
    // the fraction the channel 'Bottom x release' has released.
    load.add = [this](const Common::Solvers::LoadState &state,
                      const AffineConstraints<double> &,
                      TrilinosWrappers::MPI::Vector &rhs) {
      const double factor = 1. - state.value("Bottom x release");
      for (const auto &[dof, reaction] : released_reactions)
        rhs(dof) += factor * reaction;
    };
    const double scale = 0.1 * parameters.rubber_material.youngs_modulus *
                         parameters.geometry.roller_radius * depth();
    load.magnitude = [scale](const Common::Solvers::LoadState &) {
      return scale;
    };
    load.prescribed_displacements =
      [this](const Common::Solvers::LoadState          &state,
             std::map<types::global_dof_index, double> &values) {
        const double indentation = state.value("Indentation");
        for (const auto dof : bottom_y_dofs)
          values[dof] = indentation;
        if (parameters.geometry.elastic_roller)
          {
            // u = (Q - I)(X - c), Q the clockwise turn by the channel.
            const double theta =
              -state.value("Roller angle") * numbers::PI / 180.;
            const double     c = std::cos(theta), sn = std::sin(theta);
            const Point<dim> centre = roller_centre();
            for (const auto &hub : hub_dofs)
              {
                const Tensor<1, dim> r      = hub.position - centre;
                const double         turned = hub.component == 0 ?
                                                c * r[0] - sn * r[1] :
                                                sn * r[0] + c * r[1];
                values[hub.dof]             = turned - r[hub.component];
              }
          }
        else
          roller_carrier.prescribe(Tensor<1, dim>(), values);
      };
    return load;
  }



  // The hub's supports hold the roller against the strip's contact forces:
  // those are the supports' reactions reversed, and so is their moment
  // about the axis, taken where the hub nodes are now (turned rigidly).
  template <int dim>
  std::pair<Tensor<1, dim>, double>
  RollingProblem<dim>::elastic_roller_loads(
    const Common::Solvers::LoadState &state)
  {
    Common::Problems::ExternalLoad internal_only = external_load();
    internal_only.add = [](const Common::Solvers::LoadState &,
                           const AffineConstraints<double> &,
                           TrilinosWrappers::MPI::Vector &) {
    };
    const TrilinosWrappers::MPI::Vector reactions =
      contact_problem->nodal_reactions(state, internal_only);
    const double     theta = -state.value("Roller angle") * numbers::PI / 180.;
    const double     c = std::cos(theta), sn = std::sin(theta);
    const Point<dim> centre = roller_centre();
    Tensor<1, dim>   force;
    double           moment = 0.;
    for (const auto &hub : hub_dofs)
      if (reactions.locally_owned_elements().is_element(hub.dof))
        {
          const Tensor<1, dim> r = hub.position - centre;
          const double arm[2]    = {c * r[0] - sn * r[1], sn * r[0] + c * r[1]};
          const double f         = -reactions(hub.dof);
          force[hub.component] += f;
          moment += hub.component == 0 ? -arm[1] * f : arm[0] * f;
        }
    return {Utilities::MPI::sum(force, mpi_communicator),
            Utilities::MPI::sum(moment, mpi_communicator)};
  }



  template <int dim>
  void
  RollingProblem<dim>::postprocess_step(
    const Common::Solvers::StepInfo         &step,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    Common::Problems::print_step(console, step, statistics, *contact_problem);

    StepRecord record;
    record.time        = step.state.time;
    record.indentation = step.state.value("Indentation");
    record.angle       = step.state.value("Roller angle");
    if (parameters.geometry.elastic_roller)
      {
        const auto [force, moment] = elastic_roller_loads(step.state);
        record.roller_force        = per_unit_depth(force);
        record.roller_moment       = moment / depth();
      }
    else
      {
        const auto &geometry =
          static_cast<const Common::Contact::CurrentMortarGeometry<dim> &>(
            *contact_geometry);
        const auto loads =
          geometry.tool_loads(contact_problem->enforcement().state(),
                              dof_handler.locally_owned_dofs(),
                              mpi_communicator);
        record.roller_force  = per_unit_depth(loads[0].force);
        record.roller_moment = loads[0].moment[2] / depth();
      }
    // The whole force of the bottom on the strip: its supports' reactions
    // and the support force being released (the internal forces there).
    Common::Problems::ExternalLoad internal_only = external_load();
    internal_only.add = [](const Common::Solvers::LoadState &,
                           const AffineConstraints<double> &,
                           TrilinosWrappers::MPI::Vector &) {
    };
    record.bottom_reaction =
      per_unit_depth(contact_problem->reaction_forces({BoundaryIds::bottom},
                                                      step.state,
                                                      internal_only)[0]);
    const double magnitude = record.roller_force.norm();
    record.balance =
      magnitude > 0. ?
        (record.roller_force - record.bottom_reaction).norm() / magnitude :
        0.;
    auto *finite_strain =
      dynamic_cast<Common::Physics::FiniteStrainSolid<dim> *>(solid.get());
    record.dilatation_error =
      finite_strain != nullptr ?
        finite_strain->dilatation_error(dof_handler,
                                        contact_problem->displacement(),
                                        false) :
        0.;
    const auto points = corners();
    for (unsigned int c = 0; c < n_corners; ++c)
      record.corner_ux[c] =
        Common::Physics::displacement_at(mapping,
                                         dof_handler,
                                         contact_problem->displacement(),
                                         points[c],
                                         "a corner of the strip")[0];
    records.push_back(record);
    if (!half_turn_written && record.angle >= 180. - 1e-9)
      {
        write_half_turn_profile(record.angle);
        half_turn_written = true;
      }

    console.print_quantity("Roller angle (clockwise)", "deg", record.angle);
    console.print_quantity("Point A, u_x", "mm", record.corner_ux[0]);
    console.print_quantity("Vertical force on the roller",
                           "N/mm",
                           record.roller_force[1]);
    console.print_quantity("Driving torque", "N", record.roller_moment);

    // Free the bottom in x for the stages from the one that frees it: the
    // next step belongs to it once this one ends its predecessor.
    const unsigned int free_stage = parameters.supports.bottom_free_stage;
    if (bottom_held && free_stage > 1 &&
        std::abs(step.state.time - (free_stage - 1.)) < 1e-9)
      {
        const TrilinosWrappers::MPI::Vector reactions =
          contact_problem->nodal_reactions(step.state, internal_only);
        for (const auto dof : bottom_x_dofs)
          if (reactions.locally_owned_elements().is_element(dof))
            released_reactions[dof] = reactions(dof);
        contact_problem->release_dofs(bottom_x_dofs);
        bottom_held = false;
        console.stream()
          << "  The strip's bottom is free in x from here; its support's "
             "reaction is applied less the fraction 'Bottom x release'."
          << std::endl;
      }
    Common::Problems::warn_if_search_edge_reached(console, *contact_problem);
  }



  template class RollingProblem<2>;
  template class RollingProblem<3>;
} // namespace ReynoldsRoller
