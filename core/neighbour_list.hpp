#pragma once
// Neighbour lists in compressed rows: for each query point, the indices of the target points
// strictly closer than a radius, in ascending index order.
//
// The lists are a function of the coordinates alone: not of the cell size, not of the order in
// which the cell list stores points, not of the thread count. Sums over them are therefore
// reproducible even in floating point, and exact fixed-point sums do not need the order at all.

#include "core/cell_list.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace revsph {

struct NeighbourList {
  // Neighbours of query a: indices[offsets[a], offsets[a+1]). 32-bit (4 bytes a query, not 8):
  // find_neighbours refuses a list of more than 2^32 - 1 pairs.
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;

  std::size_t query_count() const { return offsets.size() - 1; }
  std::span<const std::uint32_t> of(std::size_t a) const {
    return {indices.data() + offsets[a], offsets[a + 1] - offsets[a]};
  }
  std::size_t pair_count() const { return indices.size(); }
};

enum class SelfPairs { excluded, included };

// Neighbours of each query among the targets held by `cells` (built from `targets`), within
// `radius` (|x_a - x_b|^2 < radius^2). With SelfPairs::excluded, queries and targets are the same
// point set and a point is not its own neighbour. Requires radius <= cells.cell_size().
template <int D>
void find_neighbours(const CellList<D>& cells, const CoordinateView<D>& targets,
                     const CoordinateView<D>& queries, double radius, SelfPairs self_pairs,
                     NeighbourList& result);

// The O(N^2) reference the tests compare against.
template <int D>
NeighbourList find_neighbours_brute_force(const CoordinateView<D>& targets,
                                          const CoordinateView<D>& queries, double radius,
                                          SelfPairs self_pairs);

} // namespace revsph
