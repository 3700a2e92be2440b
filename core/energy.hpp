#pragma once
// An energy budget: named terms (kinetic, gravitational, …) and their total.

#include <string>
#include <vector>

namespace revsph {

struct EnergyTerm {
  std::string name;
  double value = 0.0;
};

struct EnergyBudget {
  std::vector<EnergyTerm> terms;
  // The rate at which prescribed boundary motion (a driven wall) feeds energy in (W; W/m in 2D):
  // the total changes by its time integral. Zero for an isolated system.
  double power_in = 0.0;

  double total() const {
    double sum = 0.0;
    for (const EnergyTerm& term : terms) {
      sum += term.value;
    }
    return sum;
  }
};

} // namespace revsph
