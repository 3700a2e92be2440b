#include "core/energy_log.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace revsph {

EnergyLog::EnergyLog(std::optional<std::string> csv_path, std::optional<double> reference_total)
    : initial_total_(reference_total) {
  if (csv_path) {
    csv_.emplace(*csv_path);
    if (!*csv_) {
      throw std::runtime_error("cannot write " + *csv_path);
    }
    csv_->precision(17);
  }
}

void EnergyLog::record(std::int64_t step, double time, const EnergyBudget& budget) {
  const double total = budget.total();
  if (!recorded_) {
    recorded_ = true;
    if (!initial_total_) {
      initial_total_ = total;
    }
    if (csv_) {
      *csv_ << "step,time";
      for (const EnergyTerm& term : budget.terms) {
        *csv_ << "," << term.name;
      }
      *csv_ << ",total,relative_error\n";
    }
  }
  scale_ = std::max({scale_, std::fabs(*initial_total_), budget.largest_term()});
  last_relative_error_ = std::fabs(total - *initial_total_) / scale_;
  max_relative_error_ = std::max(max_relative_error_, last_relative_error_);
  last_ = budget;
  if (csv_) {
    *csv_ << step << "," << time;
    for (const EnergyTerm& term : budget.terms) {
      *csv_ << "," << term.value;
    }
    *csv_ << "," << total << "," << last_relative_error_ << "\n";
    csv_->flush();
  }
}

} // namespace revsph
