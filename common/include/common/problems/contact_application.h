/**
 * @file contact_application.h
 * The skeleton every contact application shares: the discretisation (a
 * shared triangulation, a vector FE_Q element with its MappingQ, the DoF
 * handler), the solid operator, the contact geometry and the
 * contact-Newton problem, and the run from mesh to summary.json. An
 * application derives from it and supplies only its geometry, boundary
 * conditions, load, load program (its parameters) and benchmark
 * postprocessing, through the hooks below.
 */
#ifndef common_problems_contact_application_h
#define common_problems_contact_application_h

#include <common/contact/contact_geometry.h>
#include <common/io/console.h>
#include <common/io/json_writer.h>
#include <common/io/plotting.h>
#include <common/physics/solid_operator.h>
#include <common/problems/contact_newton_problem.h>
#include <common/problems/contact_run_parameters.h>
#include <common/solvers/load_program.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <string>
#include <vector>

namespace Common
{
  namespace Problems
  {
    /**
     * @brief Base of a contact application: discretisation, contact
     * problem and the run.
     */
    template <int dim>
    class ContactApplication
    {
    public:
      /**
       * @param[in] parameters The shared parameter blocks of the run; must
       * outlive this object.
       * @param[in] element_degree Degree of the FE_Q element and of the
       * mapping.
       * @param[in] application_name The executable's name, the benchmark
       * key of summary.json.
       */
      ContactApplication(const ContactRunParameters &parameters,
                         const unsigned int          element_degree,
                         const std::string          &application_name);

      virtual ~ContactApplication() = default;

      /**
       * @brief The run: print title(), make_grid(), setup_system(),
       * begin_run() (set-up report; a dry run ends here), the load program
       * with postprocess_step() after each accepted step, the cost of
       * contact if asked for, and output_results(). Adds setup_s and
       * total_s to the timings.
       */
      void
      run();

    protected:
      /** @brief One line naming the benchmark and the model, printed
       * first. */
      virtual std::string
      title() const = 0;

      /** @brief Build the mesh in @p triangulation. */
      virtual void
      make_grid() = 0;

      /**
       * @brief Distribute the DoFs, build the Dirichlet and hanging-node
       * constraints, and call setup_contact_problem().
       */
      virtual void
      setup_system() = 0;

      /** @brief The external load at a state of the load program. */
      virtual ExternalLoad
      external_load() const = 0;

      /** @brief Files of the output directory a run writes besides those
       * every contact application writes (summary.json,
       * contact_profile.csv, reference_profile.csv, the plots
       * contact_pressure, tangential_traction and slip, solution.pvd);
       * all are cleared at the start of a run. */
      virtual std::vector<std::string>
      result_files() const = 0;

      /** @brief Report an accepted step (console). */
      virtual void
      postprocess_step(const Solvers::StepInfo         &step,
                       const Solvers::NewtonStatistics &statistics) = 0;

      /** @brief The benchmark's results after the last step. */
      virtual void
      output_results(const Solvers::LoadSteppingStatistics &stepping) = 0;

      /**
       * @brief Close @p constraints_dirichlet_and_hanging_nodes, take the
       * solid and the contact geometry, and set up the contact problem.
       * @param[in] reference_modulus Scales the complementarity constant
       * (MPa), usually the secondary body's Young's modulus.
       */
      void
      setup_contact_problem(
        std::unique_ptr<Physics::SolidOperator<dim>>   solid,
        std::unique_ptr<Contact::ContactGeometry<dim>> geometry,
        const double                                   reference_modulus);

      /** @brief The blocks of summary.json an application fills. */
      struct SummaryBlocks
      {
        /** The case (case_summary() and the application's keys). */
        IO::JsonObject case_description;
        /** mesh_summary(). */
        IO::JsonObject mesh;
        /** The headline numbers with units in their keys. */
        IO::JsonObject results;
        /** The reference values and their sources. */
        IO::JsonObject reference;
        /** Results over references. */
        IO::JsonObject ratios;
      };

      /**
       * @brief Write summary.json (rank 0) with the blocks benchmark (the
       * application's name), case, mesh, newton, results, reference,
       * ratios and timing_s; call last, so that only a complete run leaves
       * one.
       */
      void
      write_summary(const Solvers::LoadSteppingStatistics &stepping,
                    const SummaryBlocks                   &blocks) const;

      /**
       * @brief Write @p plots into the output directory
       * (IO::write_plots()); if gnuplot is missing, say on the console that
       * only the scripts were written, and name each plot gnuplot could
       * not draw. Call on rank 0.
       */
      void
      write_plots(
        const std::vector<std::pair<std::string, IO::PlotDescription>> &plots);

      /** @brief The load factor at the end of the load program. */
      double
      final_load_factor() const;

      const ContactRunParameters &run_parameters;
      const std::string           application_name;
      const MPI_Comm              mpi_communicator;
      IO::Console                 console;

      dealii::parallel::shared::Triangulation<dim> triangulation;
      const dealii::FESystem<dim>                  fe;
      const dealii::MappingQ<dim>                  mapping;
      dealii::DoFHandler<dim>                      dof_handler;

      /** Hanging-node and homogeneous Dirichlet constraints (on Newton
       * increments). */
      dealii::AffineConstraints<double> constraints_dirichlet_and_hanging_nodes;
      std::unique_ptr<Physics::SolidOperator<dim>>   solid;
      std::unique_ptr<Contact::ContactGeometry<dim>> contact_geometry;
      std::unique_ptr<ContactNewtonProblem<dim>>     contact_problem;

      /** Wall and processor times of the run (s), for summary.json. */
      IO::JsonObject timings;
    };
  } // namespace Problems
} // namespace Common

#endif
