#pragma once
// energy.csv: one row per output step with every energy term, the total and the relative error
// |E(t) - E(0)| / S, E(0) being the first row's total or, for a restarted run, the total at the
// start of the original run, and S the larger of |E(0)| and the largest |term| recorded so far:
// |E(0)| itself for an isolated system whose terms are positive, and still a meaningful scale
// for one that starts at rest (E(0) = 0) and is driven (its terms then include the work done on
// it, counted negative).

#include "core/energy.hpp"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

namespace revsph {

class EnergyLog {
public:
  // Writes to `csv_path` if given; always keeps the error statistics.
  explicit EnergyLog(std::optional<std::string> csv_path,
                     std::optional<double> reference_total = std::nullopt);

  void record(std::int64_t step, double time, const EnergyBudget& budget);

  bool empty() const { return !recorded_; }
  // E(0) for the relative error, if not the first record's total (a later half of a run).
  void set_reference_total(double total) { initial_total_ = total; }
  double initial_total() const { return initial_total_.value_or(0.0); }
  double last_relative_error() const { return last_relative_error_; }
  double max_relative_error() const { return max_relative_error_; }
  const EnergyBudget& last() const { return last_; }

private:
  std::optional<std::ofstream> csv_;
  std::optional<double> initial_total_;
  bool recorded_ = false;
  double scale_ = 0.0;
  double last_relative_error_ = 0.0;
  double max_relative_error_ = 0.0;
  EnergyBudget last_;
};

} // namespace revsph
