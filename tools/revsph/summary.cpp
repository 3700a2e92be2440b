#include "tools/revsph/summary.hpp"

#include "core/atomic_file.hpp"
#include "core/build_info.hpp"
#include "core/openmp_waiting.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace revsph::cli {

void write_summary(const std::filesystem::path& path, Simulation& simulation, const RunSummary& run,
                   const EnergyLog& energy) {
  const SimulationInfo& info = simulation.info();
  nlohmann::ordered_json summary;
  summary["case"] = info.case_name;
  summary["case_source"] = run.case_source;
  summary["overrides"] = run.overrides;
  if (run.from_snapshot) {
    summary["from_snapshot"] = *run.from_snapshot;
  }
  summary["start_step"] = run.start_step;
  summary["model"] = info.model;
  summary["dimension"] = info.dimension;
  summary["arithmetic"] = std::string(to_string(info.arithmetic));
  for (const ParticleCount& p : info.particles) {
    summary["particles"][p.particle_set] = p.count;
  }
  summary["dt"] = info.dt;
  for (const auto& [name, value] : info.setup_report) {
    summary["setup"][name] = value;
  }
  summary["steps_requested"] = run.steps_requested;
  // Absolute, as a continued run goes on to it (docs/restart.md).
  if (run.end.length.steps) {
    summary["run_end"]["step"] = *run.end.length.steps;
  }
  if (run.end.length.t_end) {
    summary["run_end"]["t_end"] = *run.end.length.t_end;
  }
  summary["run_end"]["from"] = run.end.origin;
  summary["steps"] = simulation.steps_taken() - run.start_step;
  summary["final_step"] = simulation.steps_taken();
  summary["time"] = simulation.time();
  summary["completed"] = !run.failure.has_value();
  if (run.failure) {
    summary["failure"] = *run.failure;
  }
  summary["healthy"] = run.healthy;
  summary["health_reasons"] = run.health_reasons;
  summary["wall_seconds"] = run.wall_seconds;
  const double particle_steps = static_cast<double>(info.moving_particle_count()) *
                                static_cast<double>(simulation.steps_taken() - run.start_step);
  summary["particle_steps_per_second"] =
      run.wall_seconds > 0 ? particle_steps / run.wall_seconds : 0.0;
  // The engine's throughput, for benchmarks: short runs of large problems would otherwise be
  // dominated by writing the first and last snapshots.
  summary["stepping_seconds"] = run.stepping_seconds;
  summary["stepping_particle_steps_per_second"] =
      run.stepping_seconds > 0 ? particle_steps / run.stepping_seconds : 0.0;
  summary["threads"] = run.threads;
  summary["processes"] = run.processes;
  if (const auto& d = run.distribution) {
    // docs/running.md, "Several processes".
    summary["distribution"] = {{"processes", d->processes},
                               {"threads_per_process", d->threads},
                               {"partition", "Zoltan RCB weighted by estimated work"},
                               {"stepping_seconds", d->stepping_seconds},
                               {"communication_seconds_min", d->communication_seconds_min},
                               {"communication_seconds_max", d->communication_seconds_max},
                               {"communication_seconds_mean", d->communication_seconds_mean},
                               {"bytes_sent_per_step", d->bytes_sent_per_step},
                               {"mpi_calls_per_step", d->calls_per_step},
                               {"mpi_exchanges_per_step", d->exchanges_per_step},
                               {"own_particles_min", d->own_particles_min},
                               {"own_particles_max", d->own_particles_max},
                               {"ghost_fraction", d->ghost_fraction},
                               {"estimated_work_imbalance", d->work_imbalance},
                               {"ghost_lists_made", d->ghost_lists_made},
                               {"rebalances", d->rebalances},
                               {"rebalances_by_measured_time", d->rebalances_by_measured_time}};
  }
  // How the threads waited at barriers (core/openmp_waiting.hpp: chosen from the machine's
  // load at start), which a benchmark's throughput depends on.
  summary["openmp_waiting"] = openmp_waiting_description();
  summary["peak_memory_bytes"] = run.peak_memory_bytes;
  summary["peak_memory_bytes_max_over_processes"] = run.peak_memory_bytes_max_over_processes;
  summary["initial_hash"] = run.initial_hash;
  summary["final_hash"] = run.final_hash;
  summary["snapshots_written"] = run.snapshots_written;
  if (run.last_snapshot) {
    summary["last_snapshot"] = *run.last_snapshot;
  }
  if (!energy.empty()) {
    summary["energy"]["initial_total"] = energy.initial_total();
    summary["energy"]["final_total"] = energy.last().total().value();
    summary["energy"]["max_relative_error"] = energy.max_relative_error();
    // docs/verify.md, "Two energy errors".
    summary["energy"]["mechanical_scale"] = energy.mechanical_scale();
    summary["energy"]["max_mechanical_relative_error"] = energy.max_mechanical_relative_error();
    for (const EnergyTerm& term : energy.last().terms) {
      summary["energy"]["final"][term.name] = term.value.value();
    }
    summary["units"]["energy"] = energy.last().terms.empty() ? "" : energy.last().terms[0].unit;
  }
  for (const EnergyTerm& minimum : run.diagnostics_minima) {
    summary["diagnostics"]["min_" + minimum.name] = minimum.value.value();
  }
  for (const EnergyTerm& maximum : run.diagnostics_maxima) {
    summary["diagnostics"]["max_" + maximum.name] = maximum.value.value();
    summary["units"][maximum.name] = maximum.unit;
  }
  summary["build"] = {{"version", build_info::version},
                      {"git_commit", build_info::git_commit},
                      {"compiler", build_info::compiler},
                      {"build_type", build_info::build_type},
                      {"flags", build_info::flags}};
  write_file_atomically(path, summary.dump(2) + "\n");
}

} // namespace revsph::cli
