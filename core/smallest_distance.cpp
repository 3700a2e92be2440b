#include "core/smallest_distance.hpp"

#include "core/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace revsph {

template <int D>
double smallest_distance(const CoordinateView<D>& points, std::size_t moving, double cell_size) {
  const std::size_t n = points[0].size();
  double smallest = std::numeric_limits<double>::infinity();
  if (n < 2 || moving == 0) {
    return smallest;
  }
  Box<D> bounds;
  for (int k = 0; k < D; ++k) {
    const auto [low, high] = std::minmax_element(points[k].begin(), points[k].end());
    bounds.min[k] = *low;
    bounds.max[k] = *high;
  }
  CellList<D> cells(bounds, cell_size, cell_budget(n));
  cells.build(points);
  // The minimum of squared distances: exact in any order, so any thread count gives the same.
#pragma omp parallel for schedule(static) reduction(min : smallest)
  for (std::size_t i = 0; i < moving; ++i) {
    cells.for_each_candidate(point_of<D>(points, i), [&](std::uint32_t j) {
      // A pair of moving points once (from its higher index), a moving-fixed pair from its
      // moving point.
      if (j < moving && j >= i) {
        return;
      }
      smallest = std::min(smallest, squared_distance<D>(points, i, j));
    });
  }
  return std::sqrt(smallest);
}

template double smallest_distance<1>(const CoordinateView<1>&, std::size_t, double);
template double smallest_distance<2>(const CoordinateView<2>&, std::size_t, double);
template double smallest_distance<3>(const CoordinateView<3>&, std::size_t, double);

} // namespace revsph
