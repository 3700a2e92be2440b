#pragma once
// The check a dissipative case gets instead of the bitwise reversal (design note §5): its energy
// budget. A model's energy terms then include what the irreversible terms have dissipated and,
// counted negative, what driven boundaries have put in, so that the total stays constant up to
// the time integrator's error.

#include "core/progress.hpp"
#include "core/simulation.hpp"

#include <cstdint>

namespace revsph {

struct EnergyBudgetCheck {
  std::int64_t steps = 0;
  double initial_total = 0.0;
  double final_total = 0.0;
  // The largest |term| seen: the scale of the energies that change hands.
  double largest_term = 0.0;
  // max over the steps of |E(t) - E(0)| / largest_term
  double max_relative_error = 0.0;
  double wall_seconds = 0.0;
};

// Takes `steps` steps, evaluating the energy after each.
EnergyBudgetCheck check_energy_budget(Simulation& simulation, std::int64_t steps,
                                      ProgressReporter* progress = nullptr);

} // namespace revsph
