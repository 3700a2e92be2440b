#pragma once
// diagnostics.csv: the model's diagnostics (core/simulation.hpp HasDiagnostics) with the same
// cadence as energy.csv: `step,time,NAME…`, and the largest value of each over the run.

#include "core/energy.hpp"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace revsph {

class DiagnosticsLog {
public:
  explicit DiagnosticsLog(std::optional<std::string> csv_path);

  void record(std::int64_t step, double time, const std::vector<EnergyTerm>& diagnostics);
  // The largest value of each diagnostic so far, in the order of the first record.
  const std::vector<EnergyTerm>& maxima() const { return maxima_; }

private:
  std::optional<std::string> csv_path_;
  std::optional<std::ofstream> csv_;
  std::vector<EnergyTerm> maxima_;
};

} // namespace revsph
