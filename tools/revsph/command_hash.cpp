#include "core/progress.hpp"
#include "core/run_loop.hpp"
#include "tools/revsph/commands.hpp"
#include "verify/state_hash.hpp"

#include <iostream>

namespace revsph::cli {

int hash_command(const HashOptions& options) {
  apply_thread_count(options.case_options.threads);
  LoadedCase loaded = load_simulation(options.case_options);
  Simulation& simulation = *loaded.simulation;
  const std::int64_t steps = resolve_steps(loaded, options.steps, options.t_end, true);
  // Progress on stderr: stdout carries only the hash, for scripts.
  ProgressReporter progress(stderr, "hash", steps, simulation.info().dt,
                            loaded.settings.progress_interval);
  RunHooks hooks;
  hooks.progress = steps > 0 ? &progress : nullptr;
  try {
    run_steps(simulation, steps, hooks);
  } catch (const SimulationFault& fault) {
    print_error(std::string("the run stopped: ") + fault.what());
    return simulation_failed;
  }
  std::cout << state_hash(simulation.capture_state()) << "\n";
  return success;
}

} // namespace revsph::cli
