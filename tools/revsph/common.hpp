#pragma once
// What the revsph subcommands share: loading a case with overrides, exit codes, error output.

#include "core/case_file.hpp"
#include "core/model_registry.hpp"
#include "core/run_settings.hpp"
#include "core/simulation.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace revsph::cli {

// Exit statuses of every subcommand.
enum ExitStatus : int {
  success = 0,
  not_reversible = 1, // verify: the state did not return bit for bit
  bad_input = 2,      // command line or case file
  simulation_failed = 3,
};

// Options every simulating subcommand takes.
struct CaseOptions {
  std::string case_path = "dambreak-small";
  std::vector<std::string> overrides; // --set key=value
  std::string arithmetic = "fixed";
  int threads = 0; // 0: all hardware threads
};

struct LoadedCase {
  CaseFile case_file;
  RunSettings settings;
  std::unique_ptr<Simulation> simulation;
};

// Loads, overrides, validates (unknown keys included) and builds. Throws CaseError.
LoadedCase load_simulation(const CaseOptions& options);

// The run length from --steps / --t-end, else from the case's [run] table. Throws CaseError if
// neither says.
std::int64_t resolve_steps(const LoadedCase& loaded, std::optional<std::int64_t> steps,
                           std::optional<double> t_end, bool required_on_command_line);

void apply_thread_count(int threads);

// "revsph: error: <message>" on stderr.
void print_error(const std::string& message);

} // namespace revsph::cli
