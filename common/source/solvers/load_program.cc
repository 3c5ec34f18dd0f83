#include <common/solvers/load_program.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace Common
{
  namespace Solvers
  {
    using namespace dealii;

    namespace
    {
      std::string
      stage_subsection(const unsigned int s)
      {
        return "Stage " + std::to_string(s + 1);
      }
    } // namespace



    LoadChannel
    load_factor_channel()
    {
      return {"Load factor",
              "Fraction of the full load of the subsection 'Loading' at the "
              "end of the stage. Dimensionless."};
    }



    double
    LoadState::value(const std::string &channel) const
    {
      const auto it = values.find(channel);
      AssertThrow(it != values.end(),
                  ExcMessage("The load program has no channel '" + channel +
                             "'."));
      return it->second;
    }



    double
    LoadState::load_factor() const
    {
      return value(load_factor_channel().name);
    }



    LoadState
    LoadState::with_load_factor(const double load_factor)
    {
      LoadState state;
      state.time                               = load_factor;
      state.values[load_factor_channel().name] = load_factor;
      return state;
    }



    void
    LoadProgramParameters::declare_parameters(
      ParameterHandler                    &prm,
      const std::vector<LoadChannel>      &channels,
      const std::map<std::string, double> &default_end_values)
    {
      prm.enter_subsection("Load program");
      {
        prm.declare_entry("Number of stages",
                          "1",
                          Patterns::Integer(1, max_stages),
                          "Stages run one after the other; stage k covers "
                          "the pseudo-time interval [k - 1, k]. At most " +
                            std::to_string(max_stages) + ".");
        prm.declare_entry("Minimum increment",
                          "1e-4",
                          Patterns::Double(0.),
                          "Smallest step, as a fraction of a stage, that "
                          "cutbacks may reach before the run stops with an "
                          "error. Dimensionless, in (0, 1].");
        prm.enter_subsection("Largest step");
        for (const auto &channel : channels)
          prm.declare_entry(channel.name,
                            "0",
                            Patterns::Double(0.),
                            "Largest change of the channel in one step, in "
                            "the unit of its stage entry: a stage whose "
                            "steps change it by more divides each of its "
                            "steps into equal substeps that do not (a path "
                            "discretisation, as a step is; the console and "
                            "the results count the substeps as steps). 0: no "
                            "limit.");
        prm.leave_subsection();
        for (unsigned int s = 0; s < max_stages; ++s)
          {
            prm.enter_subsection(stage_subsection(s));
            prm.declare_entry("Name",
                              s == 0 ? "load" : "",
                              Patterns::Anything(),
                              "Name of the stage in the console report.");
            prm.declare_entry("Number of steps",
                              "1",
                              Patterns::Integer(1),
                              "Equal steps in pseudo-time over the stage.");
            for (const auto &channel : channels)
              {
                const auto it = default_end_values.find(channel.name);
                const bool has_default =
                  s == 0 && it != default_end_values.end();
                std::string text;
                if (has_default)
                  {
                    std::ostringstream value;
                    value << it->second;
                    text = value.str();
                  }
                prm.declare_entry(channel.name,
                                  text,
                                  Patterns::Anything(),
                                  channel.documentation +
                                    " Empty: the value at the start of the "
                                    "stage is held (every channel starts at "
                                    "0).");
              }
            prm.leave_subsection();
          }
      }
      prm.leave_subsection();
    }



    void
    LoadProgramParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load program");
      const unsigned int n_stages = prm.get_integer("Number of stages");
      min_increment               = prm.get_double("Minimum increment");
      AssertThrow(min_increment > 0. && min_increment <= 1.,
                  ExcMessage("Load program: 'Minimum increment' must lie in "
                             "(0, 1]."));
      largest_step.clear();
      prm.enter_subsection("Largest step");
      for (const auto &channel : channels)
        {
          const double value = prm.get_double(channel.name);
          if (value > 0.)
            largest_step[channel.name] = value;
        }
      prm.leave_subsection();
      stages.clear();
      std::map<std::string, double> current;
      for (const auto &channel : channels)
        current[channel.name] = 0.;
      for (unsigned int s = 0; s < max_stages; ++s)
        {
          prm.enter_subsection(stage_subsection(s));
          const std::string where =
            "Load program/" + stage_subsection(s) + ": ";
          if (s >= n_stages)
            {
              // A stage beyond the count must not carry settings that would
              // silently be ignored.
              bool set = prm.get("Name") != "" ||
                         prm.get_integer("Number of steps") != 1;
              for (const auto &channel : channels)
                set = set || prm.get(channel.name) != "";
              AssertThrow(!set,
                          ExcMessage(where +
                                     "this stage is set, but "
                                     "'Number of stages' is " +
                                     std::to_string(n_stages) + "."));
              prm.leave_subsection();
              continue;
            }
          Stage stage;
          stage.name    = prm.get("Name");
          stage.n_steps = prm.get_integer("Number of steps");
          for (const auto &channel : channels)
            {
              const std::string text = prm.get(channel.name);
              if (!text.empty())
                {
                  // Decimal notation only: strtod also reads hexadecimal
                  // ("0x10" is 16), which no one means in a load program.
                  char        *end   = nullptr;
                  const double value = std::strtod(text.c_str(), &end);
                  AssertThrow(end != text.c_str() && *end == '\0' &&
                                (value == 0. ||
                                 (std::abs(value) >= min_channel_value &&
                                  std::abs(value) <= max_channel_value)) &&
                                text.find_first_not_of("0123456789+-.eE") ==
                                  std::string::npos,
                              ExcMessage(where + "'" + channel.name +
                                         "' must be 0, a number of magnitude "
                                         "from 1e-9 to 1e9, or empty, not '" +
                                         text + "'."));
                  current[channel.name] = value;
                }
            }
          stage.end_values = current;
          stages.push_back(stage);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      // A program that never leaves zero loads nothing: every result
      // would be zero, and relative residuals undefined.
      bool loads = false;
      for (const auto &stage : stages)
        for (const auto &[name, value] : stage.end_values)
          loads = loads || value != 0.;
      // Checks the limits at once, not at the start of their stage.
      for (unsigned int s = 0; s < stages.size(); ++s)
        substeps_per_step(s);
      if (!loads && !channels.empty())
        {
          std::string names;
          for (unsigned int c = 0; c < channels.size(); ++c)
            names += (c == 0                   ? "'" :
                      c + 1 == channels.size() ? "' and '" :
                                                 "', '") +
                     channels[c].name;
          AssertThrow(false,
                      ExcMessage("Load program: " + names +
                                 (channels.size() == 1 ? "' is" : "' are") +
                                 " 0 in every stage: nothing loads the "
                                 "model."));
        }
    }



    unsigned int
    LoadProgramParameters::n_steps() const
    {
      unsigned int n = 0;
      for (const auto &stage : stages)
        n += stage.n_steps;
      return n;
    }



    unsigned int
    LoadProgramParameters::substeps_per_step(const unsigned int s) const
    {
      AssertIndexRange(s, stages.size());
      unsigned int n_substeps = 1;
      for (const auto &[name, largest] : largest_step)
        {
          const double start = s == 0 ? 0. : stages[s - 1].end_values.at(name);
          const double change =
            std::abs(stages[s].end_values.at(name) - start) / stages[s].n_steps;
          // A step exactly at the limit (up to round-off) is not divided.
          const double n = std::ceil(change / largest * (1. - 1e-12));
          AssertThrow(n * stages[s].n_steps <= max_steps_per_stage,
                      ExcMessage(
                        "Load program/Largest step: '" + name + "' = " +
                        IO::Console::format(largest) + " would divide stage " +
                        std::to_string(s + 1) + " into more than " +
                        std::to_string(max_steps_per_stage) + " steps."));
          n_substeps = std::max(n_substeps, static_cast<unsigned int>(n));
        }
      return n_substeps;
    }



    LoadState
    LoadProgramParameters::initial_state() const
    {
      LoadState state;
      for (const auto &channel : channels)
        state.values[channel.name] = 0.;
      return state;
    }



    LoadState
    LoadProgramParameters::state(const double time) const
    {
      LoadState state = initial_state();
      if (stages.empty())
        return state;
      const double       t = std::clamp(time, 0., 1. * stages.size());
      const unsigned int s =
        std::min<unsigned int>(static_cast<unsigned int>(std::floor(t)),
                               stages.size() - 1);
      const double fraction = t - s;
      state.time            = t;
      for (auto &[name, value] : state.values)
        {
          const double start = s == 0 ? 0. : stages[s - 1].end_values.at(name);
          const double end   = stages[s].end_values.at(name);
          // The end value exactly at the end of the stage (no round-off).
          value = fraction == 1. ? end : start + fraction * (end - start);
        }
      return state;
    }



    void
    LoadProgramParameters::check_load_magnitude(const std::string &entry,
                                                const double       value,
                                                const std::string &unit)
    {
      AssertThrow(std::abs(value) >= min_channel_value &&
                    std::abs(value) <= max_channel_value,
                  ExcMessage(entry + " must lie between 1e-9 and 1e9 " + unit +
                             ", got " + IO::Console::format(value) + "."));
    }



    LoadSteppingStatistics
    run_load_program(const LoadProgramParameters &program,
                     const LoadStepCallbacks     &callbacks,
                     IO::Console                 &console)
    {
      LoadSteppingStatistics statistics;
      unsigned int           step = 0;
      // Iterations of the failed attempts since the last accepted step.
      unsigned int failed_iterations = 0;
      // Extra active-set solves since the last accepted step.
      unsigned int extra_solves = 0;
      // Stabilized solves since the last accepted step.
      unsigned int stabilized_solves = 0;
      // A cutback since the last accepted step.
      bool cut_back = false;
      for (unsigned int s = 0; s < program.stages.size(); ++s)
        {
          const auto        &stage      = program.stages[s];
          const unsigned int n_substeps = program.substeps_per_step(s);
          const unsigned int n_steps    = stage.n_steps * n_substeps;
          const double       nominal    = 1. / n_steps;
          if (n_substeps > 1)
            console.stream()
              << "Stage " << s + 1 << (stage.name.empty() ? "" : " (")
              << stage.name << (stage.name.empty() ? "" : ")")
              << ": each step changes a channel by more than its 'Largest "
                 "step'; "
              << n_substeps << " substeps per step, " << n_steps << " in all"
              << std::endl;
          double increment = nominal;
          // Fraction of the stage reached.
          double       reached       = 0.;
          unsigned int step_in_stage = 0;
          while (reached < 1. - 1e-12)
            {
              const double target = std::min(1., reached + increment);
              // The end of a stage exactly at its end time.
              LoadState state =
                program.state(target == 1. ? s + 1. : s + target);
              state.after_cutback           = cut_back;
              const NewtonStatistics newton = callbacks.solve(state);
              statistics.n_extra_first_iteration_solves +=
                newton.n_extra_first_iteration_solves;
              statistics.n_extra_later_iteration_solves +=
                newton.n_extra_later_iteration_solves;
              extra_solves += newton.n_extra_first_iteration_solves +
                              newton.n_extra_later_iteration_solves;
              stabilized_solves += newton.n_stabilized_solves;
              statistics.max_iterations_per_solve =
                std::max(statistics.max_iterations_per_solve,
                         newton.max_iterations_per_solve);
              if (newton.converged)
                {
                  ++step;
                  ++step_in_stage;
                  reached = target;
                  statistics.times.push_back(state.time);
                  statistics.newton_iterations.push_back(newton.n_iterations);
                  statistics.failed_attempt_iterations.push_back(
                    failed_iterations);
                  failed_iterations = 0;
                  statistics.extra_solves.push_back(extra_solves);
                  extra_solves = 0;
                  statistics.stabilized_solves.push_back(stabilized_solves);
                  statistics.stabilization_energy.push_back(
                    newton.stabilization_energy);
                  stabilized_solves = 0;
                  cut_back          = false;
                  statistics.n_converged_on_step += newton.converged_on_step;
                  StepInfo info;
                  info.step             = step;
                  info.stage            = s;
                  info.stage_name       = stage.name;
                  info.n_stages         = program.stages.size();
                  info.step_in_stage    = step_in_stage;
                  info.n_steps_in_stage = n_steps;
                  info.state            = state;
                  callbacks.accept(info, newton);
                  // Return to the nominal increment once a reduced one
                  // worked.
                  increment = std::min(nominal, 2. * increment);
                }
              else
                {
                  callbacks.reject();
                  ++statistics.n_cutbacks;
                  cut_back = true;
                  failed_iterations += newton.n_iterations;
                  increment *= 0.5;
                  const std::string where =
                    "pseudo-time " + IO::Console::format(state.time) +
                    (program.stages.size() > 1 ?
                       " (stage " + std::to_string(s + 1) + ")" :
                       "");
                  AssertThrow(increment >= program.min_increment * (1 - 1e-12),
                              ExcMessage("Newton did not converge at " + where +
                                         " (" + newton.failure +
                                         ") and the minimum increment was "
                                         "reached."));
                  console.stream()
                    << "  Newton did not converge at " << where << " ("
                    << newton.failure << "); cutting the increment back to "
                    << IO::Console::format(increment) << " of the stage"
                    << std::endl;
                }
            }
        }
      return statistics;
    }
  } // namespace Solvers
} // namespace Common
