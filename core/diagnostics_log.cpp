#include "core/diagnostics_log.hpp"

#include <algorithm>
#include <stdexcept>

namespace revsph {

DiagnosticsLog::DiagnosticsLog(std::optional<std::string> csv_path)
    : csv_path_(std::move(csv_path)) {}

DiagnosticsLog::DiagnosticsLog(std::optional<std::string> csv_path, const LoggedRows& earlier)
    : csv_path_(std::move(csv_path)) {
  for (std::size_t r = 0; r < earlier.rows.size(); ++r) {
    if (r == 0) {
      for (std::size_t c = 2; c < earlier.columns.size(); ++c) {
        // The units come with the first new record.
        maxima_.push_back(
            {earlier.columns[c], RunTotal::same_on_every_process(earlier.rows[r][c]), ""});
      }
      minima_ = maxima_;
    }
    for (std::size_t i = 0; i < maxima_.size(); ++i) {
      const RunTotal value = RunTotal::same_on_every_process(earlier.rows[r][i + 2]);
      maxima_[i].value = std::max(maxima_[i].value, value);
      minima_[i].value = std::min(minima_[i].value, value);
    }
  }
  if (csv_path_ && !earlier.rows.empty()) {
    csv_.emplace(*csv_path_, std::ios::app);
    if (!*csv_) {
      throw std::runtime_error("cannot write " + *csv_path_);
    }
    csv_->precision(17);
  }
}

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
      *csv_ << "step," << column_header("time", "s");
      for (const EnergyTerm& d : diagnostics) {
        *csv_ << "," << column_header(d.name, d.unit);
      }
      *csv_ << "\n";
    }
  }
  for (std::size_t i = 0; i < diagnostics.size() && i < maxima_.size(); ++i) {
    if (maxima_[i].name != diagnostics[i].name) {
      throw std::runtime_error("the diagnostics differ from those of the rows continued");
    }
    maxima_[i].unit = minima_[i].unit = diagnostics[i].unit;
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
