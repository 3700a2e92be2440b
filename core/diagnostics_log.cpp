#include "core/diagnostics_log.hpp"

#include <algorithm>
#include <stdexcept>

namespace revsph {

DiagnosticsLog::DiagnosticsLog(std::optional<std::string> csv_path)
    : csv_path_(std::move(csv_path)) {}

void DiagnosticsLog::record(std::int64_t step, double time,
                            const std::vector<EnergyTerm>& diagnostics) {
  if (diagnostics.empty()) {
    return;
  }
  if (maxima_.empty()) {
    maxima_ = diagnostics;
    minima_ = diagnostics;
    // The file is created with the first record, so runs without diagnostics have none.
    if (csv_path_) {
      csv_.emplace(*csv_path_);
      if (!*csv_) {
        throw std::runtime_error("cannot write " + *csv_path_);
      }
      csv_->precision(17);
      *csv_ << "step,time";
      for (const EnergyTerm& d : diagnostics) {
        *csv_ << "," << d.name;
      }
      *csv_ << "\n";
    }
  }
  for (std::size_t i = 0; i < diagnostics.size() && i < maxima_.size(); ++i) {
    maxima_[i].value = std::max(maxima_[i].value, diagnostics[i].value);
    minima_[i].value = std::min(minima_[i].value, diagnostics[i].value);
  }
  if (csv_) {
    *csv_ << step << "," << time;
    for (const EnergyTerm& d : diagnostics) {
      *csv_ << "," << d.value;
    }
    *csv_ << "\n";
    csv_->flush();
  }
}

} // namespace revsph
