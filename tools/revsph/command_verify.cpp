#include "core/energy_log.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "tools/revsph/commands.hpp"
#include "verify/reversibility.hpp"

#include <cstdio>
#include <iostream>

namespace revsph::cli {

int verify_command(const VerifyCommandOptions& options) {
  apply_thread_count(options.case_options.threads);
  LoadedCase loaded = load_simulation(options.case_options);
  Simulation& simulation = *loaded.simulation;
  const std::int64_t steps = resolve_steps(loaded, options.steps, options.t_end, true);
  const SimulationInfo& info = simulation.info();
  std::cout << "revsph verify: " << info.case_name << " (" << info.model << ", " << info.dimension
            << "D, " << to_string(info.arithmetic) << "-point arithmetic), " << steps
            << " steps forward, time reversal, " << steps << " steps, time reversal; "
            << thread_count() << (thread_count() == 1 ? " thread\n" : " threads\n");

  if (options.check_substeps) {
    for (const SubstepCheck& check : check_substeps(simulation, info.dt)) {
      std::cout << "sub-step " << check.name << ": " << check.comparison.verdict() << "\n";
    }
  }

  EnergyLog energy(std::nullopt);
  ProgressReporter forward(stdout, "forward ", steps, info.dt, loaded.settings.progress_interval);
  ProgressReporter backward(stdout, "backward", 2 * steps, info.dt,
                            loaded.settings.progress_interval);
  VerifyOptions verify;
  verify.steps = steps;
  verify.forward_progress = &forward;
  verify.backward_progress = &backward;
  verify.energy_log = &energy;
  verify.energy_every = loaded.settings.energy_every;
  VerifyReport report;
  try {
    report = verify_reversibility(simulation, verify);
  } catch (const SimulationFault& fault) {
    print_error(std::string("the run stopped: ") + fault.what());
    return simulation_failed;
  }
  std::cout << "initial state hash:   " << report.initial_hash << "\n"
            << "turning-point hash:   " << report.turning_point_hash << "\n"
            << "returned state hash:  " << report.final_hash << "\n";
  std::printf("energy: max |E(t) - E(0)| / |E(0)| = %.3e over both halves\n",
              energy.max_relative_error());
  std::printf("wall time: %.2f s\n", report.wall_seconds);
  for (const std::string& line : report.comparison.details()) {
    std::cout << "  " << line << "\n";
  }
  std::cout << "verdict: " << report.comparison.verdict() << "\n";
  return report.identical() ? success : not_reversible;
}

} // namespace revsph::cli
