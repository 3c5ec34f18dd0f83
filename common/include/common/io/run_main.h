/**
 * @file run_main.h
 * The body of every application's main(): command line, MPI start-up,
 * one-line error reports and exit codes. Knows nothing about the physics.
 */
#ifndef common_io_run_main_h
#define common_io_run_main_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>

namespace Common
{
  namespace IO
  {
    /**
     * @brief Run an application.
     *
     * Usage: `<app> <file.prm>` runs the case; `<app> --help` prints the
     * usage; `<app> --print-parameters` prints every `.prm` entry with its
     * documentation, units and default. Without arguments the usage is
     * printed and the exit code is 1. A parameter file that is missing, or
     * has no entries (empty, or comments only), is refused before the
     * application reads it. Any error is reported in one line on
     * standard error, `<app>: error: <what>`, and the exit code is 1.
     * In a parallel run an error on any rank ends every rank (none is
     * left waiting in a collective call) and is reported once: by rank 0
     * if it has it (an input error occurs on every rank), otherwise by the
     * rank that has it, `<app>: error (MPI rank <r>): <what>`.
     *
     * @param[in] argc, argv Command line.
     * @param[in] application_name Executable name for messages.
     * @param[in] description One line describing the benchmark.
     * @param[in] declare_parameters Declares all entries of the app.
     * @param[in] run Runs the case described by a parameter file.
     * @return Process exit code.
     */
    int
    run_main(
      int                                                    argc,
      char                                                 **argv,
      const std::string                                     &application_name,
      const std::string                                     &description,
      const std::function<void(dealii::ParameterHandler &)> &declare_parameters,
      const std::function<void(const std::string &)>        &run);

    /**
     * @brief Collapse the message of an exception into one line. For
     * deal.II exceptions only the additional information is kept, not the
     * banner with source file and stack trace.
     */
    std::string
    one_line_message(const std::exception &exception);
  } // namespace IO
} // namespace Common

#endif
