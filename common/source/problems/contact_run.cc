#include <common/contact/contact_postprocessor.h>
#include <common/geometry/two_body_meshes.h>
#include <common/io/solution_output.h>
#include <common/io/timer.h>
#include <common/problems/contact_run.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <memory>
#include <utility>
#include <vector>

namespace Common
{
  namespace Problems
  {
    using namespace dealii;

    IO::JsonObject
    newton_summary(const Solvers::LoadSteppingStatistics &stepping)
    {
      unsigned int total_iterations = 0, max_iterations = 0;
      unsigned int total_failed = 0, max_with_cutbacks = 0;
      unsigned int max_solves = 0, total_stabilized = 0, max_stabilized = 0;
      for (unsigned int i = 0; i < stepping.newton_iterations.size(); ++i)
        {
          const unsigned int n      = stepping.newton_iterations[i];
          const unsigned int failed = stepping.failed_attempt_iterations[i];
          total_iterations += n;
          total_failed += failed;
          max_iterations    = std::max(max_iterations, n);
          max_with_cutbacks = std::max(max_with_cutbacks, n + failed);
          const unsigned int extra =
            i < stepping.extra_solves.size() ? stepping.extra_solves[i] : 0;
          max_solves = std::max(max_solves, n + failed + extra);
          const unsigned int stabilized =
            i < stepping.stabilized_solves.size() ?
              stepping.stabilized_solves[i] :
              0;
          total_stabilized += stabilized;
          max_stabilized = std::max(max_stabilized, stabilized);
        }
      double stabilization_energy = 0.;
      for (const double e : stepping.stabilization_energy)
        stabilization_energy += e;
      IO::JsonObject newton;
      newton.set("total_iterations", total_iterations)
        .set("max_iterations_per_step", max_iterations)
        .set("iterations_per_step", stepping.newton_iterations)
        .set("n_cutbacks", stepping.n_cutbacks)
        .set("failed_attempt_iterations", total_failed)
        .set("max_iterations_per_step_with_cutbacks", max_with_cutbacks)
        .set("failed_attempt_iterations_per_step",
             stepping.failed_attempt_iterations)
        .set("n_steps_converged_on_step_tolerance",
             stepping.n_converged_on_step)
        .set("first_iteration_extra_solves",
             stepping.n_extra_first_iteration_solves)
        .set("later_iterations_extra_solves",
             stepping.n_extra_later_iteration_solves)
        .set("extra_solves_per_step", stepping.extra_solves)
        .set("max_linear_solves_per_step_with_cutbacks", max_solves)
        .set("stabilized_solves", total_stabilized)
        .set("max_stabilized_solves_per_step", max_stabilized)
        .set("stabilized_solves_per_step", stepping.stabilized_solves)
        .set("stabilization_energy", stabilization_energy)
        .set("stabilization_energy_per_step", stepping.stabilization_energy)
        .set("max_iterations_per_solve", stepping.max_iterations_per_solve);
      return newton;
    }



    IO::JsonObject
    case_summary(const ContactRunParameters &parameters,
                 const unsigned int          element_degree,
                 const MPI_Comm              mpi_communicator)
    {
      const auto &contact = parameters.contact;
      const bool penalty = contact.enforcement == Contact::Enforcement::penalty;
      IO::JsonObject description;
      description.set("element_degree", element_degree)
        .set("enforcement", penalty ? "penalty" : "lagrange multiplier")
        .set("friction_law",
             contact.friction_law == Contact::FrictionLaw::frictionless ||
                 contact.friction_coefficient == 0. ?
               "frictionless" :
               "coulomb")
        .set("friction_coefficient", contact.friction_coefficient)
        .set("n_load_steps", parameters.load_program.n_steps())
        .set("n_load_stages",
             static_cast<unsigned int>(parameters.load_program.stages.size()))
        .set("n_mpi_ranks", Utilities::MPI::n_mpi_processes(mpi_communicator));
      if (penalty)
        description.set("penalty_stiffness_MPa_per_mm",
                        contact.penalty_stiffness);
      return description;
    }



    template <int dim>
    IO::JsonObject
    mesh_summary(const DoFHandler<dim>                           &dof_handler,
                 const std::function<double(const Point<dim> &)> &distance)
    {
      IO::JsonObject mesh;
      mesh
        .set("n_active_cells", dof_handler.get_triangulation().n_active_cells())
        .set("n_dofs", dof_handler.n_dofs())
        .set("smallest_cell_in_contact_zone_mm",
             Geometry::smallest_cell_near<dim>(dof_handler.get_triangulation(),
                                               distance));
      return mesh;
    }



    namespace
    {
      /** Secondary nodes with a partner, over all ranks (each rank
       * integrates the rows it holds: the owners count). */
      template <int dim>
      unsigned int
      n_paired_nodes(const ContactNewtonProblem<dim> &problem)
      {
        const auto  &coupling = problem.coupling();
        const auto  &rows     = problem.enforcement().rows();
        unsigned int n_paired = 0;
        for (unsigned int j = 0; j < coupling.n_rows(); ++j)
          n_paired += rows.is_owned(j) && coupling.row(j).has_partner;
        if (rows.is_distributed())
          n_paired = Utilities::MPI::sum(n_paired, rows.communicator());
        return n_paired;
      }
    } // namespace



    template <int dim>
    void
    print_setup(IO::Console                     &console,
                const DoFHandler<dim>           &dof_handler,
                const ContactNewtonProblem<dim> &problem)
    {
      const auto        &coupling = problem.coupling();
      const unsigned int n_paired = n_paired_nodes(problem);
      console.stream() << "Mesh: "
                       << dof_handler.get_triangulation().n_active_cells()
                       << " active cells, " << dof_handler.n_dofs()
                       << " degrees of freedom, Q"
                       << dof_handler.get_fe().degree << std::endl
                       << "Contact: " << coupling.n_rows()
                       << " secondary nodes, " << n_paired << " paired, "
                       << problem.enforcement().n_active()
                       << " initially closed" << std::endl;
      // The DoFs each rank stores: its own plus the ghosts of the
      // partition interface and of the contact interface, never all.
      const MPI_Comm communicator = dof_handler.get_communicator();
      if (Utilities::MPI::n_mpi_processes(communicator) > 1)
        {
          const auto &stored = problem.stored_dofs();
          const auto  all =
            Utilities::MPI::gather(communicator,
                                   std::array<types::global_dof_index, 3>{
                                     {stored.n_owned,
                                      stored.n_partition_ghosts,
                                      stored.n_contact_ghosts}});
          for (unsigned int r = 0; r < all.size(); ++r)
            console.stream()
              << "DoFs stored on rank " << r << ": " << all[r][0] << " owned + "
              << all[r][1] << " partition ghosts + " << all[r][2]
              << " contact ghosts" << std::endl;
        }
    }



    template <int dim>
    bool
    begin_run(IO::Console                     &console,
              const DoFHandler<dim>           &dof_handler,
              const ContactNewtonProblem<dim> &problem,
              const ContactRunParameters      &parameters,
              const std::vector<std::string>  &result_files)
    {
      print_setup<dim>(console, dof_handler, problem);
      // Rows integrated once, in the reference configuration, never gain a
      // partner: without one the bodies cannot touch.
      const auto &contact = parameters.contact;
      AssertThrow(
        problem.contact_geometry().is_current_configuration() ||
          n_paired_nodes(problem) > 0,
        ExcMessage("Contact: no node of the secondary surface ('Secondary "
                   "boundary id' = " +
                   std::to_string(contact.secondary_boundary_id) + ", " +
                   std::to_string(problem.coupling().n_rows()) +
                   " nodes) faces the primary surface ('Primary boundary "
                   "id' = " +
                   std::to_string(contact.primary_boundary_id) +
                   ") within 'Search distance': the bodies cannot come into "
                   "contact (a face pairs only if all of it does: faces larger "
                   "than the distance may need more 'Number of contact "
                   "refinements')."));
      if (parameters.run_control.dry_run)
        {
          console.stream() << "Dry run: parameters, mesh and contact pairing "
                              "are valid."
                           << std::endl;
          return false;
        }
      std::vector<std::string> files = result_files;
      files.push_back("used_parameters.prm");
      parameters.output.prepare_directory(files,
                                          dof_handler.get_communicator());
      if (console.is_root())
        {
          std::ofstream used(parameters.output.path("used_parameters.prm"));
          used << parameters.used_parameters;
        }
      return true;
    }



    template <int dim>
    void
    print_step(IO::Console                     &console,
               const Solvers::StepInfo         &step,
               const Solvers::NewtonStatistics &statistics,
               const ContactNewtonProblem<dim> &problem)
    {
      const auto &values = step.state.values;
      const bool  load_factor_only =
        step.n_stages == 1 && values.size() == 1 &&
        values.begin()->first == Solvers::load_factor_channel().name;
      auto &out = console.stream();
      if (load_factor_only)
        out << "Load step " << step.step_in_stage << " of "
            << std::max(step.step_in_stage, step.n_steps_in_stage)
            << ", load factor "
            << IO::Console::format(step.state.load_factor());
      else
        out << "Stage " << step.stage + 1 << " of " << step.n_stages
            << (step.stage_name.empty() ? "" : " (" + step.stage_name + ")")
            << ", step " << step.step_in_stage << " of "
            << std::max(step.step_in_stage, step.n_steps_in_stage)
            << ", pseudo-time " << IO::Console::format(step.state.time);
      out << ": Newton iterations " << statistics.n_iterations
          << ", active contact nodes " << problem.enforcement().n_active()
          << std::endl;
    }



    template <int dim>
    void
    warn_if_search_edge_reached(IO::Console                     &console,
                                const ContactNewtonProblem<dim> &problem)
    {
      if (problem.enforcement().touches_search_edge())
        console.stream() << "  Warning: the contact zone reaches the edge of "
                            "the search region; increase 'Search distance'."
                         << std::endl;
    }



    template <int dim>
    Solvers::LoadSteppingStatistics
    run_load_steps(ContactNewtonProblem<dim>            &problem,
                   const ExternalLoad                   &load,
                   const Solvers::LoadProgramParameters &program,
                   const IO::OutputParameters           &output,
                   const DoFHandler<dim>                &dof_handler,
                   const Mapping<dim>                   &mapping,
                   IO::Console                          &console,
                   const StepReport                     &report,
                   IO::JsonObject                       &timings)
    {
      IO::SolutionOutput<dim> solution_output(output,
                                              "solution",
                                              dof_handler.get_communicator());
      const auto solid_fields = problem.solid().output_postprocessors();
      std::vector<const DataPostprocessor<dim> *> postprocessors;
      for (const auto &p : solid_fields)
        postprocessors.push_back(p.get());

      // Reaction forces on the chosen boundaries, one row per accepted
      // step, written when the load program has ended.
      std::vector<types::boundary_id> reaction_ids;
      {
        const auto on_mesh = dof_handler.get_triangulation().get_boundary_ids();
        for (const unsigned int id : output.reaction_boundary_ids)
          {
            AssertThrow(std::find(on_mesh.begin(), on_mesh.end(), id) !=
                          on_mesh.end(),
                        ExcMessage("Output: 'Reaction boundary ids' names "
                                   "boundary id " +
                                   std::to_string(id) +
                                   ", which the mesh does not have."));
            reaction_ids.push_back(id);
          }
      }
      std::vector<std::vector<double>> reaction_rows;

      Solvers::LoadStepCallbacks callbacks;
      callbacks.solve = [&](const Solvers::LoadState &state) {
        return problem.solve(state,
                             load,
                             console.stream(IO::Verbosity::verbose));
      };
      callbacks.accept = [&](const Solvers::StepInfo         &step,
                             const Solvers::NewtonStatistics &statistics) {
        problem.commit();
        report(step, statistics);
        if (!reaction_ids.empty())
          {
            std::vector<double> row = {static_cast<double>(step.step),
                                       step.state.time,
                                       step.state.load_factor()};
            for (const auto &force :
                 problem.reaction_forces(reaction_ids, step.state, load))
              for (unsigned int c = 0; c < dim; ++c)
                row.push_back(force[c]);
            reaction_rows.push_back(std::move(row));
          }
        if (output.write_graphical_output)
          {
            std::vector<IO::NodalScalarField> contact_fields;
            for (auto &[name, values] :
                 Contact::contact_nodal_fields(problem.coupling(),
                                               problem.enforcement()))
              contact_fields.push_back({name, std::move(values)});
            solution_output.write(dof_handler,
                                  mapping,
                                  problem.displacement(),
                                  postprocessors,
                                  contact_fields,
                                  step.state.time,
                                  step.step);
          }
      };
      callbacks.reject = [&]() {
        problem.restore();
      };

      const auto start = std::chrono::steady_clock::now();
      const auto stepping =
        Solvers::run_load_program(program, callbacks, console);
      if (!reaction_ids.empty() && console.is_root())
        {
          std::ofstream csv(output.path("reactions.csv"));
          csv << "step,pseudo_time,load_factor";
          for (const auto id : reaction_ids)
            for (unsigned int c = 0; c < dim; ++c)
              csv << ",boundary_" << id << "_R"
                  << "xyz"[c] << "_N";
          csv << '\n' << std::setprecision(10);
          for (const auto &row : reaction_rows)
            {
              for (unsigned int i = 0; i < row.size(); ++i)
                csv << (i > 0 ? "," : "") << row[i];
              csv << '\n';
            }
        }
      const auto &times = problem.times();
      timings.set("contact_setup_s", times.contact_setup)
        .set("contact_solve_s", times.contact_setup + times.newton)
        .set("contact_cpu_s", times.contact_cpu)
        .set("load_stepping_s", IO::seconds_since(start))
        .set("assembly_s", times.assembly)
        .set("linear_solve_s", times.linear_solve)
        .set("residual_s", times.residual)
        .set("active_set_update_s", times.active_set_update);
      const auto &linear = problem.linear_solver_statistics();
      timings.set("factorisation_s", linear.factorisation_time)
        .set("n_factorisations", linear.n_factorisations)
        .set("n_reuse_solves", linear.n_reuse_solves)
        .set("n_reuse_gmres_iterations", linear.n_reuse_iterations)
        .set("n_failed_reuse", linear.n_failed_reuse);
      return stepping;
    }



    template <int dim>
    void
    measure_contact_cost(ContactNewtonProblem<dim>  &problem,
                         const ExternalLoad         &load,
                         const Solvers::LoadState   &state,
                         const ContactRunParameters &parameters,
                         IO::Console                &console,
                         IO::JsonObject             &timings)
    {
      if (!parameters.run_control.measure_contact_cost)
        return;
      const double contact = problem.times().contact_cpu;
      const double fixed   = problem.time_fixed_active_set_solve(state, load);
      timings.set("fixed_active_set_solve_s", fixed)
        .set("contact_cost_ratio", contact / fixed);
      console.stream() << "Cost of contact: " << std::fixed
                       << std::setprecision(2) << contact / fixed
                       << " times one assembly and solve with the active set "
                          "held fixed (processor time)"
                       << std::defaultfloat << std::setprecision(6)
                       << std::endl;
    }



    template <int dim>
    ExternalLoad
    point_load(const DoFHandler<dim>        &dof_handler,
               const types::global_dof_index dof,
               const double                  force)
    {
      const bool   owned = dof_handler.locally_owned_dofs().is_element(dof);
      ExternalLoad load;
      load.add = [force, dof, owned](const Solvers::LoadState        &state,
                                     const AffineConstraints<double> &c,
                                     TrilinosWrappers::MPI::Vector   &vector) {
        if (owned)
          {
            Vector<double> f(1);
            f(0) = state.load_factor() * force;
            c.distribute_local_to_global(f,
                                         std::vector<types::global_dof_index>{
                                           dof},
                                         vector);
          }
      };
      load.magnitude = [force](const Solvers::LoadState &state) {
        return state.load_factor() * std::abs(force);
      };
      return load;
    }



#define INSTANTIATE(dim)                                                   \
  template IO::JsonObject mesh_summary(                                    \
    const DoFHandler<dim> &,                                               \
    const std::function<double(const Point<dim> &)> &);                    \
  template void print_setup(IO::Console &,                                 \
                            const DoFHandler<dim> &,                       \
                            const ContactNewtonProblem<dim> &);            \
  template bool begin_run(IO::Console &,                                   \
                          const DoFHandler<dim> &,                         \
                          const ContactNewtonProblem<dim> &,               \
                          const ContactRunParameters &,                    \
                          const std::vector<std::string> &);               \
  template void print_step(IO::Console &,                                  \
                           const Solvers::StepInfo &,                      \
                           const Solvers::NewtonStatistics &,              \
                           const ContactNewtonProblem<dim> &);             \
  template void warn_if_search_edge_reached(                               \
    IO::Console &,                                                         \
    const ContactNewtonProblem<dim> &);                                    \
  template Solvers::LoadSteppingStatistics run_load_steps(                 \
    ContactNewtonProblem<dim> &,                                           \
    const ExternalLoad &,                                                  \
    const Solvers::LoadProgramParameters &,                                \
    const IO::OutputParameters &,                                          \
    const DoFHandler<dim> &,                                               \
    const Mapping<dim> &,                                                  \
    IO::Console &,                                                         \
    const StepReport &,                                                    \
    IO::JsonObject &);                                                     \
  template ExternalLoad point_load(const DoFHandler<dim> &,                \
                                   const types::global_dof_index,          \
                                   const double);                          \
  template void         measure_contact_cost(ContactNewtonProblem<dim> &,  \
                                             const ExternalLoad &,         \
                                             const Solvers::LoadState &,   \
                                             const ContactRunParameters &, \
                                             IO::Console &,                \
                                             IO::JsonObject &);
    INSTANTIATE(2)
    INSTANTIATE(3)
#undef INSTANTIATE
  } // namespace Problems
} // namespace Common
