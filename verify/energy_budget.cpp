#include "verify/energy_budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace revsph {

EnergyBudgetCheck check_energy_budget(Simulation& simulation, std::int64_t steps,
                                      ProgressReporter* progress) {
  const auto start = std::chrono::steady_clock::now();
  const double dt = simulation.info().dt;
  EnergyBudget budget = simulation.energy();
  EnergyBudgetCheck check;
  check.steps = steps;
  check.initial_total = budget.total();
  double scale = std::fabs(check.initial_total);
  double power = budget.power_in;
  for (std::int64_t step = 1; step <= steps; ++step) {
    simulation.advance(1);
    budget = simulation.energy();
    check.work_in += 0.5 * dt * (power + budget.power_in);
    power = budget.power_in;
    const double total = budget.total();
    scale = std::max({scale, std::fabs(total), std::fabs(check.work_in)});
    if (scale > 0.0) {
      check.max_relative_error = std::max(
          check.max_relative_error, std::fabs(total - check.initial_total - check.work_in) / scale);
    }
    check.final_total = total;
    if (progress != nullptr) {
      progress->update(simulation.steps_taken());
    }
  }
  if (progress != nullptr) {
    progress->finish(simulation.steps_taken());
  }
  check.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return check;
}

} // namespace revsph
