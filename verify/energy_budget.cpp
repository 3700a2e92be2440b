#include "verify/energy_budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace revsph {

EnergyBudgetCheck check_energy_budget(Simulation& simulation, std::int64_t steps,
                                      ProgressReporter* progress) {
  const auto start = std::chrono::steady_clock::now();
  EnergyBudgetCheck check;
  check.steps = steps;
  const EnergyBudget initial = simulation.energy();
  check.initial_total = check.final_total = initial.total();
  check.largest_term = initial.largest_term();
  double largest_deviation = 0.0;
  for (std::int64_t step = 1; step <= steps; ++step) {
    simulation.advance(1);
    const EnergyBudget budget = simulation.energy();
    check.final_total = budget.total();
    check.largest_term = std::max(check.largest_term, budget.largest_term());
    largest_deviation =
        std::max(largest_deviation, std::fabs(check.final_total - check.initial_total));
    if (progress != nullptr) {
      progress->update(simulation.steps_taken());
    }
  }
  if (progress != nullptr) {
    progress->finish(simulation.steps_taken());
  }
  // Relative to the largest term seen by the end of the run.
  if (check.largest_term > 0.0) {
    check.max_relative_error = largest_deviation / check.largest_term;
  }
  check.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return check;
}

} // namespace revsph
