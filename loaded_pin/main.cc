/*
 * loaded_pin: benchmark 4 of the FENET/NAFEMS advanced contact benchmarks,
 * a steel pin pulled in the hole of an aluminium lug (3D quarter model,
 * receding contact).
 */
#include <common/io/run_main.h>

#include "parameters.h"
#include "pin_problem.h"

int
main(int argc, char *argv[])
{
  return Common::IO::run_main(
    argc,
    argv,
    "loaded_pin",
    "FENET benchmark 4, steel pin pulled in the hole of an aluminium lug "
    "(3D quarter model)",
    &LoadedPin::Parameters::declare_parameters,
    [](const std::string &parameter_file) {
      const LoadedPin::Parameters parameters(parameter_file);
      LoadedPin::PinProblem(parameters).run();
    });
}
