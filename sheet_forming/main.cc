/*
 * sheet_forming: benchmark 3 of the FENET/NAFEMS advanced contact
 * benchmarks, an aluminium strip bent by a rigid punch into a rigid die,
 * then released (plane strain half model, springback).
 */
#include <common/io/run_main.h>

#include "forming_problem.h"
#include "parameters.h"

int
main(int argc, char *argv[])
{
  return Common::IO::run_main(
    argc,
    argv,
    "sheet_forming",
    "FENET benchmark 3, aluminium strip bent by a rigid punch into a rigid "
    "die and released (plane strain half model or 3D strip)",
    &SheetForming::Parameters::declare_parameters,
    [](const std::string &parameter_file) {
      const SheetForming::Parameters parameters(parameter_file);
      if (parameters.geometry.three_d)
        SheetForming::FormingProblem<3>(parameters).run();
      else
        SheetForming::FormingProblem<2>(parameters).run();
    });
}
