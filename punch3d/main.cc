/*
 * punch3d: benchmark 2 of the FENET/NAFEMS advanced contact benchmarks, a
 * punch with a rounded edge pressed onto a cylindrical foundation, as an
 * axisymmetric model or a 3D quarter model.
 */
#include <common/io/run_main.h>

#include "parameters.h"
#include "punch_problem.h"

int
main(int argc, char *argv[])
{
  return Common::IO::run_main(
    argc,
    argv,
    "punch3d",
    "FENET benchmark 2, punch with a rounded edge on a cylindrical "
    "foundation (axisymmetric or 3D quarter model)",
    &Punch3d::Parameters::declare_parameters,
    [](const std::string &parameter_file) {
      const Punch3d::Parameters parameters(parameter_file);
      if (parameters.model.three_d)
        Punch3d::PunchProblem<3>(parameters).run();
      else
        Punch3d::PunchProblem<2>(parameters).run();
    });
}
