/**
 * @file contact_run_parameters.h
 * The parameter blocks every contact application has: contact, nonlinear
 * and linear solver, load stepping, output and run control. An
 * application's parameters derive from this and add their own blocks
 * (geometry, mesh, loads, materials).
 */
#ifndef common_problems_contact_run_parameters_h
#define common_problems_contact_run_parameters_h

#include <common/contact/contact_parameters.h>
#include <common/io/output_parameters.h>
#include <common/io/run_control.h>
#include <common/solvers/linear_solver.h>
#include <common/solvers/load_stepping.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Common
{
  namespace Problems
  {
    /**
     * @brief Subsections "Contact", "Nonlinear solver", "Linear solver",
     * "Load stepping", "Output" and "Run control".
     */
    struct ContactRunParameters
    {
      /** @brief Declare the entries of the shared subsections. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read and check the entries of the shared subsections, and
       * keep the whole input as used_parameters. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      Contact::ContactParameters         contact;
      Solvers::NonlinearSolverParameters nonlinear_solver;
      Solvers::LinearSolverParameters    linear_solver;
      Solvers::LoadSteppingParameters    load_stepping;
      IO::OutputParameters               output;
      IO::RunControlParameters           run_control;

      /** The parameters as read (every entry), for used_parameters.prm. */
      std::string used_parameters;
    };
  } // namespace Problems
} // namespace Common

#endif
