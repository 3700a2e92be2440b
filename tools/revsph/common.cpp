#include "tools/revsph/common.hpp"

#include "core/distributed/index_order_stream.hpp"
#include "core/distributed/processes.hpp"

#include "core/threads.hpp"
#include "verify/snapshot_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string_view>

namespace revsph::cli {

namespace {

void apply_overrides(CaseFile& case_file, const std::vector<std::string>& overrides) {
  for (const std::string& assignment : overrides) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw CaseError(case_file.source_name(), assignment,
                      "--set expects key=value, e.g. --set discretisation.dr=0.01");
    }
    case_file.set(assignment.substr(0, equals), assignment.substr(equals + 1));
  }
}

LoadedCase build(CaseFile case_file, Arithmetic arithmetic) {
  SimulationOptions simulation_options;
  simulation_options.arithmetic = arithmetic;
  RunSettings settings = read_run_settings(case_file);
  std::unique_ptr<Simulation> simulation;
  try {
    simulation = create_simulation(case_file, simulation_options);
  } catch (const ArithmeticRefused& refusal) {
    // A model without a float variant (its registration says so) refuses --arithmetic float.
    throw CaseError(case_file.source_name(), "--arithmetic", refusal.what());
  }
  case_file.require_no_unknown_keys();
  return {std::move(case_file), std::move(settings), std::move(simulation), std::nullopt};
}

LoadedCase load_from_snapshot(const CaseOptions& options) {
  Snapshot snapshot = read_checked_snapshot(options.from_snapshot);
  const SnapshotMetadata& metadata = snapshot.metadata;
  if (options.arithmetic_given &&
      options.arithmetic != std::string(to_string(metadata.arithmetic))) {
    throw SnapshotError(options.from_snapshot + ": the snapshot holds " +
                        std::string(to_string(metadata.arithmetic)) +
                        "-point state; --arithmetic " + options.arithmetic + " cannot continue it");
  }
  CaseFile case_file = CaseFile::parse(metadata.case_text, metadata.case_source);
  // Its input files as the snapshot keeps them: none is read from disk again (older snapshots
  // keep none, and their case reads them where it names them).
  for (const InputFile& input : metadata.inputs) {
    case_file.inputs().give(input);
  }
  apply_overrides(case_file, metadata.overrides);
  apply_overrides(case_file, options.overrides);
  LoadedCase loaded = build(std::move(case_file), metadata.arithmetic);
  if (loaded.simulation->info().model != metadata.model) {
    throw SnapshotError(options.from_snapshot + ": written by model " + metadata.model +
                        ", but its case builds model " + loaded.simulation->info().model);
  }
  try {
    loaded.simulation->restore_state(snapshot.state);
    loaded.simulation->restore_energy_accounts(metadata.energy_accounts);
  } catch (const std::invalid_argument& mismatch) {
    throw SnapshotError(options.from_snapshot +
                        ": does not fit the model its case describes: " + mismatch.what());
  }
  loaded.simulation->continue_from(metadata.step, metadata.time);
  if (metadata.energy_accounts.empty() && !loaded.simulation->energy_accounts().empty() &&
      snapshot.metadata.reference_energy) {
    // Written before snapshots kept the energy exchanged with the outside: the budget can only
    // start again here.
    std::cout << "note: " << options.from_snapshot
              << " carries no energy accounts; the energy error is measured from its state\n";
    snapshot.metadata.reference_energy.reset();
  }
  loaded.from_snapshot = std::move(snapshot);
  return loaded;
}

} // namespace

LoadedCase load_simulation(const CaseOptions& options) {
  apply_thread_count(options.threads); // the set-up's own loops run on them too
  if (!options.from_snapshot.empty()) {
    if (options.case_given) {
      throw CaseError(options.case_path, "--from",
                      "give either a case or --from SNAPSHOT (a snapshot carries its case)");
    }
    return load_from_snapshot(options);
  }
  if (is_hdf5_file(options.case_path) || options.case_path.ends_with(".h5")) {
    throw CaseError(options.case_path, "",
                    "this is a snapshot: use --from " + options.case_path + " to continue it");
  }
  CaseFile case_file = load_case(options.case_path);
  apply_overrides(case_file, options.overrides);
  if (options.arithmetic != "fixed" && options.arithmetic != "float") {
    throw CaseError(case_file.source_name(), "--arithmetic",
                    "expected fixed or float, got " + options.arithmetic);
  }
  return build(std::move(case_file),
               options.arithmetic == "fixed" ? Arithmetic::fixed : Arithmetic::floating);
}

namespace {

// The value of `key` given with --set (the last), if any.
std::optional<std::string> overridden(const std::vector<std::string>& overrides,
                                      std::string_view key) {
  std::optional<std::string> value;
  for (const std::string& assignment : overrides) {
    if (assignment.starts_with(key) && assignment.size() > key.size() &&
        assignment[key.size()] == '=') {
      value = assignment.substr(key.size() + 1);
    }
  }
  return value;
}

// The end the case's [run] gives, with what said so.
RunEnd case_end(const LoadedCase& loaded, std::string& key) {
  RunEnd end;
  end.length = loaded.settings.length;
  key = end.length.steps ? "run.steps" : "run.t_end";
  const std::optional<std::string> given = overridden(loaded.case_file.overrides(), key);
  end.origin = given ? "--set " + key + "=" + *given : "[run] " + key.substr(4) + " of the case";
  return end;
}

// The end the snapshot continued from keeps, unless the continuing command sets the run's length
// (--set run.steps / run.t_end): then the case's.
std::optional<RunEnd> snapshot_end(const LoadedCase& loaded) {
  if (!loaded.from_snapshot) {
    return std::nullopt;
  }
  const SnapshotMetadata& from = loaded.from_snapshot->metadata;
  const std::vector<std::string>& all = loaded.case_file.overrides();
  const std::vector<std::string> added(
      all.begin() + static_cast<std::ptrdiff_t>(std::min(from.overrides.size(), all.size())),
      all.end());
  if ((!from.run_end_step && !from.run_end_time) || overridden(added, "run.steps") ||
      overridden(added, "run.t_end")) {
    return std::nullopt;
  }
  RunEnd end;
  end.length.steps = from.run_end_step;
  end.length.t_end = from.run_end_time;
  end.origin = from.run_end_origin;
  return end;
}

} // namespace

RunEnd resolve_run_end(const LoadedCase& loaded, std::optional<std::int64_t> steps,
                       std::optional<double> t_end, bool required_on_command_line) {
  const std::string& source = loaded.case_file.source_name();
  const Simulation& simulation = *loaded.simulation;
  const std::int64_t now = simulation.steps_taken();
  RunEnd end;
  if (steps) {
    if (*steps < 0) {
      throw CaseError(source, "--steps", "must be >= 0");
    }
    end.length.steps = now + *steps;
    end.origin = "--steps " + std::to_string(*steps) + " given at step " + std::to_string(now);
    end.steps = *steps;
    return end;
  }
  std::string key;
  if (t_end) {
    if (!(*t_end > 0.0)) {
      throw CaseError(source, "--t-end", "must be > 0");
    }
    end.length.t_end = t_end;
    end.origin = "--t-end " + format_number(*t_end);
    key = "--t-end";
  } else if (!required_on_command_line) {
    if (const std::optional<RunEnd> kept = snapshot_end(loaded)) {
      end = *kept;
      key = "--from";
    } else {
      end = case_end(loaded, key);
    }
  }
  if (!end.length.given()) {
    throw CaseError(source, "run",
                    required_on_command_line
                        ? "give the number of steps with --steps N or --t-end T"
                        : "no run length: give --steps N or --t-end T, or [run] steps / t_end");
  }
  const double dt = simulation.info().dt;
  if (t_end && *t_end < dt) {
    char reason[160];
    std::snprintf(
        reason, sizeof reason,
        "shorter than one time step (%.6g s < dt = %.6g s): give a later end or --steps N", *t_end,
        dt);
    throw CaseError(source, "--t-end", reason);
  }
  RunLength in_steps = end.length;
  if (in_steps.t_end) {
    // Continued at another dt than its snapshot's, the run's clock is offset from steps * dt
    // (Simulation::time_at); 0 otherwise, exactly.
    *in_steps.t_end -= simulation.time() - static_cast<double>(now) * dt;
  }
  end.steps = in_steps.steps_for(dt) - now;
  if (end.steps < 0) {
    throw CaseError(source, key,
                    "the run is already at step " + std::to_string(now) +
                        " (t = " + std::to_string(simulation.time()) + " s), past the run's end, " +
                        end.description());
  }
  return end;
}

void apply_thread_count(int threads) {
  if (threads > 0) {
    set_thread_count(threads);
  }
}

int stop_every_process(const std::string& message, int status) {
  if (distributed::process_count() > 1) {
    // One write of the whole line: several processes may fail in the same step.
    const std::string line = "revsph: error: " + message + "\n";
    std::fwrite(line.data(), 1, line.size(), stderr);
    std::fflush(stderr);
    distributed::end_every_process(status);
  }
  print_error(message);
  return status;
}

int stop_on_fault(const SimulationFault& fault) {
  const std::string message = std::string("the run stopped: ") + fault.what();
  if (fault.shared()) {
    if (distributed::process_rank() == 0) {
      print_error(message);
    }
    return simulation_failed;
  }
  return stop_every_process(message, simulation_failed);
}

std::optional<std::string> file_of_first_process(const std::filesystem::path& path) {
  if (distributed::process_rank() != 0) {
    return std::nullopt;
  }
  return path.string();
}

void check_on_first_process(const std::function<void()>& check) {
  constexpr char separator = '\0';
  std::string refusal;
  if (distributed::process_rank() == 0) {
    try {
      check();
    } catch (const CaseError& error) {
      refusal = error.file() + separator + error.key() + separator + error.reason();
    }
  }
  if (distributed::process_count() > 1) {
    refusal = distributed::broadcast_from_first(refusal);
  }
  if (refusal.empty()) {
    return;
  }
  const std::size_t first = refusal.find(separator);
  const std::size_t second = refusal.find(separator, first + 1);
  throw CaseError(refusal.substr(0, first), refusal.substr(first + 1, second - first - 1),
                  refusal.substr(second + 1));
}

void print_error(const std::string& message) {
  // Every process of a distributed run meets the same error (the same input, the same state):
  // one line, from the first.
  if (distributed::process_rank() == 0) {
    std::cerr << "revsph: error: " << message << "\n";
  }
}

void print_setup_report(const SimulationInfo& info) {
  for (const auto& [name, value] : info.setup_report) {
    std::cout << "setup: " << name << " = " << value << "\n";
  }
}

} // namespace revsph::cli
