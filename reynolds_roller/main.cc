/*
 * reynolds_roller: benchmark 5 of the FENET/NAFEMS advanced contact
 * benchmarks, a rigid steel roller pressed 3 mm into a rubber strip and
 * turned a full revolution (Reynolds creep; plane strain).
 */
#include <common/io/run_main.h>

#include "parameters.h"
#include "rolling_problem.h"

int
main(int argc, char *argv[])
{
  return Common::IO::run_main(
    argc,
    argv,
    "reynolds_roller",
    "FENET benchmark 5, a rigid steel roller pressed into a rubber strip "
    "and turned a full revolution (plane strain or its 3D extrusion)",
    &ReynoldsRoller::Parameters::declare_parameters,
    [](const std::string &parameter_file) {
      const ReynoldsRoller::Parameters parameters(parameter_file);
      if (parameters.geometry.three_d)
        ReynoldsRoller::RollingProblem<3>(parameters).run();
      else
        ReynoldsRoller::RollingProblem<2>(parameters).run();
    });
}
