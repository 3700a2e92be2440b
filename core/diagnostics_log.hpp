#pragma once
// diagnostics.csv: the model's diagnostics (core/simulation.hpp HasDiagnostics) with the same
// cadence as energy.csv: `step,time,NAME…`, and the smallest and largest value of each over the
// run.

#include "core/energy.hpp"
#include "core/logged_rows.hpp"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace revsph {

class DiagnosticsLog {
public:
  explicit DiagnosticsLog(std::optional<std::string> csv_path);
  // Continues the rows `earlier` (what csv_path already holds, core/logged_rows.hpp): their
  // extremes carry on, and the rows from here on are appended.
  DiagnosticsLog(std::optional<std::string> csv_path, const LoggedRows& earlier);

  void record(std::int64_t step, double time, const std::vector<EnergyTerm>& diagnostics);
  // The largest and the smallest value of each diagnostic so far, in the order of the first
  // record (a signed quantity that only falls keeps its maximum at the start: both are needed).
  const std::vector<EnergyTerm>& maxima() const { return maxima_; }
  const std::vector<EnergyTerm>& minima() const { return minima_; }

private:
  std::optional<std::string> csv_path_;
  std::optional<std::ofstream> csv_;
  std::vector<EnergyTerm> maxima_;
  std::vector<EnergyTerm> minima_;
};

} // namespace revsph
