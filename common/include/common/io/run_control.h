/**
 * @file run_control.h
 * Parameters of subsection "Run control", shared by the applications: a
 * dry run that stops after the set-up, and the optional measurement of the
 * cost of contact.
 */
#ifndef common_io_run_control_h
#define common_io_run_control_h

#include <deal.II/base/parameter_handler.h>

namespace Common
{
  namespace IO
  {
    /** Subsection "Run control". */
    struct RunControlParameters
    {
      /** @brief Declare the entries of subsection "Run control". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read the entries of subsection "Run control". */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Stop after building mesh, DoFs and contact pairing. */
      bool dry_run;
      /** Time one solve with the converged active set held fixed and report
       * the cost of contact relative to it. */
      bool measure_contact_cost;
    };
  } // namespace IO
} // namespace Common

#endif
