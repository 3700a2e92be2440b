#include "verify/energy_budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace revsph {

void EnergyBudgetTracker::observe(const EnergyBudget& budget) {
  const double total = budget.total();
  if (!started_) {
    started_ = true;
    check_.initial_total = total;
  }
  check_.final_total = total;
  check_.largest_term = std::max(check_.largest_term, budget.largest_term());
  largest_deviation_ = std::max(largest_deviation_, std::fabs(total - check_.initial_total));
  mechanical_scale_.observe(budget);
}

EnergyBudgetCheck EnergyBudgetTracker::result() const {
  EnergyBudgetCheck check = check_;
  // Relative to the largest term seen by the end of the run.
  if (check.largest_term > 0.0) {
    check.max_relative_error = largest_deviation_ / check.largest_term;
  }
  check.mechanical_scale = mechanical_scale_.value();
  check.max_mechanical_relative_error =
      mechanical_relative_error(largest_deviation_, mechanical_scale_.value());
  return check;
}

EnergyBudgetCheck check_energy_budget(Simulation& simulation, std::int64_t steps,
                                      ProgressReporter* progress) {
  const auto start = std::chrono::steady_clock::now();
  EnergyBudgetTracker tracker;
  tracker.observe(simulation.energy());
  for (std::int64_t step = 1; step <= steps; ++step) {
    simulation.advance(1);
    tracker.observe(simulation.energy());
    if (progress != nullptr) {
      progress->update(simulation.steps_taken());
    }
  }
  if (progress != nullptr) {
    progress->finish(simulation.steps_taken());
  }
  EnergyBudgetCheck check = tracker.result();
  check.steps = steps;
  check.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return check;
}

} // namespace revsph
