#include "core/neighbour_list.hpp"
#include "core/interaction_reach.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace revsph {

namespace {

// Calls emit(b, accepted) for each candidate b of query a, in cell order; accepted says whether
// b is a neighbour. Reporting rejected candidates too lets the callers count and store without a
// branch on the distance test: once the fluid is disordered, about a third of the candidates
// pass in no predictable pattern, and mispredicted branches dominated the search.
template <int D, class Emit>
void scan_query(const CellList<D>& cells, const CoordinateView<D>& targets,
                const CoordinateView<D>& queries, std::size_t a, double radius_squared,
                bool exclude_self, Emit&& emit) {
  cells.for_each_candidate(point_of<D>(queries, a), [&](std::uint32_t b) {
    const bool is_self = exclude_self & (b == a);
    emit(b, (squared_distance<D>(queries, a, targets, b) < radius_squared) & !is_self);
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
  note_interaction_radius(radius);
  const std::size_t n = queries[0].size();
  const double radius_squared = radius * radius;
  const bool exclude_self = self_pairs == SelfPairs::excluded;
  result.offsets.assign(n + 1, 0);
  bool too_many = false;

  // Two passes (count, then fill) keep the output layout independent of the thread count; one
  // parallel region for both (every region is a barrier: issue 15).
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      std::size_t count = 0;
      scan_query<D>(cells, targets, queries, a, radius_squared, exclude_self,
                    [&](std::uint32_t, bool accepted) { count += accepted; });
      result.offsets[a + 1] = static_cast<std::uint32_t>(count);
    }
#pragma omp single
    {
      std::size_t total = 0;
      for (std::size_t a = 0; a < n; ++a) {
        total += result.offsets[a + 1];
        too_many = too_many || total > std::numeric_limits<std::uint32_t>::max();
        result.offsets[a + 1] = static_cast<std::uint32_t>(total);
      }
      result.indices.resize(too_many ? 0 : total);
    }
    // Every candidate is written at the next free place, which advances only when accepted: one
    // spare place past the (known) count suffices.
    std::vector<std::uint32_t> buffer;
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      if (too_many) {
        continue;
      }
      const std::size_t expected = result.offsets[a + 1] - result.offsets[a];
      buffer.resize(expected + 1);
      std::size_t written = 0;
      scan_query<D>(cells, targets, queries, a, radius_squared, exclude_self,
                    [&](std::uint32_t b, bool accepted) {
                      buffer[written] = b;
                      written += accepted;
                    });
      std::sort(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(written));
      std::copy(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(written),
                result.indices.begin() + static_cast<std::ptrdiff_t>(result.offsets[a]));
    }
  }
  if (too_many) {
    throw std::length_error("find_neighbours: more than 2^32 - 1 pairs in one list");
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
    result.offsets.push_back(static_cast<std::uint32_t>(result.indices.size()));
  }
  return result;
}

template void find_neighbours<1>(const CellList<1>&, const CoordinateView<1>&,
                                 const CoordinateView<1>&, double, SelfPairs, NeighbourList&);
template NeighbourList find_neighbours_brute_force<1>(const CoordinateView<1>&,
                                                      const CoordinateView<1>&, double, SelfPairs);
template void find_neighbours<2>(const CellList<2>&, const CoordinateView<2>&,
                                 const CoordinateView<2>&, double, SelfPairs, NeighbourList&);
template void find_neighbours<3>(const CellList<3>&, const CoordinateView<3>&,
                                 const CoordinateView<3>&, double, SelfPairs, NeighbourList&);
template NeighbourList find_neighbours_brute_force<2>(const CoordinateView<2>&,
                                                      const CoordinateView<2>&, double, SelfPairs);
template NeighbourList find_neighbours_brute_force<3>(const CoordinateView<3>&,
                                                      const CoordinateView<3>&, double, SelfPairs);

} // namespace revsph
