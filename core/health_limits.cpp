#include "core/health_limits.hpp"

#include <limits>

namespace revsph {

HealthLimits default_health_limits() {
  HealthLimits limits;
  limits.max_energy_error = 0.5;
  limits.max_speed_over_c = 10.0;
  limits.close_pair_fraction = 0.1;
  limits.merged_pair_fraction = 1e-6;
  return limits;
}

HealthLimits read_health_limits(const CaseFile& case_file) {
  HealthLimits limits = default_health_limits();
  // 0 turns a limit off: no value is beyond infinity (but NaN).
  const auto limit = [&](const char* key, double fallback) {
    const double value = case_file.non_negative_number_or(key, fallback, "no check");
    return value > 0.0 ? value : std::numeric_limits<double>::infinity();
  };
  limits.max_energy_error = limit("health.max_energy_error", limits.max_energy_error);
  limits.max_speed_over_c = limit("health.max_speed_over_c", limits.max_speed_over_c);
  const auto fraction = [&](const char* key, double fallback, const char* zero_means) {
    const double value = case_file.non_negative_number_or(key, fallback, zero_means);
    if (value > 1.0) {
      case_file.fail(key, "must be <= 1 (a fraction of dr)");
    }
    return value;
  };
  limits.close_pair_fraction =
      fraction("health.close_pair_fraction", limits.close_pair_fraction, "not counted");
  limits.merged_pair_fraction =
      fraction("health.merged_pair_fraction", limits.merged_pair_fraction, "no check");
  case_file.accept_table("health");
  return limits;
}

} // namespace revsph
