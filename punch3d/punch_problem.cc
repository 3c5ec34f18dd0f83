/*
 * Benchmark 2 of the FENET/NAFEMS advanced contact benchmarks, axisymmetric
 * model: a steel punch (diameter 100 mm, height 100 mm, 10 mm fillet at the
 * contact edge) pressed onto an aluminium foundation (diameter 200 mm,
 * height 200 mm) by 100 MPa on its top. The contact pressure is compared
 * with the half-space solution of a rounded flat punch and with the
 * MSC.Marc and Abaqus curves of the benchmark report; see README.md.
 */
#include "punch_problem.h"

#include <common/geometry/revolution.h>
#include <common/geometry/two_body_meshes.h>
#include <common/io/plotting.h>
#include <common/io/timer.h>
#include <common/physics/boundary_conditions.h>
#include <common/physics/boundary_displacement.h>
#include <common/physics/boundary_loads.h>
#include <common/physics/rigid_body.h>
#include <common/problems/load_steps.h>

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
  namespace
  {
    /** MSC.Marc's u_z of the foundation top on the axis (REFERENCES.md 2.2,
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
  PunchProblem<dim>::PunchProblem(const Parameters &parameters)
    : parameters(parameters)
    , mpi_communicator(MPI_COMM_WORLD)
    , console(parameters.output.verbosity, mpi_communicator)
    , triangulation(mpi_communicator)
    , fe(FE_Q<dim>(parameters.mesh.element_degree), dim)
    , mapping(parameters.mesh.element_degree)
    , dof_handler(triangulation)
    , axis_dof(numbers::invalid_dof_index)
    , loaded_area(0.)
  {}



  namespace
  {
    /** Distance of a point from the axis: r = x in the axisymmetric model,
     * sqrt(x^2 + z^2) in the 3D one (y is the axis). */
    template <int dim>
    double
    radius(const Point<dim> &p)
    {
      return dim == 2 ? std::abs(p[0]) : std::hypot(p[0], p[dim - 1]);
    }

    // The meridian section (r, z): the foundation is [0, Rf] x [0, Hf];
    // the punch [0, a] x [Hf, Hf + Hp] with the corner at (a, Hf) rounded by
    // a fillet of radius rho centred at (a - rho, Hf + rho). The punch's
    // coarse mesh is built by hand: a strip along its flat face, two cells
    // along the fillet, and two rows above. Its fillet faces get manifold
    // id 0 (a circle about the fillet's centre, attached here) and, if
    // @p transfinite_cells, its cells manifold id 1 (for a transfinite
    // interpolation attached to the joined mesh). Boundary and material
    // ids are set on both.
    void
    make_meridian_meshes(const GeometryParameters &geometry,
                         const bool                transfinite_cells,
                         Triangulation<2>         &foundation,
                         Triangulation<2>         &punch)
    {
      const double   a   = geometry.punch_radius;
      const double   Hp  = geometry.punch_height;
      const double   rho = geometry.fillet_radius;
      const double   Rf  = geometry.foundation_radius;
      const double   Hf  = geometry.foundation_height;
      const double   b   = a - rho;
      const Point<2> centre(b, Hf + rho);

      const double coarse_size = 0.5 * a;
      GridGenerator::subdivided_hyper_rectangle(
        foundation,
        {std::max(1u, static_cast<unsigned int>(std::round(Rf / coarse_size))),
         std::max(1u, static_cast<unsigned int>(std::round(Hf / coarse_size)))},
        Point<2>(0., 0.),
        Point<2>(Rf, Hf));

      const double                           s = std::sqrt(0.5);
      std::vector<Point<2>>                  vertices;
      std::vector<std::vector<unsigned int>> cell_vertices;
      if (geometry.hemispherical_end())
        {
          // A quarter disc of three cells about the hemisphere's centre
          // (two along the arc, one at the centre), then two columns of
          // two cells above it. Vertices 0 to 2: the arc from the axis to
          // the side; 3 to 5: the inner cell's corners; 6: the centre;
          // then the rows z_mid and the top, from the axis outward.
          const double z_mid = Hf + 0.5 * (a + Hp);
          vertices           = {{0., Hf},
                                {s * a, Hf + a - s * a},
                                {a, Hf + a},
                                {0., Hf + 0.5 * a},
                                {0.5 * a, Hf + 0.5 * a},
                                {0.5 * a, Hf + a},
                                {0., Hf + a},
                                {0., z_mid},
                                {0.5 * a, z_mid},
                                {a, z_mid},
                                {0., Hf + Hp},
                                {0.5 * a, Hf + Hp},
                                {a, Hf + Hp}};
          cell_vertices      = {{0, 1, 3, 4},
                                {1, 2, 4, 5},
                                {3, 4, 6, 5},
                                {6, 5, 7, 8},
                                {5, 2, 8, 9},
                                {7, 8, 10, 11},
                                {8, 9, 11, 12}};
        }
      else
        {
          // Vertices 0 to 3: the axis, the start, middle and end of the
          // fillet; then four rows from the axis outward.
          const double z_mid = Hf + 0.5 * (2.5 * rho + Hp);
          vertices           = {{0., Hf},
                                {b, Hf},
                                {b + s * rho, Hf + rho - s * rho},
                                {a, Hf + rho},
                                {0., Hf + 2. * rho},
                                {b - 1.5 * rho, Hf + 2. * rho},
                                {b - 0.25 * rho, Hf + 2.25 * rho},
                                {a, Hf + 2.5 * rho},
                                {0., z_mid},
                                {b - 1.5 * rho, z_mid},
                                {b - 0.25 * rho, z_mid},
                                {a, z_mid},
                                {0., Hf + Hp},
                                {b - 1.5 * rho, Hf + Hp},
                                {b - 0.25 * rho, Hf + Hp},
                                {a, Hf + Hp}};
          cell_vertices      = {{0, 1, 4, 5},
                                {1, 2, 5, 6},
                                {2, 3, 6, 7},
                                {4, 5, 8, 9},
                                {5, 6, 9, 10},
                                {6, 7, 10, 11},
                                {8, 9, 12, 13},
                                {9, 10, 13, 14},
                                {10, 11, 14, 15}};
        }
      std::vector<CellData<2>> cells(cell_vertices.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int v = 0; v < 4; ++v)
          cells[c].vertices[v] = cell_vertices[c][v];
      // Neighbours must traverse their shared lines alike (the fillet mesh
      // is numbered so already).
      if (geometry.hemispherical_end())
        GridTools::consistently_order_cells(cells);
      punch.create_triangulation(vertices, cells, SubCellData());

      const double tolerance = 1e-8 * a;
      for (const auto &cell : foundation.active_cell_iterators())
        {
          cell->set_material_id(MaterialIds::foundation);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<2> c = face->center();
                face->set_boundary_id(
                  std::abs(c[1]) < tolerance ? BoundaryIds::foundation_bottom :
                  std::abs(c[1] - Hf) < tolerance ?
                                               BoundaryIds::foundation_top :
                  std::abs(c[0]) < tolerance ? BoundaryIds::foundation_axis :
                                               BoundaryIds::foundation_side);
              }
        }
      for (const auto &cell : punch.active_cell_iterators())
        {
          cell->set_material_id(MaterialIds::punch);
          if (transfinite_cells)
            cell->set_all_manifold_ids(1);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<2> c = face->center();
                if (std::abs(c[0]) < tolerance)
                  face->set_boundary_id(BoundaryIds::punch_axis);
                else if (std::abs(c[1] - Hf - Hp) < tolerance)
                  face->set_boundary_id(BoundaryIds::punch_top);
                else if (std::abs(c[0] - a) < tolerance)
                  face->set_boundary_id(BoundaryIds::punch_side);
                else
                  {
                    // The flat face and the fillet: the primary surface.
                    face->set_boundary_id(BoundaryIds::punch_contact);
                    if (c[0] > b + tolerance)
                      face->set_manifold_id(0);
                  }
              }
        }
      punch.set_manifold(0, SphericalManifold<2>(centre));
    }
  } // namespace



  // The axisymmetric model joins the meridian meshes; the fillet is a
  // circle, the punch's interior a transfinite interpolation, so the arc
  // is exact under refinement and represented by the element geometry of
  // Q2. The 3D model revolves each meridian mesh into a quarter
  // (common/geometry/revolution.h) and joins them; the fillet becomes a
  // torus. Both are then graded toward the contact zone.
  template <int dim>
  void
  PunchProblem<dim>::make_grid()
  {
    const auto  &geometry = parameters.geometry;
    const double a        = geometry.punch_radius;
    const double b        = a - geometry.fillet_radius;
    const double Hf       = geometry.foundation_height;

    Triangulation<2> foundation, punch;
    make_meridian_meshes(geometry, dim == 2, foundation, punch);
    if constexpr (dim == 2)
      {
        Common::Geometry::join_bodies<dim>({&foundation, &punch},
                                           triangulation);
        TransfiniteInterpolationManifold<dim> transfinite;
        transfinite.initialize(triangulation);
        triangulation.set_manifold(1, transfinite);
      }
    else
      {
        Triangulation<dim> foundation_3d, punch_3d;
        Common::Geometry::revolve_quarter(foundation,
                                          BoundaryIds::symmetry_z0,
                                          BoundaryIds::symmetry_x0,
                                          10,
                                          foundation_3d);
        Common::Geometry::revolve_quarter(punch,
                                          BoundaryIds::symmetry_z0,
                                          BoundaryIds::symmetry_x0,
                                          20,
                                          punch_3d);
        Common::Geometry::join_bodies<dim>({&foundation_3d, &punch_3d},
                                           triangulation);
      }

    triangulation.refine_global(parameters.mesh.n_global_refinements);
    // Graded toward the band under the punch, then toward the contact
    // edge, from the start of the fillet to half its radius beyond it.
    const auto band = [Hf](const double r0, const double r1) {
      return [Hf, r0, r1](const Point<dim> &p) {
        const double r  = radius(p);
        const double dr = std::max({0., r0 - r, r - r1});
        return std::sqrt(dr * dr + (p[1] - Hf) * (p[1] - Hf));
      };
    };
    // A hemispherical end has its contact zone, and its edge, within the
    // Hertz radius: both gradings aim at r <= 1.25 a_Hertz.
    const bool   sphere     = geometry.hemispherical_end();
    const double edge_start = sphere ? 0. : b;
    const double edge_end   = sphere ?
                                1.25 * half_space_reference().contact_radius() :
                                b + 0.5 * geometry.fillet_radius;
    Common::Geometry::refine_toward<dim>(triangulation,
                                         band(0., sphere ? edge_end : a),
                                         parameters.mesh.n_contact_refinements,
                                         parameters.mesh.grading_factor);
    Common::Geometry::refine_toward<dim>(triangulation,
                                         band(edge_start, edge_end),
                                         parameters.mesh.n_edge_refinements,
                                         parameters.mesh.grading_factor);
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
        top_on_axis[1] = parameters.geometry.foundation_height +
                         parameters.geometry.punch_height;
        Common::Physics::add_rigid_translation_constraints(
          dof_handler,
          MaterialIds::punch,
          top_on_axis,
          fixed,
          constraints_dirichlet_and_hanging_nodes);
      }
    constraints_dirichlet_and_hanging_nodes.close();

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
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == MaterialIds::foundation)
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).distance(axis_point) <
              1e-8 * parameters.geometry.punch_radius)
            axis_dof = cell->vertex_dof_index(v, 1);
    AssertThrow(axis_dof != numbers::invalid_dof_index,
                ExcMessage("No foundation vertex on the axis at the top."));

    std::map<types::material_id, Common::Materials::LinearElastic<dim>>
      materials;
    materials.emplace(MaterialIds::punch,
                      Common::Materials::LinearElastic<dim>(
                        parameters.punch_material));
    materials.emplace(MaterialIds::foundation,
                      Common::Materials::LinearElastic<dim>(
                        parameters.foundation_material));
    physics = std::make_unique<Common::Physics::SmallStrainElasticity<dim>>(
      mapping,
      fe,
      materials,
      kinematics());

    contact_problem =
      std::make_unique<Common::Problems::SmallStrainContactProblem<dim>>(
        dof_handler,
        mapping,
        *physics,
        parameters.contact,
        parameters.linear_solver,
        parameters.nonlinear_solver,
        parameters.foundation_material.youngs_modulus,
        mpi_communicator);
    contact_problem->setup(constraints_dirichlet_and_hanging_nodes);
  }



  // The uniform pressure on the punch's top face, over the full ring.
  template <int dim>
  Common::Problems::ExternalLoad
  PunchProblem<dim>::external_load() const
  {
    const double                   pressure = parameters.loading.pressure;
    const double                   a        = parameters.geometry.punch_radius;
    Common::Problems::ExternalLoad load;
    load.add = [this, pressure](const double                     load_factor,
                                const AffineConstraints<double> &c,
                                TrilinosWrappers::MPI::Vector   &vector) {
      Common::Physics::add_boundary_pressure(mapping,
                                             dof_handler,
                                             BoundaryIds::punch_top,
                                             load_factor * pressure,
                                             kinematics(),
                                             c,
                                             vector);
    };
    // The load on the model: the full ring, or a quarter of it in 3D.
    load.magnitude = [pressure, a](const double load_factor) {
      return load_factor * pressure * numbers::PI * a * a * model_fraction;
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
    const unsigned int                       step,
    const double                             load_factor,
    const Common::Solvers::NewtonStatistics &statistics)
  {
    const Results r = evaluate_results(load_factor);
    console.stream() << "Load step " << step << " of "
                     << std::max(step, parameters.load_stepping.n_steps)
                     << ", load factor "
                     << Common::IO::Console::format(load_factor)
                     << ": Newton iterations " << statistics.n_iterations
                     << ", active contact nodes "
                     << contact_problem->enforcement().n_active() << std::endl;
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
    if (contact_problem->enforcement().touches_search_edge())
      console.stream() << "  Warning: the contact zone reaches the edge of "
                          "the search region; increase 'Search distance'."
                       << std::endl;
  }



  template <int dim>
  void
  PunchProblem<dim>::output_results(
    const Common::Solvers::LoadSteppingStatistics &stepping)
  {
    using Common::IO::JsonObject;
    const auto &enforcement = contact_problem->enforcement();
    const auto &out         = parameters.output;
    const bool  root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const Results r  = evaluate_results(1.);
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
            for (const auto &p : marc_surface)
              marc_displacements << p.r << ',' << p.ur_mu0 << ',' << p.uz_mu0
                                 << ',' << p.ur_mu01 << ',' << p.uz_mu01
                                 << '\n';
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

        if (!Common::IO::write_plots(out.directory, plots))
          console.stream() << "  Note: gnuplot not available; plot scripts "
                              "written without PNG."
                           << std::endl;
      }

    // summary.json
    JsonObject case_description;
    case_description.set("model", dim == 2 ? "axisymmetric" : "3d quarter")
      .set("punch", parameters.model.rigid_punch ? "rigid" : "elastic")
      .set("element_degree", parameters.mesh.element_degree)
      .set("global_refinements", parameters.mesh.n_global_refinements)
      .set("contact_refinements", parameters.mesh.n_contact_refinements)
      .set("edge_refinements", parameters.mesh.n_edge_refinements)
      .set("enforcement",
           parameters.contact.enforcement ==
               Common::Contact::Enforcement::penalty ?
             "penalty" :
             "lagrange multiplier")
      .set("friction_law", friction ? "coulomb" : "frictionless")
      .set("friction_coefficient", mu)
      .set("n_load_steps", parameters.load_stepping.n_steps)
      .set("n_mpi_ranks", Utilities::MPI::n_mpi_processes(mpi_communicator));

    const double Hf               = parameters.geometry.foundation_height;
    const double a                = parameters.geometry.punch_radius;
    const auto   contact_distance = [Hf, a](const Point<dim> &p) {
      return std::abs(p[1] - Hf) + std::max(0., radius(p) - a);
    };
    JsonObject mesh;
    mesh.set("n_active_cells", triangulation.n_active_cells())
      .set("n_dofs", dof_handler.n_dofs())
      .set("smallest_cell_in_contact_zone_mm",
           Common::Geometry::smallest_cell_near<dim>(triangulation,
                                                     contact_distance));

    const JsonObject newton = Common::Problems::newton_summary(stepping);

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
      .set("source",
           benchmark_geometry ?
             "half-space solution of a rounded flat punch (REFERENCES.md "
             "2.1); MSC.Marc/Abaqus curves of NAFEMS R0094 (REFERENCES.md "
             "2.2)" :
           sphere ?
             "Hertz point contact: the half-space solution of REFERENCES.md "
             "2.1 with flat radius b = 0" :
             "half-space solution of a rounded flat punch (REFERENCES.md "
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

    JsonObject summary;
    summary.set("benchmark", "punch3d")
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
  PunchProblem<dim>::run()
  {
    const auto start = std::chrono::steady_clock::now();
    console.stream() << "punch3d: rounded punch on a cylindrical foundation "
                        "("
                     << (dim == 2 ? "axisymmetric" : "3D quarter model")
                     << (parameters.model.rigid_punch ? ", rigid punch" : "")
                     << (parameters.geometry.hemispherical_end() ?
                           ", hemispherical end)" :
                           ")")
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
                                           "fe_reference.csv",
                                           "contact_pressure.png",
                                           "contact_pressure.gp",
                                           "tangential_traction.png",
                                           "tangential_traction.gp",
                                           "slip.png",
                                           "slip.gp",
                                           "surface_displacement.csv",
                                           "marc_surface_displacement.csv",
                                           "surface_displacement_u_r.png",
                                           "surface_displacement_u_r.gp",
                                           "surface_displacement_u_z.png",
                                           "surface_displacement_u_z.gp",
                                           "solution.pvd"}))
      return;
    const auto &out = parameters.output;

    const auto stepping = Common::Problems::run_load_steps<dim>(
      *contact_problem,
      external_load(),
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
    timings.set("total_s", Common::IO::seconds_since(start));
    output_results(stepping);
  }


  template class PunchProblem<2>;
  template class PunchProblem<3>;
} // namespace Punch3d
