#pragma once
// The check a dissipative case gets instead of the bitwise reversal (design note §5): its energy
// budget. The model's total energy includes what the irreversible terms have dissipated (so it
// stays constant without driving), and changes by the work of driven boundaries, the time
// integral of EnergyBudget::power_in (trapezoid rule, sampled every step).

#include "core/progress.hpp"
#include "core/simulation.hpp"

#include <cstdint>

namespace revsph {

struct EnergyBudgetCheck {
  std::int64_t steps = 0;
  double initial_total = 0.0;
  double final_total = 0.0;
  double work_in = 0.0; // integral of power_in over the run
  // max over the steps of |E(t) - E(0) - W(t)| / max(|E(0)|, |E(t)|, |W(t)|)
  double max_relative_error = 0.0;
  double wall_seconds = 0.0;
};

EnergyBudgetCheck check_energy_budget(Simulation& simulation, std::int64_t steps,
                                      ProgressReporter* progress = nullptr);

} // namespace revsph
