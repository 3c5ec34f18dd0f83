/*
 * cgs_roller: benchmark 1 of the FENET/NAFEMS advanced contact benchmarks,
 * a 2D elastic cylinder pressed onto an elastic block (Hertz line contact).
 */
#include <common/io/run_main.h>

#include "parameters.h"
#include "roller_problem.h"

int
main(int argc, char *argv[])
{
  return Common::IO::run_main(
    argc,
    argv,
    "cgs_roller",
    "FENET benchmark 1, elastic cylinder on an elastic block (plane strain, "
    "Hertz line contact)",
    &CgsRoller::Parameters::declare_parameters,
    [](const std::string &parameter_file) {
      const CgsRoller::Parameters parameters(parameter_file);
      CgsRoller::RollerProblem    problem(parameters);
      problem.run();
    });
}
