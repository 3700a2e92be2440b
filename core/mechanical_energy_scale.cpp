#include "core/mechanical_energy_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace revsph {

void MechanicalEnergyScale::observe(const EnergyBudget& budget) {
  if (!started_) {
    started_ = true;
    for (const EnergyTerm& term : budget.terms) {
      initial_terms_.push_back(term.value);
    }
  }
  for (std::size_t i = 0; i < budget.terms.size(); ++i) {
    const EnergyTerm& term = budget.terms[i];
    // A model keeps its list of terms for the whole run; a term beyond the first budget's has no
    // initial value and counts whole.
    const double initial = i < initial_terms_.size() ? initial_terms_[i] : 0.0;
    const double moved =
        term.name == "kinetic" ? std::fabs(term.value) : std::fabs(term.value - initial);
    scale_ = std::max(scale_, moved);
  }
}

double mechanical_relative_error(double deviation, double scale) {
  if (scale > 0.0) {
    return deviation / scale;
  }
  return deviation == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

} // namespace revsph
