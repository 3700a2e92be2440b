#pragma once
// The smallest distance between two particles, of which at least one moves: how close the flow
// has pushed its particles (the progress line's min r/dr, docs/running.md). Two fixed particles
// are never looked at: their distance is the case's.

#include "core/geometry.hpp"

#include <cstddef>

namespace revsph {

// Over `points` (finite coordinates), of which the first `moving` move and the rest are fixed.
// The candidate pairs are those in neighbouring cells of a cell list (core/cell_list.hpp) of cells
// `cell_size` wide: O(N) for points about cell_size apart. The result is exact when it is at most
// cell_size, since every pair that close is a candidate; above, it is the smallest over the
// candidates, no less than the true one. Infinity without a candidate pair.
template <int D>
double smallest_distance(const CoordinateView<D>& points, std::size_t moving, double cell_size);

} // namespace revsph
