#pragma once
// Advancing a simulation with energy output and progress: the loop behind `revsph run` and
// both halves of `revsph verify`.

#include "core/diagnostics_log.hpp"
#include "core/energy_log.hpp"
#include "core/progress.hpp"
#include "core/simulation.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

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
  // Columns of the run's own after the model's diagnostics in each diagnostics.csv row (the
  // moving particles inside walls, say), taken at each energy record (collective too). The same
  // columns every record: a file's header is its first row's.
  std::function<std::vector<EnergyTerm>(Simulation&)> extra_diagnostics;
};

// The row of diagnostics.csv now: the model's diagnostics, then the hooks' extra ones.
std::vector<EnergyTerm> diagnostics_row(Simulation& simulation, const RunHooks& hooks);

// Takes `steps` steps. SimulationFault propagates to the caller.
void run_steps(Simulation& simulation, std::int64_t steps, const RunHooks& hooks);

} // namespace revsph
