/**
 * @file contact_run_parameters.h
 * The parameter blocks every contact application has: contact, nonlinear
 * and linear solver, load program, output and run control. An
 * application's parameters derive from this and add their own blocks
 * (geometry, mesh, loads, materials).
 */
#ifndef common_problems_contact_run_parameters_h
#define common_problems_contact_run_parameters_h

#include <common/contact/contact_parameters.h>
#include <common/io/output_parameters.h>
#include <common/io/run_control.h>
#include <common/physics/solid_model.h>
#include <common/solvers/linear_solver.h>
#include <common/solvers/load_program.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace Common
{
  namespace Problems
  {
    /**
     * @brief Subsections "Solid", "Contact", "Nonlinear solver", "Linear
     * solver", "Load program", "Output" and "Run control".
     */
    struct ContactRunParameters
    {
      /**
       * @brief Declare the entries of the shared subsections.
       * @param[in] channels Channels of the load program; by default the
       * load factor, with the single stage ramping it to 1.
       * @param[in] default_end_values Default end values of the channels
       * in stage 1.
       */
      static void
      declare_parameters(dealii::ParameterHandler                &prm,
                         const std::vector<Solvers::LoadChannel> &channels =
                           {Solvers::load_factor_channel()},
                         const std::map<std::string, double>
                           &default_end_values = {{"Load factor", 1.}});

      /** @brief Read and check the entries of the shared subsections, and
       * keep the whole input as used_parameters.
       * @param[in] channels The channels given to declare_parameters(). */
      void
      parse_parameters(dealii::ParameterHandler                &prm,
                       const std::vector<Solvers::LoadChannel> &channels = {
                         Solvers::load_factor_channel()});

      Physics::SolidParameters           solid;
      Contact::ContactParameters         contact;
      Solvers::NonlinearSolverParameters nonlinear_solver;
      Solvers::LinearSolverParameters    linear_solver;
      Solvers::LoadProgramParameters     load_program;
      IO::OutputParameters               output;
      IO::RunControlParameters           run_control;

      /** The parameters as read (every entry), for used_parameters.prm. */
      std::string used_parameters;
    };
  } // namespace Problems
} // namespace Common

#endif
