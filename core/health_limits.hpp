#pragma once
// The limits of the run's health checks: the case's [health] table (core/run_health.hpp,
// docs/running.md "Health checks"). The defaults live in health_limits.cpp, with core/keys.toml
// declaring the same.

#include "core/case_file.hpp"

namespace revsph {

struct HealthLimits {
  double max_energy_error = 0.0;     // of energy.csv's relative_error; inf: no check
  double max_speed_over_c = 0.0;     // inf: no check (0 in the case file)
  double close_pair_fraction = 0.0;  // of dr: diagnostics.csv's close_pairs; 0: not counted
  double merged_pair_fraction = 0.0; // of dr: the merged-pair check; 0: no check
};

HealthLimits default_health_limits();

// [health] max_energy_error, max_speed_over_c (>= 0; 0 turns the check off: an infinite limit),
// close_pair_fraction and merged_pair_fraction (in [0, 1]); the defaults for those absent.
HealthLimits read_health_limits(const CaseFile& case_file);

} // namespace revsph
