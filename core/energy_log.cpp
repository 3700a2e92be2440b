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

EnergyLog::EnergyLog(std::optional<std::string> csv_path, std::optional<double> reference_total,
                     const LoggedRows& earlier)
    : initial_total_(reference_total) {
  const std::size_t columns = earlier.columns.size();
  if (columns < 5 || earlier.columns[columns - 3] != "total") {
    throw std::runtime_error("the energy.csv continued has no step, time, terms, total, errors");
  }
  earlier_terms_.assign(earlier.columns.begin() + 2, earlier.columns.end() - 3);
  for (const std::vector<double>& row : earlier.rows) {
    EnergyBudget budget;
    for (std::size_t t = 0; t < earlier_terms_.size(); ++t) {
      budget.terms.push_back({earlier_terms_[t], RunTotal::same_on_every_process(row[2 + t]), ""});
    }
    if (!initial_total_) {
      initial_total_ = budget.total().value();
    }
    observe(budget);
  }
  recorded_ = !earlier.rows.empty();
  if (csv_path) {
    csv_.emplace(*csv_path, std::ios::app);
    if (!*csv_) {
      throw std::runtime_error("cannot write " + *csv_path);
    }
    csv_->precision(17);
  }
}

void EnergyLog::continue_from(const EnergyLog& earlier) {
  initial_total_ = earlier.initial_total_;
  scale_ = earlier.scale_;
  mechanical_scale_ = earlier.mechanical_scale_;
}

void EnergyLog::record(std::int64_t step, double time, const EnergyBudget& budget) {
  const double total = budget.total();
  if (!recorded_) {
    recorded_ = true;
    if (!initial_total_) {
      initial_total_ = total;
    }
    if (csv_) {
      // Each column's unit in its header cell, `name [unit]` (core/logged_rows.hpp).
      const std::string unit = budget.terms.empty() ? "" : budget.terms.front().unit;
      *csv_ << "step," << column_header("time", "s");
      for (const EnergyTerm& term : budget.terms) {
        *csv_ << "," << column_header(term.name, term.unit);
      }
      *csv_ << "," << column_header("total", unit) << "," << column_header("relative_error", "1")
            << "," << column_header("mechanical_relative_error", "1") << "\n";
    }
  }
  if (!earlier_terms_.empty()) {
    for (std::size_t t = 0; t < budget.terms.size(); ++t) {
      if (budget.terms.size() != earlier_terms_.size() ||
          budget.terms[t].name != earlier_terms_[t]) {
        throw std::runtime_error("the energy terms differ from those of the rows continued");
      }
    }
  }
  observe(budget);
  if (csv_) {
    *csv_ << step << "," << time;
    for (const EnergyTerm& term : budget.terms) {
      *csv_ << "," << term.value;
    }
    *csv_ << "," << total << "," << last_relative_error_ << "," << last_mechanical_relative_error_
          << "\n";
    csv_->flush();
  }
}

void EnergyLog::observe(const EnergyBudget& budget) {
  const double total = budget.total();
  const double deviation = std::fabs(total - *initial_total_);
  max_deviation_ = std::max(max_deviation_, deviation);
  scale_ = std::max({scale_, std::fabs(*initial_total_), budget.largest_term()});
  last_relative_error_ = deviation / scale_;
  max_relative_error_ = std::max(max_relative_error_, last_relative_error_);
  mechanical_scale_.observe(budget);
  last_mechanical_relative_error_ = mechanical_relative_error(deviation, mechanical_scale_.value());
  last_ = budget;
}

double EnergyLog::max_mechanical_relative_error() const {
  return mechanical_relative_error(max_deviation_, mechanical_scale_.value());
}

} // namespace revsph
