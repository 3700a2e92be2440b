#include "core/run_settings.hpp"

#include "core/health_limits.hpp"

#include <cmath>
#include <filesystem>
#include <limits>

namespace revsph {

std::int64_t RunLength::steps_for(double dt) const {
  if (steps) {
    return *steps;
  }
  if (t_end) {
    // Saturated: llround of a quotient beyond int64 is unspecified (LLONG_MIN on x86), which
    // read as a negative run length ("already past that end").
    const double quotient = *t_end / dt;
    if (!(quotient < 9223372036854775808.0)) { // 2^63
      return std::numeric_limits<std::int64_t>::max();
    }
    return static_cast<std::int64_t>(std::llround(quotient));
  }
  return 0;
}

std::string RunEnd::description() const {
  const std::string where = length.steps
                                ? "step " + std::to_string(*length.steps)
                                : "t = " + format_number(length.t_end.value_or(0.0)) + " s";
  return where + " from " + origin;
}

std::string case_name(const CaseFile& case_file) {
  return case_file.string_or("name",
                             std::filesystem::path(case_file.source_name()).stem().string());
}

SimulationInfo simulation_info(const CaseFile& case_file, std::string_view model, int dimension,
                               Arithmetic arithmetic, double dt) {
  SimulationInfo info;
  info.case_name = case_name(case_file);
  info.model = std::string(model);
  info.dimension = dimension;
  info.arithmetic = arithmetic;
  info.dt = dt;
  return info;
}

RunSettings read_run_settings(const CaseFile& case_file) {
  RunSettings settings;
  settings.name = case_name(case_file);
  if (case_file.has("run.steps") && case_file.has("run.t_end")) {
    case_file.fail("run.t_end", "give either run.steps or run.t_end, not both");
  }
  if (case_file.has("run.steps")) {
    const std::int64_t steps = case_file.integer("run.steps");
    if (steps < 0) {
      case_file.fail("run.steps", "must be >= 0 (got " + std::to_string(steps) + ")");
    }
    settings.length.steps = steps;
  }
  if (case_file.has("run.t_end")) {
    settings.length.t_end = case_file.positive_number("run.t_end");
  }
  settings.energy_every = case_file.integer_or("output.energy_every", 100);
  if (settings.energy_every < 1) {
    case_file.fail("output.energy_every", "must be >= 1");
  }
  settings.snapshot_every = case_file.integer_or("output.snapshot_every", 0);
  if (settings.snapshot_every < 0) {
    case_file.fail("output.snapshot_every", "must be >= 0 (0: only at the start and the end)");
  }
  if (case_file.has("output.snapshot_interval")) {
    settings.snapshot_interval = case_file.positive_number("output.snapshot_interval");
  }
  if (case_file.has("output.progress_interval")) {
    settings.progress_interval = case_file.positive_number("output.progress_interval");
  }
  // [health] is checked here with the rest, before the set-up; `revsph run` reads it again for
  // its health checks (core/health_limits.hpp).
  read_health_limits(case_file);
  case_file.accept_table("run");
  case_file.accept_table("output");
  return settings;
}

} // namespace revsph
