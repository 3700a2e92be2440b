#pragma once
// What the revsph subcommands share: loading a case (or a snapshot) with overrides, exit codes,
// error output.

#include "core/case_file.hpp"
#include "core/fault.hpp"
#include "core/model_registry.hpp"
#include "core/run_settings.hpp"
#include "core/simulation.hpp"
#include "core/snapshot_file.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace revsph::cli {

// Exit statuses of every subcommand.
enum ExitStatus : int {
  success = 0,
  not_reversible = 1, // verify: the state did not return bit for bit; diff: the states differ
  bad_input = 2,      // command line, case file or snapshot file
  simulation_failed = 3,
};

// Options every simulating subcommand takes.
struct CaseOptions {
  std::string case_path = "dambreak-small";
  bool case_given = false;            // CASE was on the command line (not the default)
  std::string from_snapshot;          // --from: start from this snapshot (its own case) instead
  std::vector<std::string> overrides; // --set key=value
  std::string arithmetic = "fixed";
  bool arithmetic_given = false;
  int threads = 0; // 0: all hardware threads
};

struct LoadedCase {
  CaseFile case_file;
  RunSettings settings;
  std::unique_ptr<Simulation> simulation;
  std::optional<Snapshot> from_snapshot; // metadata and state the run started from
};

// Sets the thread count (--threads), then loads, overrides, validates (unknown keys included)
// and builds; from a snapshot, rebuilds its
// case with its overrides (plus any new ones) and restores its exact state and step.
// Throws CaseError or SnapshotError.
LoadedCase load_simulation(const CaseOptions& options);

// Where the run ends and the steps to there: --steps N (N more), else the absolute end given by
// --t-end T; unless required_on_command_line, else the end of the run a snapshot continues (kept
// in it, docs/restart.md) or the case's [run] steps / t_end. Throws CaseError if nothing says,
// or if the run is already past that end (naming it).
RunEnd resolve_run_end(const LoadedCase& loaded, std::optional<std::int64_t> steps,
                       std::optional<double> t_end, bool required_on_command_line);

void apply_thread_count(int threads);

// "revsph: error: <message>" on stderr.
void print_error(const std::string& message);
// A failure only this process may have met (a fault in its own particles): one line and, in a
// distributed run, the end of every process at once with `status` (none must wait for this one
// in an exchange); otherwise returns `status`.
int stop_every_process(const std::string& message, int status);
// A fault that stopped the steps: one that every process threw together (SimulationFault::shared,
// the same agreed report on each) is printed by process 0 and every process returns the status;
// one met by this process alone ends every process (stop_every_process).
int stop_on_fault(const SimulationFault& fault);

// In a distributed run, process 0 alone writes the run's files (the others take part in the
// collective snapshot writes). `path` on that process, nothing on the others.
std::optional<std::string> file_of_first_process(const std::filesystem::path& path);
// Runs `check` (which may throw CaseError) on process 0 only, then every process throws what it
// threw: checks of the output directory that must not race (--force removes files there).
void check_on_first_process(const std::function<void()>& check);

// "setup: NAME = VALUE" for each entry of SimulationInfo::setup_report (stdout).
void print_setup_report(const SimulationInfo& info);

} // namespace revsph::cli
