#include "core/close_pairs.hpp"
#include "core/diagnostics_log.hpp"
#include "core/distributed/processes.hpp"
#include "core/energy_log.hpp"
#include "core/logged_rows.hpp"
#include "core/memory.hpp"
#include "core/openmp_waiting.hpp"
#include "core/progress.hpp"
#include "core/run_health.hpp"
#include "core/run_loop.hpp"
#include "core/threads.hpp"
#include "tools/revsph/commands.hpp"
#include "tools/revsph/interruption.hpp"
#include "tools/revsph/particle_checks.hpp"
#include "tools/revsph/run_output.hpp"
#include "tools/revsph/state_speeds.hpp"
#include "tools/revsph/summary.hpp"
#include "verify/state_hash.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace revsph::cli {

namespace {

std::string describe_particles(const SimulationInfo& info) {
  std::string text;
  for (const ParticleCount& p : info.particles) {
    text += (text.empty() ? "" : " + ") + std::to_string(p.count) + " " + p.particle_set;
  }
  return text + " particles";
}

void print_header(const LoadedCase& loaded, std::int64_t steps) {
  const Simulation& simulation = *loaded.simulation;
  const SimulationInfo& info = simulation.info();
  std::cout << "revsph run: " << info.case_name << " (" << info.model << ", " << info.dimension
            << "D, " << to_string(info.arithmetic) << "-point arithmetic), "
            << describe_particles(info) << ", dt = " << info.dt << " s, " << steps << " steps";
  if (loaded.from_snapshot) {
    std::cout << " from step " << simulation.steps_taken() << " (t = " << simulation.time()
              << " s)";
  }
  std::cout << ", " << thread_count() << (thread_count() == 1 ? " thread" : " threads")
            << " (OpenMP " << openmp_waiting_description() << ")\n";
  print_setup_report(info);
  for (const std::string& term : info.irreversible_terms) {
    std::cout << "note: irreversible term: " << term << "\n";
  }
}

} // namespace

int run_command(const RunOptions& options) {
  if (!options.out_dir.empty()) {
    // A bad --out is bad input: said before the set-up, which may take long.
    const CaseOptions& given = options.case_options;
    check_on_first_process([&] {
      RunOutput::check_creatable(
          options.out_dir, given.from_snapshot.empty() ? given.case_path : given.from_snapshot);
    });
  }
  LoadedCase loaded = load_simulation(options.case_options);
  Simulation& simulation = *loaded.simulation;
  const RunEnd end = resolve_run_end(loaded, options.steps, options.t_end, false);
  const std::int64_t steps = end.steps;
  // A run from a snapshot of a run folder continues that run (docs/restart.md): in its folder
  // unless --out names another, with the rows of its logs up to the snapshot either way.
  std::optional<std::filesystem::path> source_folder;
  if (loaded.from_snapshot) {
    source_folder = run_folder_of(options.case_options.from_snapshot);
  }
  const std::filesystem::path directory =
      !options.out_dir.empty() ? std::filesystem::path(options.out_dir)
      : source_folder          ? *source_folder
                               : std::filesystem::path("out") / loaded.settings.name;
  std::error_code same_error;
  const bool continues_in_place =
      source_folder && std::filesystem::equivalent(directory, *source_folder, same_error);
  // Every check is done before the first file is written.
  check_on_first_process([&] {
    if (continues_in_place) {
      RunOutput::check_later_snapshots(directory, simulation.steps_taken(), options.force,
                                       options.case_options.from_snapshot);
    } else {
      RunOutput::check_directory(directory, options.force, loaded.case_file.source_name());
    }
  });
  std::optional<LoggedRows> earlier_energy;
  std::optional<LoggedRows> earlier_diagnostics;
  if (source_folder) {
    const std::int64_t step = simulation.steps_taken();
    const std::int64_t every = loaded.settings.energy_every;
    // Rows of a run killed before its first one: none to keep.
    const auto kept = [&](const char* name) -> std::optional<LoggedRows> {
      const std::filesystem::path path = *source_folder / name;
      if (!std::filesystem::is_regular_file(path)) {
        return std::nullopt;
      }
      LoggedRows rows = rows_before(read_logged_rows(path), step, every);
      return rows.rows.empty() ? std::nullopt : std::optional<LoggedRows>(std::move(rows));
    };
    earlier_energy = kept("energy.csv");
    earlier_diagnostics = kept("diagnostics.csv");
  }

  print_header(loaded, steps);
  // A restarted run measures energy against the original run's E(0); a new run's E(0) is its
  // first energy record.
  const std::optional<double> reference_energy =
      loaded.from_snapshot ? loaded.from_snapshot->metadata.reference_energy : std::nullopt;
  RunOutput output(directory, run_metadata(simulation, loaded.case_file, reference_energy, end),
                   loaded.settings.snapshot_every, loaded.settings.snapshot_interval);
  if (continues_in_place) {
    output.continue_run(simulation);
    std::cout << "continuing " << directory.string() << " from step " << simulation.steps_taken();
    if (output.removed_later_snapshots() > 0) {
      std::cout << " (its " << output.removed_later_snapshots()
                << " later snapshots removed: this run replaces them)";
    }
    std::cout << "\n";
  }
  const std::filesystem::path diagnostics_csv = output.directory() / "diagnostics.csv";
  if (distributed::process_rank() == 0) {
    // The rows kept, before this run appends its own (the same file when continuing in place).
    if (earlier_energy) {
      write_logged_rows(output.energy_csv(), *earlier_energy);
    }
    if (earlier_diagnostics) {
      write_logged_rows(diagnostics_csv, *earlier_diagnostics);
    } else if (continues_in_place) {
      std::filesystem::remove(diagnostics_csv);
    }
  }
  EnergyLog energy =
      earlier_energy
          ? EnergyLog(file_of_first_process(output.energy_csv()), reference_energy, *earlier_energy)
          : EnergyLog(file_of_first_process(output.energy_csv()), reference_energy);
  DiagnosticsLog diagnostics =
      earlier_diagnostics
          ? DiagnosticsLog(file_of_first_process(diagnostics_csv), *earlier_diagnostics)
          : DiagnosticsLog(file_of_first_process(diagnostics_csv));
  ProgressReporter progress(stdout, "run", simulation.steps_taken() + steps, simulation.info().dt,
                            loaded.settings.progress_interval);
  progress.set_time_at_step_zero(simulation.time_at(0));

  RunSummary summary;
  summary.case_source = loaded.case_file.source_name();
  summary.overrides = loaded.case_file.overrides();
  if (loaded.from_snapshot) {
    // Absolute: a reader of the run folder finds it from anywhere (tools/python/revsph).
    summary.from_snapshot = std::filesystem::absolute(options.case_options.from_snapshot).string();
  }
  summary.start_step = simulation.steps_taken();
  summary.steps_requested = steps;
  summary.end = end;
  summary.threads = thread_count();
  summary.processes = distributed::process_count();
  summary.initial_hash = state_hash(simulation.borrow_state());

  RunHooks hooks;
  hooks.energy_log = &energy;
  hooks.diagnostics_log = &diagnostics;
  hooks.energy_every = loaded.settings.energy_every;
  hooks.progress = &progress;
  std::vector<std::string> moving_sets;
  for (const ParticleCount& set : simulation.info().particles) {
    if (set.moving && set.count > 0) {
      moving_sets.push_back(set.particle_set);
    }
  }
  const ParticleChecks checks(loaded.case_file, simulation.info());
  hooks.flow_note = [&](Simulation& s) {
    const StateSnapshot state = s.borrow_state();
    const double largest = distributed::max_over_processes(largest_own_speed(state, moving_sets));
    const double closest = checks.smallest_distance_over_dr(state);
    char note[96];
    const double c = s.info().sound_speed;
    const int length = c > 0.0 ? std::snprintf(note, sizeof note, "max|v|/c = %.3g", largest / c)
                               : std::snprintf(note, sizeof note, "max|v| = %.3g m/s", largest);
    if (std::isfinite(closest) && length > 0) {
      std::snprintf(note + length, sizeof note - static_cast<std::size_t>(length),
                    "  min r/dr = %.2g", closest);
    }
    return std::string(note);
  };
  // Moving particles that passed into a wall: a column of diagnostics.csv and a warning each time
  // their number exceeds the largest so far (in a continued run, the largest of the rows kept).
  std::uint64_t most_in_walls = 0;
  for (const EnergyTerm& maximum : diagnostics.maxima()) {
    if (maximum.name == particles_in_walls) {
      most_in_walls = static_cast<std::uint64_t>(std::max(0.0, maximum.value.value()));
    }
  }
  if (checks.has_wall_regions()) {
    hooks.extra_diagnostics = [&](Simulation& s) {
      const WallCount count = checks.count_in_walls(s.borrow_state());
      if (count.total > most_in_walls) {
        most_in_walls = count.total;
        if (distributed::process_rank() == 0) {
          progress.announce(checks.wall_warning(s.steps_taken(), s.time(), count));
        }
      }
      // An exact sum over the processes (count_in_walls): the run's number on every process.
      return std::vector<EnergyTerm>{
          {particles_in_walls, RunTotal::same_on_every_process(static_cast<double>(count.total)),
           "1"}};
    };
  }
  // The health checks (core/run_health.hpp) at each record: a warning line when one is first
  // crossed, columns of diagnostics.csv (before the walls' one), summary.json's healthy.
  const HealthLimits limits = read_health_limits(loaded.case_file);
  RunHealth health(limits);
  if (earlier_energy || earlier_diagnostics) {
    health.replay(earlier_energy.value_or(LoggedRows{}),
                  earlier_diagnostics.value_or(LoggedRows{}));
  }
  const ClosePairCount close_pairs(loaded.case_file, simulation.info(), limits.close_pair_fraction);
  const ClosePairCount merged_pairs(loaded.case_file, simulation.info(),
                                    limits.merged_pair_fraction);
  hooks.extra_diagnostics = [&, walls = std::move(hooks.extra_diagnostics)](Simulation& s) {
    std::vector<EnergyTerm> columns;
    HealthReading reading;
    // relative_error is 0 / 0 while E(0) and every term are 0 (a driven flow still at rest).
    const double error = energy.last_relative_error();
    reading.energy_error = std::isnan(error) && energy.max_deviation() == 0.0 ? 0.0 : error;
    const StateSnapshot state = s.borrow_state();
    const double c = s.info().sound_speed;
    if (c > 0.0) {
      reading.speed_over_c =
          distributed::max_over_processes(largest_own_speed(state, moving_sets)) / c;
      columns.push_back(
          {speed_over_c_column, RunTotal::same_on_every_process(*reading.speed_over_c), "1"});
    }
    if (close_pairs.active()) {
      reading.close_pairs = close_pairs.count(state);
      columns.push_back({close_pairs_column,
                         RunTotal::same_on_every_process(static_cast<double>(*reading.close_pairs)),
                         "1"});
    }
    if (merged_pairs.active()) {
      reading.merged_pairs = merged_pairs.count(state);
      columns.push_back(
          {merged_pairs_column,
           RunTotal::same_on_every_process(static_cast<double>(*reading.merged_pairs)), "1"});
    }
    for (const std::string& warning : health.observe(s.steps_taken(), s.time(), reading)) {
      if (distributed::process_rank() == 0) {
        progress.announce(warning);
      }
    }
    if (walls) {
      const std::vector<EnergyTerm> in_walls = walls(s);
      columns.insert(columns.end(), in_walls.begin(), in_walls.end());
    }
    return columns;
  };
  const StopOnSignals signals;
  hooks.after_step = [&](Simulation& s, std::int64_t) {
    if (output.snapshot_due(s, s.steps_taken())) {
      output.write_snapshot(s);
      if (distributed::process_rank() == 0 && output.last_snapshot()) {
        char line[64];
        std::snprintf(line, sizeof line,
                      "step %lld, t = %.6g s: ", static_cast<long long>(s.steps_taken()), s.time());
        progress.announce(std::string(line) + "snapshot " + output.last_snapshot()->string());
      }
    }
    signals.stop_if_signalled();
  };
  const auto start = std::chrono::steady_clock::now();
  // Until a fault, if one stops the run: summary.json's stepping time and speed then cover the
  // steps taken.
  std::optional<std::chrono::steady_clock::time_point> stepping_start;
  const auto stepped_seconds = [&stepping_start] {
    return stepping_start
               ? std::chrono::duration<double>(std::chrono::steady_clock::now() - *stepping_start)
                     .count()
               : 0.0;
  };
  int status = success;
  try {
    if (!reference_energy) {
      output.set_reference_energy(simulation.energy().total());
    }
    output.write_snapshot(simulation);
    stepping_start = std::chrono::steady_clock::now();
    const distributed::CommunicationTally tally_before = distributed::communication_tally();
    run_steps(simulation, steps, hooks);
    summary.stepping_seconds = stepped_seconds();
    summary.distribution = summarise_distribution(
        simulation, distributed::communication_tally() - tally_before, summary.stepping_seconds,
        simulation.steps_taken() - summary.start_step, summary.threads);
    output.write_snapshot(simulation);
  } catch (const SimulationFault& fault) {
    // The state is left half-updated by the failed step: no snapshot of it; the last one
    // written stays the last good state. (Faults carry their step: ModelSimulation.)
    // In a distributed run a fault met by one process alone (not shared) may leave the others
    // waiting for it in an exchange: it ends them all (docs/design/distributed.md). A shared
    // one, the same on every process, ends the run as on one process, with summary.json.
    if (distributed::process_count() > 1 && !fault.shared()) {
      return stop_on_fault(fault);
    }
    summary.stepping_seconds = stepped_seconds();
    progress.finish(simulation.steps_taken());
    summary.failure = fault.what();
    if (distributed::process_rank() == 0) {
      print_error(std::string("the run stopped: ") + fault.what());
    }
    status = simulation_failed;
  } catch (const RunInterrupted& interruption) {
    // The step under way finished: its state is whole, and the last snapshot (docs/restart.md).
    summary.stepping_seconds = stepped_seconds();
    progress.finish(simulation.steps_taken());
    summary.failure = std::string(interruption.what()) + " after step " +
                      std::to_string(simulation.steps_taken());
    try {
      // The rows of this last step, as at the end of any run (the signal came before them).
      energy.record(simulation.steps_taken(), simulation.time(), simulation.energy());
      diagnostics.record(simulation.steps_taken(), simulation.time(),
                         diagnostics_row(simulation, hooks));
      output.write_snapshot(simulation);
    } catch (const SnapshotError& error) {
      summary.failure = *summary.failure + "; its last snapshot failed: " + error.what();
    }
    print_error("the run stopped: " + *summary.failure + " (continue it with run --from " +
                (output.last_snapshot() ? output.last_snapshot()->string() : "") + ")");
    status = interruption.exit_status();
  } catch (const SnapshotError& error) {
    summary.failure = error.what();
    print_error(error.what());
    status = simulation_failed;
  }
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.final_hash = state_hash(simulation.borrow_state());
  summary.snapshots_written = output.snapshot_count();
  if (const auto last = output.last_snapshot()) {
    summary.last_snapshot = last->string();
  }
  summary.healthy = health.healthy();
  summary.health_reasons = health.reasons();
  summary.diagnostics_maxima = diagnostics.maxima();
  summary.diagnostics_minima = diagnostics.minima();
  summary.peak_memory_bytes = peak_resident_bytes();
  summary.peak_memory_bytes_max_over_processes = static_cast<std::size_t>(
      distributed::max_over_processes(static_cast<double>(summary.peak_memory_bytes)));
  if (distributed::process_rank() == 0) {
    write_summary(output.summary_json(), simulation, summary, energy);
  }

  const double steps_done = static_cast<double>(simulation.steps_taken() - summary.start_step);
  std::printf("energy: max |E(t) - E(0)| / max(|E(0)|, |terms|) = %.3e\n",
              energy.max_relative_error());
  std::printf("energy: max |E(t) - E(0)| / energy moved = %.3e (energy moved %.6e)\n",
              energy.max_mechanical_relative_error(), energy.mechanical_scale());
  std::printf("speed: %.3g particle-steps/s (%.2f s wall)\n",
              summary.wall_seconds > 0
                  ? static_cast<double>(simulation.info().moving_particle_count()) * steps_done /
                        summary.wall_seconds
                  : 0.0,
              summary.wall_seconds);
  for (std::size_t i = 0; i < diagnostics.maxima().size(); ++i) {
    const EnergyTerm& maximum = diagnostics.maxima()[i];
    std::printf("%s: min %.6g, max %.6g %s\n", maximum.name.c_str(),
                diagnostics.minima()[i].value.value(), maximum.value.value(), maximum.unit.c_str());
  }
  if (summary.distribution && summary.processes > 1) {
    std::cout << distribution_line(*summary.distribution) << "\n";
  }
  for (const std::string& reason : summary.health_reasons) {
    std::cout << "unhealthy: " << reason << "\n";
  }
  std::cout << "state hash: " << summary.final_hash << "\n";
  std::cout << "wrote " << output.directory().string() << "/: energy.csv, summary.json, run.xdmf, "
            << output.snapshot_count() << " snapshots";
  if (summary.last_snapshot) {
    std::cout << " (last: " << *summary.last_snapshot << ")";
  }
  std::cout << "\n";
  if (options.strict && !summary.healthy && status == success) {
    print_error("the run is unhealthy (--strict): " + summary.health_reasons.front());
    status = simulation_failed;
  }
  return status;
}

} // namespace revsph::cli
