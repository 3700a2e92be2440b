#include "core/distributed/processes.hpp"
#include "core/progress.hpp"
#include "core/run_loop.hpp"
#include "core/snapshot_file.hpp"
#include "tools/revsph/commands.hpp"
#include "verify/snapshot_check.hpp"
#include "verify/state_hash.hpp"

#include <iostream>

namespace revsph::cli {

int hash_command(const HashOptions& options) {
  CaseOptions case_options = options.case_options;
  const bool snapshot_given =
      is_hdf5_file(case_options.case_path) || case_options.case_path.ends_with(".h5");
  if (snapshot_given && !options.steps && !options.t_end) {
    // The hash of the snapshot itself (checked against the one recorded in it); every process
    // of a distributed launch reads it, the first prints it.
    const std::string hash = state_hash(read_checked_snapshot(case_options.case_path).state);
    if (distributed::process_rank() == 0) {
      std::cout << hash << "\n";
    }
    return success;
  }
  if (snapshot_given) {
    case_options.from_snapshot = case_options.case_path;
    case_options.case_given = false;
  } else if (!options.steps && !options.t_end) {
    print_error("hash of a case needs --steps N or --t-end T");
    return bad_input;
  }
  LoadedCase loaded = load_simulation(case_options);
  Simulation& simulation = *loaded.simulation;
  const std::int64_t steps = resolve_run_end(loaded, options.steps, options.t_end, true).steps;
  // Progress on stderr: stdout carries only the hash, for scripts.
  ProgressReporter progress(stderr, "hash", simulation.steps_taken() + steps, simulation.info().dt,
                            loaded.settings.progress_interval);
  RunHooks hooks;
  hooks.progress = steps > 0 && distributed::process_rank() == 0 ? &progress : nullptr;
  try {
    run_steps(simulation, steps, hooks);
  } catch (const SimulationFault& fault) {
    return stop_on_fault(fault);
  }
  // In a distributed run every process holds a piece; each gets the whole state's hash, process
  // 0 prints it.
  const std::string hash = state_hash(simulation.borrow_state());
  if (distributed::process_rank() == 0) {
    std::cout << hash << "\n";
  }
  return success;
}

} // namespace revsph::cli
