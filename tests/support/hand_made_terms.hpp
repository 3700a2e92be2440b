#pragma once
// Energy terms with values written in a test, for the code that reads budgets and diagnostics
// (a log, a scale): a test's value is the same on every process by construction
// (core/run_total.hpp).

#include "core/energy.hpp"

#include <initializer_list>
#include <utility>
#include <vector>

namespace revsph::testing {

inline std::vector<EnergyTerm>
hand_made_terms(std::initializer_list<std::pair<const char*, double>> terms) {
  std::vector<EnergyTerm> made;
  for (const auto& [name, value] : terms) {
    made.push_back({name, RunTotal::same_on_every_process(value)});
  }
  return made;
}

inline EnergyBudget hand_made_budget(std::initializer_list<std::pair<const char*, double>> terms) {
  return EnergyBudget{hand_made_terms(terms)};
}

} // namespace revsph::testing
