#pragma once
// The check a case with irreversible terms gets besides (or, historically, instead of) the
// bitwise reversal (design note §5): its energy budget. A model's energy terms then include what
// the irreversible terms have dissipated and, counted negative, what driven boundaries have put
// in, so that the total stays constant up to the time integrator's error.

#include "core/mechanical_energy_scale.hpp"
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
  // The energy that moved (core/mechanical_energy_scale.hpp) by the end, and
  // max |E(t) - E(0)| over it.
  double mechanical_scale = 0.0;
  double max_mechanical_relative_error = 0.0;
  double wall_seconds = 0.0;
};

// Accumulates the check from the budgets of successive states (every step of one or both halves
// of a reversal experiment); the first budget is E(0).
class EnergyBudgetTracker {
public:
  void observe(const EnergyBudget& budget);
  // steps and wall_seconds are left to the caller.
  EnergyBudgetCheck result() const;

private:
  bool started_ = false;
  EnergyBudgetCheck check_;
  double largest_deviation_ = 0.0;
  MechanicalEnergyScale mechanical_scale_;
};

// Takes `steps` steps, evaluating the energy after each.
EnergyBudgetCheck check_energy_budget(Simulation& simulation, std::int64_t steps,
                                      ProgressReporter* progress = nullptr);

} // namespace revsph
