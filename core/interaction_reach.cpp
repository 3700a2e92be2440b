#include "core/interaction_reach.hpp"

#include <atomic>
#include <stdexcept>
#include <string>

namespace revsph {

namespace {

std::atomic<double> largest_radius{0.0};
std::atomic<double> radius_limit{0.0};

} // namespace

void note_interaction_radius(double radius) {
  const double limit = radius_limit.load();
  if (limit > 0.0 && radius > limit) {
    throw std::logic_error("a pair list over " + std::to_string(radius) +
                           " m, beyond the distributed run's ghost reach of " +
                           std::to_string(limit) + " m");
  }
  double seen = largest_radius.load();
  while (radius > seen && !largest_radius.compare_exchange_weak(seen, radius)) {
  }
}

double largest_interaction_radius() {
  return largest_radius.load();
}

void limit_interaction_radius(double reach) {
  radius_limit.store(reach);
}

void forget_interaction_radii() {
  radius_limit.store(0.0);
  largest_radius.store(0.0);
}

} // namespace revsph
