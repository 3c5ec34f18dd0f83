/**
 * @file load_program.h
 * A quasi-static load program in pseudo-time, made of stages: each stage
 * takes a number of steps and moves named load channels (a load factor, a
 * tool displacement, a rotation angle: whatever the application declares)
 * linearly from their values at its start to the values it sets at its
 * end; a channel a stage does not set holds its value. Ramping a load,
 * prescribing a motion, holding and releasing are all stages. Stage k
 * (counted from 0) covers the pseudo-time interval [k, k + 1].
 *
 * A channel may limit its change in one step ("Largest step"): the steps
 * of a stage that exceed it are divided into equal substeps beforehand.
 * The stepping cuts a failed step back (the problem restores its last
 * accepted state) and retries with half the increment, down to a minimum
 * per stage; after a successful reduced step the increment grows back to
 * the stage's nominal one. Sees only callbacks.
 */
#ifndef common_solvers_load_program_h
#define common_solvers_load_program_h

#include <common/io/console.h>
#include <common/solvers/newton_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace Common
{
  namespace Solvers
  {
    /**
     * @brief A load channel an application declares: its entry name in
     * each stage subsection and the documentation of that entry (with
     * units).
     */
    struct LoadChannel
    {
      std::string name;
      std::string documentation;
    };

    /** The channel of the applications that scale one load: the fraction
     * of the full load. */
    LoadChannel
    load_factor_channel();

    /**
     * @brief Values of every channel at a point of the load program.
     */
    struct LoadState
    {
      /** Pseudo-time: stage index plus the fraction of that stage. */
      double time = 0.;
      /** Channel values, by channel name. */
      std::map<std::string, double> values;
      /** True for an attempt that follows a cutback of the same step (the
       * load program's retry with a smaller increment). */
      bool after_cutback = false;

      /** @brief The value of @p channel; throws if it is not declared. */
      double
      value(const std::string &channel) const;

      /** @brief The value of the channel "Load factor". */
      double
      load_factor() const;

      /** @brief A state with only the channel "Load factor". */
      static LoadState
      with_load_factor(const double load_factor);
    };

    /**
     * @brief Where an accepted step lies in the program.
     */
    struct StepInfo
    {
      /** Accepted steps so far, this one included (from 1). */
      unsigned int step = 0;
      /** Stage index (from 0), its name and the number of stages. */
      unsigned int stage = 0;
      std::string  stage_name;
      unsigned int n_stages = 1;
      /** Accepted steps of this stage so far (from 1) and its nominal
       * number of steps. */
      unsigned int step_in_stage    = 0;
      unsigned int n_steps_in_stage = 1;
      /** The state the step reached. */
      LoadState state;
    };

    /**
     * @brief Parameters of subsection "Load program".
     */
    struct LoadProgramParameters
    {
      /** Most stages a program may have. */
      static constexpr unsigned int max_stages = 6;
      /** Smallest and largest magnitude of a channel's nonzero value, in
       * the channel's unit: beyond them the residuals, which are relative
       * to the load, lose their meaning. */
      static constexpr double min_channel_value = 1e-9;
      static constexpr double max_channel_value = 1e9;
      /** Most steps a stage may take after the division by "Largest
       * step". */
      static constexpr unsigned int max_steps_per_stage = 1000000;

      /**
       * @brief Throw a one-line message unless the magnitude of @p value,
       * a load given outside a load program (a pressure, a force), lies in
       * [min_channel_value, max_channel_value]: the residuals are relative
       * to the load, as they are for a channel.
       * @param[in] entry The entry as the message names it, e.g.
       * "Loading: 'Pressure'".
       * @param[in] unit The entry's unit, e.g. "MPa".
       */
      static void
      check_load_magnitude(const std::string &entry,
                           const double       value,
                           const std::string &unit);

      /**
       * @brief Declare subsection "Load program" with "Number of stages",
       * "Minimum increment", the subsection "Largest step" (one entry per
       * channel) and the subsections "Stage 1" to
       * "Stage <max_stages>", each with "Name", "Number of steps" and one
       * entry per channel (a number: the channel's value at the end of the
       * stage; empty: hold the value).
       * @param[in] default_end_values Default end value of each channel
       * in stage 1 (for the single-stage program of a load factor: 1).
       */
      static void
      declare_parameters(
        dealii::ParameterHandler            &prm,
        const std::vector<LoadChannel>      &channels,
        const std::map<std::string, double> &default_end_values = {});

      /** @brief Read and check the program. Throws a one-line message
       * naming the entry on a bad value, or when a stage beyond "Number of
       * stages" has been set. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      struct Stage
      {
        std::string  name;
        unsigned int n_steps;
        /** Value of each channel at the end of the stage (every channel;
         * held values filled in). */
        std::map<std::string, double> end_values;
      };

      std::vector<LoadChannel> channels;
      std::vector<Stage>       stages;
      /** Smallest increment after cutbacks, as a fraction of a stage. */
      double min_increment;
      /** Largest change of a channel in one step (subsection "Largest
       * step"), for the channels that have a limit, in the channel's
       * unit. */
      std::map<std::string, double> largest_step;
      /**
       * @brief The number of equal substeps into which each step of stage
       * @p s is divided so that no channel changes by more than its
       * largest step: 1 when no limit applies.
       */
      unsigned int
      substeps_per_step(const unsigned int s) const;

      /** @brief Total nominal number of steps over all stages. */
      unsigned int
      n_steps() const;

      /** @brief The state at pseudo-time @p time (clipped to the
       * program). */
      LoadState
      state(const double time) const;

      /** @brief The state at the start of the program (every channel
       * zero). */
      LoadState
      initial_state() const;
    };

    /**
     * @brief What the load program needs from a problem.
     */
    struct LoadStepCallbacks
    {
      /** Solve at the given state, starting from the last accepted one. */
      std::function<NewtonStatistics(const LoadState &state)> solve;
      /** Commit the state of a converged step. */
      std::function<void(const StepInfo &step, const NewtonStatistics &)>
        accept;
      /** Restore the last accepted state. */
      std::function<void()> reject;
    };

    /**
     * @brief Record of the accepted steps.
     */
    struct LoadSteppingStatistics
    {
      /** Pseudo-time of each accepted step. */
      std::vector<double> times;
      /** Newton iterations of each accepted step's successful attempt. */
      std::vector<unsigned int> newton_iterations;
      /** Newton iterations of the failed attempts (each followed by a
       * cutback) between the previous accepted step and each accepted
       * step; the same length as newton_iterations. */
      std::vector<unsigned int> failed_attempt_iterations;
      unsigned int              n_cutbacks = 0;
      /** Solves of first iterations beyond their first, over every
       * attempt (NewtonStatistics::n_extra_first_iteration_solves). */
      unsigned int n_extra_first_iteration_solves = 0;
      /** The same for later iterations
       * (NewtonStatistics::n_extra_later_iteration_solves). */
      unsigned int n_extra_later_iteration_solves = 0;
      /** Extra solves of both kinds of each accepted step, its failed
       * attempts included; the same length as newton_iterations. */
      std::vector<unsigned int> extra_solves;
      /** Stabilized solves (NewtonStatistics::n_stabilized_solves) of each
       * accepted step, its failed attempts included; the same length as
       * newton_iterations. */
      std::vector<unsigned int> stabilized_solves;
      /** Energy dissipated by the stabilization springs
       * (NewtonStatistics::stabilization_energy) in each accepted step's
       * solve, in the model's units (N mm, per mm of depth in plane
       * strain); the same length as newton_iterations. The states of
       * rejected attempts are discarded, and so is their energy. */
      std::vector<double> stabilization_energy;
      /** Most Newton iterations of one solve, over every attempt
       * (NewtonStatistics::max_iterations_per_solve). */
      unsigned int max_iterations_per_solve = 0;
      /** Accepted steps whose Newton iteration converged on the step test
       * (equilibrium residual at round-off above its tolerance). */
      unsigned int n_converged_on_step = 0;
    };

    /**
     * @brief Run every stage of the program. Throws with a one-line
     * message when the minimum increment fails.
     */
    LoadSteppingStatistics
    run_load_program(const LoadProgramParameters &program,
                     const LoadStepCallbacks     &callbacks,
                     IO::Console                 &console);
  } // namespace Solvers
} // namespace Common

#endif
