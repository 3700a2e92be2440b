#pragma once
// The positions of a state's particle sets as structure-of-arrays coordinates, for the checks
// that put them in a cell list (close pairs, the smallest distance, wall penetration).

#include "core/geometry.hpp"
#include "core/state_snapshot.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace revsph {

// Appends this process's positions of `sets`, in their order, to `points`. Non-finite ones are
// left out: a cell list cannot place them, and a run that made one faults on its own.
template <int D>
void append_finite_positions(const StateSnapshot& state, const std::vector<std::string>& sets,
                             CoordinateArrays<D>& points) {
  for (const std::string& set : sets) {
    const FieldSnapshot* position = state.find(set, "position");
    if (position == nullptr) {
      continue;
    }
    for (std::size_t i = 0; i < position->count; ++i) {
      bool finite = true;
      for (int k = 0; k < D; ++k) {
        finite = finite && std::isfinite(position->real(k, i));
      }
      for (int k = 0; k < D && finite; ++k) {
        points[k].push_back(position->real(k, i));
      }
    }
  }
}

} // namespace revsph
