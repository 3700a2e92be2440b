#pragma once
// Advancing a simulation with energy output and progress: the loop behind `revsph run` and
// both halves of `revsph verify`.

#include "core/diagnostics_log.hpp"
#include "core/energy_log.hpp"
#include "core/progress.hpp"
#include "core/simulation.hpp"

#include <cstdint>
#include <functional>

namespace revsph {

struct RunHooks {
  EnergyLog* energy_log = nullptr; // records every `energy_every` steps (and at both ends)
  DiagnosticsLog* diagnostics_log = nullptr; // same cadence
  std::int64_t energy_every = 100;
  ProgressReporter* progress = nullptr;
  // Called after every step with the number of steps taken so far in this call.
  std::function<void(Simulation&, std::int64_t)> after_step;
  // What the progress line adds about the flow (max |v| / c, say), taken at each energy record
  // (collective in a distributed run, like the record).
  std::function<std::string(Simulation&)> flow_note;
};

// Takes `steps` steps. SimulationFault propagates to the caller.
void run_steps(Simulation& simulation, std::int64_t steps, const RunHooks& hooks);

} // namespace revsph
