#pragma once
// An energy budget: named terms (kinetic, gravitational, …) and their total.

#include <algorithm>
#include <cmath>
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

  // The largest |term|: the scale of a budget whose total starts at zero (a driven flow).
  double largest_term() const {
    double largest = 0.0;
    for (const EnergyTerm& term : terms) {
      largest = std::max(largest, std::fabs(term.value));
    }
    return largest;
  }
};

} // namespace revsph
