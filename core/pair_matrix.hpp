#pragma once
// The pairs of a SlotLayout as a symmetric sparse matrix in the canonical carrier order:
// M_ij = f(r_ij) for the pairs within reach, M_ii = f(0). For particle methods whose quantities
// solve a linear system over the neighbours (paper 4's implicit volume, W V = 1, eq. 26). The
// entries and their order depend on the positions alone, not on the cell size or the thread
// count: r_ij is computed from the same two coordinates either way round, and the matrix is
// stored row by row in carrier order.

#include "core/pair_sum.hpp"
#include "core/slot_layout.hpp"

#include <Eigen/SparseCore>

#include <cmath>
#include <cstdint>
#include <vector>

namespace revsph {

using PairMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// f: double(double r). Rebuilds `matrix` (its storage reused).
template <int D, class Entry>
void fill_pair_matrix(const SlotLayout<D>& layout, const Entry& f, PairMatrix& matrix) {
  const std::size_t n = layout.carrier_count();
  const std::span<const std::uint32_t> carrier = layout.carrier_of_slot();
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(n + 2 * layout.pairs().pair_count());
  const double diagonal = f(0.0);
  for (std::size_t c = 0; c < n; ++c) {
    entries.emplace_back(static_cast<int>(c), static_cast<int>(c), diagonal);
  }
  for_each_pair<D>(layout, [&](const PairGeometry<D>& pair) {
    const double value = f(pair.r);
    entries.emplace_back(static_cast<int>(carrier[pair.a]), static_cast<int>(carrier[pair.b]),
                         value);
    entries.emplace_back(static_cast<int>(carrier[pair.b]), static_cast<int>(carrier[pair.a]),
                         value);
  });
  matrix.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  matrix.setFromTriplets(entries.begin(), entries.end()); // sorted by row, then column
}

} // namespace revsph
