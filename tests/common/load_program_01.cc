/*
 * The load stepping of common/solvers/load_program.h with a scripted Newton
 * solve: a step that fails is cut back by half until an attempt converges,
 * the increment then grows back to the nominal one, and the record keeps,
 * beside the iterations of each accepted attempt, the iterations of the
 * failed attempts before it. summary.json's Newton record
 * (Problems::newton_summary()) reports the most iterations of a step with
 * and without those failed attempts, and the active-set solves of each
 * step (first and later iterations, failed attempts included) beside
 * them: the most linear solves of a step are its iterations with cutbacks
 * plus those solves (step 1: 15 + 1 + 2 + 3 = 21; step 2: 4 + 10 = 14).
 * The stabilized solves of a step count its failed attempts' too (step 1:
 * 1 + 2 = 3; listed per step), and the most iterations of one solve is the
 * largest over every attempt (7, in the first, failed one). An attempt that
 * follows a cutback of its step is marked as such (LoadState::after_cutback:
 * the second and third), and the mark ends with the accepted step.
 */

#include <common/io/console.h>
#include <common/problems/contact_run.h>
#include <common/solvers/load_program.h>

#include "../tests.h"

#include <deal.II/base/mpi.h>

#include <vector>

using namespace dealii;
using namespace Common;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Solvers::LoadProgramParameters program;
  program.channels      = {Solvers::load_factor_channel()};
  program.min_increment = 1e-3;
  program.stages.push_back({"loading", 2, {{"Load factor", 1.}}});

  // The attempts in order: (converged, iterations). The first step fails
  // twice (at 0.5 and 0.25 of the stage) before it converges at 0.125.
  const std::vector<std::pair<bool, unsigned int>> script =
    {{false, 7}, {false, 5}, {true, 3}, {true, 4}, {true, 2}, {true, 2}};
  // Extra active-set solves of each attempt: (first, later iterations).
  const std::vector<std::pair<unsigned int, unsigned int>> extra =
    {{1, 0}, {0, 2}, {3, 0}, {4, 6}, {0, 0}, {0, 0}};
  // Stabilized solves of each attempt and the most iterations of one of
  // its solves (the third attempt: 3 iterations over 2 stabilized solves
  // and the final one).
  const std::vector<std::pair<unsigned int, unsigned int>> stabilized =
    {{0, 7}, {1, 5}, {2, 1}, {0, 4}, {0, 2}, {0, 2}};
  unsigned int               attempt = 0;
  Solvers::LoadStepCallbacks callbacks;
  callbacks.solve = [&](const Solvers::LoadState &state) {
    deallog << "attempt " << attempt + 1 << " at pseudo-time " << state.time
            << (state.after_cutback ? ", after a cutback" : "") << std::endl;
    Solvers::NewtonStatistics statistics;
    statistics.converged                      = script.at(attempt).first;
    statistics.n_iterations                   = script.at(attempt).second;
    statistics.n_extra_first_iteration_solves = extra.at(attempt).first;
    statistics.n_extra_later_iteration_solves = extra.at(attempt).second;
    statistics.n_stabilized_solves            = stabilized.at(attempt).first;
    statistics.max_iterations_per_solve       = stabilized.at(attempt).second;
    if (!statistics.converged)
      statistics.failure = "scripted failure";
    ++attempt;
    return statistics;
  };
  callbacks.accept = [](const Solvers::StepInfo &,
                        const Solvers::NewtonStatistics &) {
  };
  callbacks.reject = []() {
  };

  IO::Console console(IO::Verbosity::quiet, MPI_COMM_SELF);
  const Solvers::LoadSteppingStatistics stepping =
    Solvers::run_load_program(program, callbacks, console);

  deallog << "accepted steps " << stepping.newton_iterations.size()
          << ", cutbacks " << stepping.n_cutbacks << std::endl;
  for (unsigned int i = 0; i < stepping.newton_iterations.size(); ++i)
    deallog << "step " << i + 1 << " at pseudo-time " << stepping.times[i]
            << ": iterations " << stepping.newton_iterations[i]
            << ", in failed attempts before it "
            << stepping.failed_attempt_iterations[i] << std::endl;
  deallog << Problems::newton_summary(stepping).to_string() << std::endl;
}
