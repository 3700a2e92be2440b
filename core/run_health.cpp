#include "core/run_health.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace revsph {

namespace {

std::string format(const char* pattern, double a, double b) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

} // namespace

RunHealth::RunHealth(const HealthLimits& limits)
    : close_pair_fraction_(limits.close_pair_fraction),
      merged_pair_fraction_(limits.merged_pair_fraction) {
  checks_[energy_error].limit = limits.max_energy_error;
  checks_[speed_over_c].limit = limits.max_speed_over_c;
  checks_[merged_pairs].limit = 0.0; // any pair that close
}

bool RunHealth::observe_one(Check& check, double value, std::int64_t step, double time) {
  // NaN is beyond any limit.
  const bool beyond = !(value <= check.limit);
  check.largest =
      std::isnan(value) || std::isnan(check.largest) ? NAN : std::max(check.largest, value);
  if (!beyond || check.crossed) {
    return false;
  }
  check.crossed = true;
  check.first_step = step;
  check.first_time = time;
  return true;
}

std::vector<std::string> RunHealth::observe(std::int64_t step, double time,
                                            const HealthReading& reading) {
  std::vector<std::string> crossed;
  char head[64];
  std::snprintf(head, sizeof head, "warning: step %lld, t = %.6g s: ", static_cast<long long>(step),
                time);
  if (reading.energy_error &&
      observe_one(checks_[energy_error], *reading.energy_error, step, time)) {
    crossed.push_back(head + format("energy error %.3g above health.max_energy_error = %g "
                                    "(energy.csv's relative_error): energy is being made or lost",
                                    *reading.energy_error, checks_[energy_error].limit));
  }
  if (reading.speed_over_c &&
      observe_one(checks_[speed_over_c], *reading.speed_over_c, step, time)) {
    crossed.push_back(head + format("max|v|/c = %.3g above health.max_speed_over_c = %g: check "
                                    "the sound speed, dt and the forces",
                                    *reading.speed_over_c, checks_[speed_over_c].limit));
  }
  if (reading.merged_pairs &&
      observe_one(checks_[merged_pairs], static_cast<double>(*reading.merged_pairs), step, time)) {
    std::string line =
        head + format("merged pairs = %.0f (particles closer than %g dr, "
                      "health.merged_pair_fraction): particles have merged",
                      static_cast<double>(*reading.merged_pairs), merged_pair_fraction_);
    if (reading.close_pairs) {
      line += format("; %.0f pairs closer than %g dr", static_cast<double>(*reading.close_pairs),
                     close_pair_fraction_);
    }
    crossed.push_back(line);
  }
  return crossed;
}

void RunHealth::replay(const LoggedRows& energy_rows, const LoggedRows& diagnostics_rows) {
  const auto column = [](const LoggedRows& logged, const char* name) -> std::optional<std::size_t> {
    for (std::size_t c = 0; c < logged.columns.size(); ++c) {
      if (logged.columns[c] == name) {
        return c;
      }
    }
    return std::nullopt;
  };
  // Every logged row starts with step and time.
  const auto replay_rows = [&](const LoggedRows& logged, const auto& reading_of) {
    for (const std::vector<double>& row : logged.rows) {
      observe(static_cast<std::int64_t>(row[0]), row[1], reading_of(row));
    }
  };
  const auto error = column(energy_rows, "relative_error");
  const auto total = column(energy_rows, "total");
  if (error && total && !energy_rows.rows.empty()) {
    const double initial = energy_rows.rows.front()[*total];
    replay_rows(energy_rows, [&](const std::vector<double>& row) {
      HealthReading reading;
      // 0 / 0 while E(0) and every term are 0: nothing has changed.
      reading.energy_error = std::isnan(row[*error]) && row[*total] == initial ? 0.0 : row[*error];
      return reading;
    });
  }
  const auto speed = column(diagnostics_rows, speed_over_c_column);
  const auto pairs = column(diagnostics_rows, merged_pairs_column);
  replay_rows(diagnostics_rows, [&](const std::vector<double>& row) {
    HealthReading reading;
    if (speed) {
      reading.speed_over_c = row[*speed];
    }
    if (pairs) {
      reading.merged_pairs = static_cast<std::uint64_t>(std::max(0.0, row[*pairs]));
    }
    return reading;
  });
}

bool RunHealth::healthy() const {
  for (const Check& check : checks_) {
    if (check.crossed) {
      return false;
    }
  }
  return true;
}

std::vector<std::string> RunHealth::reasons() const {
  static constexpr const char* what[] = {
      "energy error reached %.3g, above health.max_energy_error = %g",
      "max|v|/c reached %.3g, above health.max_speed_over_c = %g",
      "merged pairs reached %.0f (particles closer than %g dr, health.merged_pair_fraction)"};
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < checks_.size(); ++i) {
    const Check& check = checks_[i];
    if (!check.crossed) {
      continue;
    }
    const double limit = i == merged_pairs ? merged_pair_fraction_ : check.limit;
    char where[96];
    std::snprintf(where, sizeof where, "; first at step %lld, t = %.6g s",
                  static_cast<long long>(check.first_step), check.first_time);
    lines.push_back(format(what[i], check.largest, limit) + where);
  }
  return lines;
}

} // namespace revsph
