#include "core/coincident_particles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace revsph {

namespace {

template <int D>
struct CellHash {
  std::size_t operator()(const std::array<std::int64_t, D>& cell) const {
    std::size_t hash = 0;
    for (const std::int64_t c : cell) {
      hash = hash * 1000003U ^ std::hash<std::int64_t>{}(c);
    }
    return hash;
  }
};

} // namespace

template <int D>
void refuse_coincident_particles(const CaseFile& case_file,
                                 const std::vector<ParticleBlock<D>>& blocks) {
  if (blocks.empty()) {
    return;
  }
  double spacing = std::numeric_limits<double>::infinity();
  for (const ParticleBlock<D>& block : blocks) {
    spacing = std::min(spacing, block.spacing);
  }
  const double tolerance = 1e-6 * spacing;
  // Cells of half the smallest spacing: a block puts at most one particle in each, so a cell and
  // its neighbours hold few. (block, particle) by cell.
  const double cell_size = 0.5 * spacing;
  using Cell = std::array<std::int64_t, D>;
  int neighbourhood = 1; // 3^D cells around a cell, itself included
  for (int k = 0; k < D; ++k) {
    neighbourhood *= 3;
  }
  std::unordered_map<Cell, std::vector<std::pair<std::uint32_t, std::uint32_t>>, CellHash<D>> cells;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const std::vector<Vec<D>>& positions = blocks[b].positions;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const Vec<D>& x = positions[i];
      Cell cell{};
      for (int k = 0; k < D; ++k) {
        cell[k] = static_cast<std::int64_t>(std::floor(x[k] / cell_size));
      }
      for (int n = 0; n < neighbourhood; ++n) {
        Cell near = cell;
        for (int k = 0, rest = n; k < D; ++k, rest /= 3) {
          near[k] += rest % 3 - 1;
        }
        const auto found = cells.find(near);
        if (found == cells.end()) {
          continue;
        }
        for (const auto& [other_block, other] : found->second) {
          double distance_squared = 0.0;
          const Vec<D>& y = blocks[other_block].positions[other];
          for (int k = 0; k < D; ++k) {
            distance_squared += (x[k] - y[k]) * (x[k] - y[k]);
          }
          if (distance_squared < tolerance * tolerance) {
            std::ostringstream reason;
            reason << "particle " << i << " at (";
            for (int k = 0; k < D; ++k) {
              reason << (k > 0 ? ", " : "") << x[k];
            }
            if (other_block == b) {
              reason << ") lies on its particle " << other
                     << ": two particles at one place (a point file's rows too close)";
            } else {
              reason << ") lies on particle " << other << " of " << blocks[other_block].key
                     << ": the blocks overlap (move one, or leave the overlap out with "
                        "exclude_blocks)";
            }
            case_file.fail(blocks[b].key, reason.str());
          }
        }
      }
      cells[cell].push_back({static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(i)});
    }
  }
}

template void refuse_coincident_particles<1>(const CaseFile&, const std::vector<ParticleBlock<1>>&);
template void refuse_coincident_particles<2>(const CaseFile&, const std::vector<ParticleBlock<2>>&);
template void refuse_coincident_particles<3>(const CaseFile&, const std::vector<ParticleBlock<3>>&);

} // namespace revsph
