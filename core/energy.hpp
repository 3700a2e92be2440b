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

  double total() const {
    double sum = 0.0;
    for (const EnergyTerm& term : terms) {
      sum += term.value;
    }
    return sum;
  }
};

} // namespace revsph
