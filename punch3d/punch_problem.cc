/*
 * Benchmark 2 of the FENET/NAFEMS advanced contact benchmarks, axisymmetric
 * model: a steel punch (diameter 100 mm, height 100 mm, 10 mm fillet at the
 * contact edge) pressed onto an aluminium foundation (diameter 200 mm,
 * height 200 mm) by 100 MPa on its top. The contact pressure is compared
 * with the half-space solution of a rounded flat punch and with the
 * MSC.Marc and Abaqus curves of the benchmark report; see README.md.
 */
#include "punch_problem.h"

#include <common/contact/current_mortar_geometry.h>
#include <common/geometry/revolution.h>
#include <common/geometry/two_body_meshes.h>
#include <common/io/plotting.h>
#include <common/io/timer.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/boundary_displacement.h>
#include <common/physics/boundary_loads.h>
#include <common/physics/rigid_body.h>
#include <common/physics/solid_model.h>
#include <common/problems/contact_run.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace Punch3d
{



  template <int dim>
  PunchProblem<dim>::PunchProblem(const Parameters &parameters)
    : Base(parameters, parameters.mesh.element_degree, "punch3d")
    , parameters(parameters)
    , axis_dof(numbers::invalid_dof_index)
    , loaded_area(0.)
  {}



  template <int dim>
  std::string
  PunchProblem<dim>::title() const
  {
    return std::string("punch3d: rounded punch on a cylindrical foundation (") +
           (dim == 2 ? "axisymmetric" : "3D quarter model") +
           (parameters.model.rigid_surface ? ", rigid punch surface" :
            parameters.model.rigid_punch   ? ", rigid punch" :
                                             "") +
           (parameters.geometry.hemispherical_end() ? ", hemispherical end)" :
                                                      ")");
  }



  template <int dim>
  std::vector<std::string>
  PunchProblem<dim>::result_files() const
  {
    return {"fe_reference.csv",
            "surface_displacement.csv",
            "marc_surface_displacement.csv",
            "surface_displacement_u_r.png",
            "surface_displacement_u_r.gp",
            "surface_displacement_u_z.png",
            "surface_displacement_u_z.gp"};
  }



  template <int dim>
  void
  PunchProblem<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);

    // Hanging nodes of the graded mesh, and homogeneous Dirichlet
    // conditions on the Newton increment: fixed foundation bottom; u_r = 0
    // on the axis of both bodies (axisymmetric) or the normal component on
    // the symmetry planes (3D).
    std::vector<std::pair<unsigned int, std::vector<types::boundary_id>>>
      symmetry;
    if (dim == 2)
      symmetry = {{0, {BoundaryIds::foundation_axis, BoundaryIds::punch_axis}}};
    else
      symmetry = {{dim - 1, {BoundaryIds::symmetry_z0}},
                  {0, {BoundaryIds::symmetry_x0}}};
    Common::Physics::make_homogeneous_constraints<dim>(
      mapping,
      dof_handler,
      {BoundaryIds::foundation_bottom},
      symmetry,
      constraints_dirichlet_and_hanging_nodes);
    // A rigid punch follows the axial DoF of its top vertex on the axis;
    // symmetry holds its other components at zero.
    if (parameters.model.rigid_punch)
      {
        ComponentMask fixed(dim, true);
        fixed.set(1, false);
        Point<dim> top_on_axis;
        top_on_axis[1] =
          parameters.geometry.punch_base() + parameters.geometry.punch_height;
        Common::Physics::add_rigid_translation_constraints(
          dof_handler,
          MaterialIds::punch,
          top_on_axis,
          fixed,
          constraints_dirichlet_and_hanging_nodes);
      }

    // The loaded area of the discrete punch top, for the full body: pi a^2
    // up to round-off in the axisymmetric model; in 3D the area of the
    // mapped quarter disc (Q1: its chords) times 4.
    {
      const QGauss<dim - 1> face_quadrature(fe.degree + 1);
      FEFaceValues<dim>     fe_face_values(mapping,
                                       fe,
                                       face_quadrature,
                                       update_JxW_values |
                                         update_quadrature_points);
      double                area = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() &&
                face->boundary_id() == BoundaryIds::punch_top)
              {
                fe_face_values.reinit(cell, face);
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  area += fe_face_values.JxW(q) *
                          Common::Physics::measure_factor(
                            kinematics(),
                            fe_face_values.quadrature_point(q));
              }
      loaded_area =
        Utilities::MPI::sum(area, mpi_communicator) / model_fraction;
    }

    // The axial DoF of the foundation's top vertex on the axis.
    Point<dim> axis_point;
    axis_point[1] = parameters.geometry.foundation_height;
    axis_dof =
      Common::Geometry::vertex_dof(dof_handler,
                                   axis_point,
                                   1,
                                   1e-8 * parameters.geometry.punch_radius,
                                   "the top of the foundation on the axis",
                                   MaterialIds::foundation);

    this->setup_contact_problem(
      Common::Physics::create_solid_operator<dim>(
        parameters.solid,
        mapping,
        fe,
        {{MaterialIds::punch, parameters.punch_material},
         {MaterialIds::foundation, parameters.foundation_material}},
        kinematics()),
      make_contact_geometry(),
      parameters.foundation_material.youngs_modulus);
  }



  // The primary side: the punch's meshed contact face, or, for a punch
  // that is an analytic rigid surface, its profile (the flat face and the
  // fillet, then the side; revolved about the axis in 3D) moving with the
  // reference node, the top vertex on the axis.
  template <int dim>
  std::unique_ptr<Common::Contact::ContactGeometry<dim>>
  PunchProblem<dim>::make_contact_geometry() const
  {
    const bool axisymmetric =
      kinematics() == Common::Physics::Kinematics::axisymmetric;
    if (!parameters.model.rigid_surface)
      return Common::Contact::create_mortar_geometry<dim>(
        dof_handler,
        mapping,
        parameters.contact,
        parameters.solid.finite_strain(),
        axisymmetric);

    const auto                   &g   = parameters.geometry;
    const double                  a   = g.punch_radius;
    const double                  rho = g.fillet_radius;
    const double                  Hb  = g.punch_base();
    Common::Contact::RigidProfile profile;
    if (a - rho > 0.)
      profile.add_line(Point<2>(0., Hb), Point<2>(a - rho, Hb));
    profile.add_arc(Point<2>(a - rho, Hb + rho), rho, -0.5 * numbers::PI, 0.);
    profile.add_line(Point<2>(a, Hb + rho), Point<2>(a, Hb + g.punch_height));

    Point<dim> top_on_axis;
    top_on_axis[1] = Hb + g.punch_height;
    std::array<types::global_dof_index, dim> reference_node_dofs;
    for (unsigned int c = 0; c < dim; ++c)
      reference_node_dofs[c] =
        Common::Geometry::vertex_dof(dof_handler,
                                     top_on_axis,
                                     c,
                                     1e-8 * a,
                                     "the top of the punch on the axis",
                                     MaterialIds::punch);
    return Common::Contact::create_mortar_geometry<dim>(
      dof_handler,
      mapping,
      parameters.contact,
      parameters.solid.finite_strain(),
      "punch",
      std::make_shared<const Common::Contact::RigidSurface<dim>>(
        profile,
        Common::Contact::ProfileSweep::revolution_about_y),
      reference_node_dofs,
      axisymmetric);
  }



  // The uniform pressure on the punch's top face, over the full ring.
  template <int dim>
  Common::Problems::ExternalLoad
  PunchProblem<dim>::external_load() const
  {
    const double                   pressure = parameters.loading.pressure;
    const double                   a        = parameters.geometry.punch_radius;
    Common::Problems::ExternalLoad load;
    load.add = [this, pressure](const Common::Solvers::LoadState &state,
                                const AffineConstraints<double>  &c,
                                TrilinosWrappers::MPI::Vector    &vector) {
      Common::Physics::add_boundary_pressure(mapping,
                                             dof_handler,
                                             BoundaryIds::punch_top,
                                             state.load_factor() * pressure,
                                             kinematics(),
                                             c,
                                             vector);
    };
    // The load on the model: the full ring, or a quarter of it in 3D.
    load.magnitude = [pressure, a](const Common::Solvers::LoadState &state) {
      return state.load_factor() * pressure * numbers::PI * a * a *
             model_fraction;
    };
    return load;
  }



  template <int dim>
  Common::Analytic::RoundedPunchHalfSpace
  PunchProblem<dim>::half_space_reference() const
  {
    const double a = parameters.geometry.punch_radius;
    return Common::Analytic::RoundedPunchHalfSpace(
      parameters.model.rigid_punch ? std::numeric_limits<double>::infinity() :
                                     parameters.punch_material.youngs_modulus,
      parameters.punch_material.poisson_ratio,
      parameters.foundation_material.youngs_modulus,
      parameters.foundation_material.poisson_ratio,
      a - parameters.geometry.fillet_radius,
      parameters.geometry.fillet_radius,
      parameters.loading.pressure *
        (loaded_area > 0. ? loaded_area : numbers::PI * a * a));
  }



  template <int dim>
  typename PunchProblem<dim>::Results
  PunchProblem<dim>::evaluate_results(const double load_factor) const
  {
    const double a = parameters.geometry.punch_radius;
    Results      r;
    r.profile =
      Common::Contact::contact_profile(contact_problem->coupling(),
                                       contact_problem->enforcement(),
                                       contact_problem->displacement(),
                                       contact_problem->bulk_residual(),
                                       0);
    // 3D: the nodes on the symmetry plane z = 0, where x = r and the
    // profile's tangent (e_x) is radial.
    if (dim == 3)
      r.profile.erase(std::remove_if(r.profile.begin(),
                                     r.profile.end(),
                                     [a](const auto &p) {
                                       return std::abs(p.position[dim - 1]) >
                                              1e-8 * a;
                                     }),
                      r.profile.end());
    r.centre_pressure = r.peak_pressure = r.peak_radius = 0.;
    r.centre_radius = r.contact_radius = r.stick_radius = 0.;
    r.peak_tangential_traction                          = 0.;
    if (!r.profile.empty())
      {
        // Axisymmetric Q2: the vertex on the axis has no ring measure and
        // is not paired; the innermost paired node stands for the centre.
        const double r0   = r.profile.front().position[0];
        r.centre_pressure = r.profile.front().pressure;
        r.centre_radius   = r0;
        for (const auto &p : r.profile)
          {
            if (p.pressure > r.peak_pressure)
              {
                r.peak_pressure = p.pressure;
                r.peak_radius   = p.position[0];
              }
            r.peak_tangential_traction =
              std::max(r.peak_tangential_traction,
                       std::abs(p.tangential_traction));
          }
        r.contact_radius = r0 + Common::Contact::contact_extent(r.profile, 0);
        if (contact_problem->enforcement().has_friction())
          r.stick_radius = r0 + Common::Contact::stick_extent(r.profile, 0);
      }
    r.contact_force =
      -Common::Contact::total_contact_force(contact_problem->coupling(),
                                            contact_problem->enforcement())[1] /
      model_fraction;
    r.applied_force = load_factor * parameters.loading.pressure * loaded_area;
    const auto  &u  = contact_problem->displacement();
    const double local =
      dof_handler.locally_owned_dofs().is_element(axis_dof) ? u(axis_dof) : 0.;
    r.axis_displacement = Utilities::MPI::sum(local, mpi_communicator);
    return r;
  }



  template <int dim>
  void
  PunchProblem<dim>::postprocess_step(
    const Common::Solvers::StepInfo         &step,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const Results r = evaluate_results(step.state.load_factor());
    Common::Problems::print_step(console, step, statistics, *contact_problem);
    console.print_quantity("Contact force",
                           "N",
                           r.contact_force,
                           "F/F_applied",
                           r.contact_force / r.applied_force);
    console.print_quantity("Contact radius", "mm", r.contact_radius);
    console.print_quantity("Peak pressure", "MPa", r.peak_pressure);
    console.print_quantity("  at radius", "mm", r.peak_radius);
    if (contact_problem->enforcement().has_friction())
      console.print_quantity("Stick radius", "mm", r.stick_radius);
    console.print_quantity("Foundation top on the axis, u_z",
                           "mm",
                           r.axis_displacement);
    Common::Problems::warn_if_search_edge_reached(console, *contact_problem);
  }



  template class PunchProblem<2>;
  template class PunchProblem<3>;
} // namespace Punch3d
