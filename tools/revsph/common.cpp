#include "tools/revsph/common.hpp"

#include "core/threads.hpp"

#include <iostream>

namespace revsph::cli {

LoadedCase load_simulation(const CaseOptions& options) {
  CaseFile case_file = load_case(options.case_path);
  for (const std::string& assignment : options.overrides) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw CaseError(case_file.source_name(), assignment,
                      "--set expects key=value, e.g. --set discretisation.dr=0.01");
    }
    case_file.set(assignment.substr(0, equals), assignment.substr(equals + 1));
  }
  if (options.arithmetic != "fixed" && options.arithmetic != "float") {
    throw CaseError(case_file.source_name(), "--arithmetic",
                    "expected fixed or float, got " + options.arithmetic);
  }
  SimulationOptions simulation_options;
  simulation_options.arithmetic =
      options.arithmetic == "fixed" ? Arithmetic::fixed : Arithmetic::floating;
  RunSettings settings = read_run_settings(case_file);
  std::unique_ptr<Simulation> simulation = create_simulation(case_file, simulation_options);
  case_file.require_no_unknown_keys();
  return {std::move(case_file), std::move(settings), std::move(simulation)};
}

std::int64_t resolve_steps(const LoadedCase& loaded, std::optional<std::int64_t> steps,
                           std::optional<double> t_end, bool required_on_command_line) {
  RunLength length;
  if (steps || t_end) {
    length.steps = steps;
    length.t_end = t_end;
  } else if (!required_on_command_line) {
    length = loaded.settings.length;
  }
  if (!length.given()) {
    throw CaseError(loaded.case_file.source_name(), "run",
                    required_on_command_line
                        ? "give the number of steps with --steps N or --t-end T"
                        : "no run length: give --steps N or --t-end T, or [run] steps / t_end");
  }
  if (length.t_end && !(*length.t_end > 0.0)) {
    throw CaseError(loaded.case_file.source_name(), "--t-end", "must be > 0");
  }
  const std::int64_t n = length.steps_for(loaded.simulation->info().dt);
  if (n < 0) {
    throw CaseError(loaded.case_file.source_name(), "--steps", "must be >= 0");
  }
  return n;
}

void apply_thread_count(int threads) {
  if (threads > 0) {
    set_thread_count(threads);
  }
}

void print_error(const std::string& message) {
  std::cerr << "revsph: error: " << message << "\n";
}

} // namespace revsph::cli
