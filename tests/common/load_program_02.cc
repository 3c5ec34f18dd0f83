/*
 * The largest step of a load channel (subsection "Load program/Largest
 * step"): a stage whose steps change a channel by more than its limit
 * divides each step into the fewest equal substeps that respect it. A
 * tool moving 28.5 mm in one step with a limit of 1 mm takes 29 steps of
 * 28.5 / 29 mm, the last one exactly at the stage's end value; a stage
 * whose steps meet the limit exactly, or change a limited channel by less,
 * is not divided; a channel without a limit (0) never divides a stage. A
 * negative limit, and one that would divide a stage into more than
 * max_steps_per_stage steps, are refused with a message naming the entry.
 */

#include <common/io/console.h>
#include <common/io/run_main.h>
#include <common/solvers/load_program.h>

#include "../tests.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace Common;

namespace
{
  const std::vector<Solvers::LoadChannel> channels = {
    {"Punch displacement", "Punch travel, mm."},
    {"Die displacement", "Die travel, mm."}};

  const std::string stages = "  set Number of stages = 3\n"
                             "  subsection Stage 1\n"
                             "    set Number of steps    = 1\n"
                             "    set Punch displacement = 28.5\n"
                             "    set Die displacement   = 0\n"
                             "  end\n"
                             "  subsection Stage 2\n"
                             "    set Number of steps    = 2\n"
                             "    set Punch displacement = 26.5\n"
                             "    set Die displacement   = 0.5\n"
                             "  end\n"
                             "  subsection Stage 3\n"
                             "    set Number of steps    = 4\n"
                             "    set Punch displacement = 24.5\n"
                             "  end\n";

  /** Parse the program with the given subsection "Largest step"; print
   * "refused: <message>" if it is refused. */
  bool
  parse(const std::string              &largest_step,
        Solvers::LoadProgramParameters &program)
  {
    ParameterHandler prm;
    Solvers::LoadProgramParameters::declare_parameters(prm, channels);
    program.channels = channels;
    try
      {
        prm.parse_input_from_string("subsection Load program\n" + stages +
                                    "  subsection Largest step\n" +
                                    largest_step + "  end\nend\n");
        program.parse_parameters(prm);
      }
    catch (const std::exception &e)
      {
        deallog << "refused: " << IO::one_line_message(e) << std::endl;
        return false;
      }
    return true;
  }



  void
  run(const std::string &largest_step)
  {
    deallog << "Largest step:" << (largest_step.empty() ? " none" : "")
            << std::endl;
    std::istringstream lines(largest_step);
    for (std::string line; std::getline(lines, line);)
      deallog << line << std::endl;
    Solvers::LoadProgramParameters program;
    if (!parse(largest_step, program))
      return;
    for (unsigned int s = 0; s < program.stages.size(); ++s)
      deallog << "stage " << s + 1 << ": " << program.substeps_per_step(s)
              << " substeps per step" << std::endl;

    Solvers::LoadStepCallbacks callbacks;
    double                     last_punch = 0.;
    double                     largest    = 0.;
    unsigned int               n_steps    = 0;
    callbacks.solve = [&](const Solvers::LoadState &state) {
      largest =
        std::max(largest,
                 std::abs(state.value("Punch displacement") - last_punch));
      Solvers::NewtonStatistics statistics;
      statistics.converged    = true;
      statistics.n_iterations = 1;
      return statistics;
    };
    callbacks.accept = [&](const Solvers::StepInfo &step,
                           const Solvers::NewtonStatistics &) {
      last_punch = step.state.value("Punch displacement");
      ++n_steps;
      if (step.step_in_stage == step.n_steps_in_stage)
        deallog << "stage " << step.stage + 1 << " ends after "
                << step.n_steps_in_stage << " steps at punch "
                << step.state.value("Punch displacement") << " mm, die "
                << step.state.value("Die displacement") << " mm" << std::endl;
    };
    callbacks.reject = []() {
    };
    IO::Console console(IO::Verbosity::quiet, MPI_COMM_SELF);
    Solvers::run_load_program(program, callbacks, console);
    deallog << n_steps << " steps, largest punch step " << largest << " mm"
            << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // No limit: the nominal steps.
  run("");
  // 1 mm on the punch: stage 1 (28.5 mm in one step) takes 29 steps,
  // stage 2 (1 mm per step) and stage 3 (0.5 mm per step) none more.
  run("    set Punch displacement = 1\n");
  // 0.2 mm on the die: stage 2 (0.25 mm per step) is divided in two.
  run("    set Punch displacement = 1\n"
      "    set Die displacement   = 0.2\n");
  run("    set Punch displacement = -1\n");
  run("    set Punch displacement = 1e-9\n");
}
