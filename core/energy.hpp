#pragma once
// An energy budget: named terms (kinetic, gravitational, …) and their total. A term's value is a
// RunTotal (core/run_total.hpp): the run's, whichever process computes it.

#include "core/run_total.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace revsph {

struct EnergyTerm {
  std::string name;
  RunTotal value;
  // An energy's is the run's energy unit (the core fills it in); a diagnostic's is the model's,
  // "1" for a pure number (summary.json's "units").
  std::string unit;
};

struct EnergyBudget {
  std::vector<EnergyTerm> terms;

  RunTotal total() const {
    RunTotal sum;
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
