#include "core/neighbour_list.hpp"

#include <algorithm>
#include <stdexcept>

namespace revsph {

namespace {

template <int D>
double squared_distance(const CoordinateView<D>& a_points, std::size_t a,
                        const CoordinateView<D>& b_points, std::size_t b) {
  double sum = 0.0;
  for (int k = 0; k < D; ++k) {
    const double d = a_points[k][a] - b_points[k][b];
    sum += d * d;
  }
  return sum;
}

template <int D>
Vec<D> point_of(const CoordinateView<D>& points, std::size_t i) {
  Vec<D> p{};
  for (int k = 0; k < D; ++k) {
    p[k] = points[k][i];
  }
  return p;
}

// Calls emit(b) for each neighbour b of query a, in cell order.
template <int D, class Emit>
void scan_query(const CellList<D>& cells, const CoordinateView<D>& targets,
                const CoordinateView<D>& queries, std::size_t a, double radius_squared,
                bool exclude_self, Emit&& emit) {
  cells.for_each_candidate(point_of<D>(queries, a), [&](std::uint32_t b) {
    if (exclude_self && b == a) {
      return;
    }
    if (squared_distance<D>(queries, a, targets, b) < radius_squared) {
      emit(b);
    }
  });
}

} // namespace

template <int D>
void find_neighbours(const CellList<D>& cells, const CoordinateView<D>& targets,
                     const CoordinateView<D>& queries, double radius, SelfPairs self_pairs,
                     NeighbourList& result) {
  if (radius > cells.cell_size()) {
    throw std::invalid_argument("find_neighbours: the radius exceeds the cell size");
  }
  const std::size_t n = queries[0].size();
  const double radius_squared = radius * radius;
  const bool exclude_self = self_pairs == SelfPairs::excluded;
  result.offsets.assign(n + 1, 0);

  // Two passes (count, then fill) keep the output layout independent of the thread count.
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    std::size_t count = 0;
    scan_query<D>(cells, targets, queries, a, radius_squared, exclude_self,
                  [&](std::uint32_t) { ++count; });
    result.offsets[a + 1] = count;
  }
  for (std::size_t a = 0; a < n; ++a) {
    result.offsets[a + 1] += result.offsets[a];
  }
  result.indices.resize(result.offsets[n]);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    std::uint32_t* out = result.indices.data() + result.offsets[a];
    std::uint32_t* const begin = out;
    scan_query<D>(cells, targets, queries, a, radius_squared, exclude_self,
                  [&](std::uint32_t b) { *out++ = b; });
    std::sort(begin, out);
  }
}

template <int D>
NeighbourList find_neighbours_brute_force(const CoordinateView<D>& targets,
                                          const CoordinateView<D>& queries, double radius,
                                          SelfPairs self_pairs) {
  NeighbourList result;
  const double radius_squared = radius * radius;
  for (std::size_t a = 0; a < queries[0].size(); ++a) {
    for (std::size_t b = 0; b < targets[0].size(); ++b) {
      if (self_pairs == SelfPairs::excluded && a == b) {
        continue;
      }
      if (squared_distance<D>(queries, a, targets, b) < radius_squared) {
        result.indices.push_back(static_cast<std::uint32_t>(b));
      }
    }
    result.offsets.push_back(result.indices.size());
  }
  return result;
}

template void find_neighbours<2>(const CellList<2>&, const CoordinateView<2>&,
                                 const CoordinateView<2>&, double, SelfPairs, NeighbourList&);
template void find_neighbours<3>(const CellList<3>&, const CoordinateView<3>&,
                                 const CoordinateView<3>&, double, SelfPairs, NeighbourList&);
template NeighbourList find_neighbours_brute_force<2>(const CoordinateView<2>&,
                                                      const CoordinateView<2>&, double, SelfPairs);
template NeighbourList find_neighbours_brute_force<3>(const CoordinateView<3>&,
                                                      const CoordinateView<3>&, double, SelfPairs);

} // namespace revsph
