#include "core/energy_log.hpp"
#include "core/progress.hpp"
#include "core/run_loop.hpp"
#include "core/threads.hpp"
#include "tools/revsph/commands.hpp"
#include "tools/revsph/summary.hpp"
#include "verify/state_hash.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>

namespace revsph::cli {

namespace {

std::string describe_particles(const SimulationInfo& info) {
  std::string text;
  for (const ParticleCount& p : info.particles) {
    text += (text.empty() ? "" : " + ") + std::to_string(p.count) + " " + p.particle_set;
  }
  return text + " particles";
}

} // namespace

int run_command(const RunOptions& options) {
  apply_thread_count(options.case_options.threads);
  LoadedCase loaded = load_simulation(options.case_options);
  Simulation& simulation = *loaded.simulation;
  const std::int64_t steps = resolve_steps(loaded, options.steps, options.t_end, false);
  const std::filesystem::path out = options.out_dir.empty()
                                        ? std::filesystem::path("out") / loaded.settings.name
                                        : std::filesystem::path(options.out_dir);
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out)) {
    throw CaseError(loaded.case_file.source_name(), "--out",
                    out.string() + " exists and is not a directory");
  }
  if (std::filesystem::exists(out) && !std::filesystem::is_empty(out) && !options.force) {
    throw CaseError(loaded.case_file.source_name(), "--out",
                    "the output directory " + out.string() +
                        " exists and is not empty; choose another with --out or overwrite it "
                        "with --force");
  }
  std::filesystem::create_directories(out);

  const SimulationInfo& info = simulation.info();
  std::cout << "revsph run: " << info.case_name << " (" << info.model << ", " << info.dimension
            << "D, " << to_string(info.arithmetic) << "-point arithmetic), "
            << describe_particles(info) << ", dt = " << info.dt << " s, " << steps << " steps, "
            << thread_count() << (thread_count() == 1 ? " thread\n" : " threads\n");

  EnergyLog energy((out / "energy.csv").string());
  ProgressReporter progress(stdout, "run", simulation.steps_taken() + steps, info.dt,
                            loaded.settings.progress_interval);
  RunHooks hooks;
  hooks.energy_log = &energy;
  hooks.energy_every = loaded.settings.energy_every;
  hooks.progress = &progress;

  RunSummary summary;
  summary.case_source = loaded.case_file.source_name();
  summary.overrides = loaded.case_file.overrides();
  summary.steps_requested = steps;
  summary.threads = thread_count();
  summary.initial_hash = state_hash(simulation.capture_state());
  const auto start = std::chrono::steady_clock::now();
  int status = success;
  try {
    run_steps(simulation, steps, hooks);
  } catch (const SimulationFault& fault) {
    progress.finish(simulation.steps_taken());
    summary.failure = fault.what();
    print_error(std::string("the run stopped: ") + fault.what());
    status = simulation_failed;
  }
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.final_hash = state_hash(simulation.capture_state());
  write_summary(out / "summary.json", simulation, summary, energy);

  std::printf("energy: max |E(t) - E(0)| / |E(0)| = %.3e over %lld steps\n",
              energy.max_relative_error(), static_cast<long long>(simulation.steps_taken()));
  std::printf("speed: %.3g particle-steps/s (%.2f s wall)\n",
              summary.wall_seconds > 0
                  ? static_cast<double>(info.moving_particle_count()) *
                        static_cast<double>(simulation.steps_taken()) / summary.wall_seconds
                  : 0.0,
              summary.wall_seconds);
  std::cout << "state hash: " << summary.final_hash << "\n";
  std::cout << "wrote " << (out / "energy.csv").string() << " and "
            << (out / "summary.json").string() << "\n";
  return status;
}

} // namespace revsph::cli
