#pragma once
// Each particle's estimated share of a step's work, the weight by which the regions are cut
// (docs/design/distributed.md, piece 6): equal particle counts are not equal work where a region
// holds many wall particles (which pair with the fluid only) or a free surface (fewer
// neighbours). The work of a particle is a constant for its own updates plus half the pairs it
// takes part in (each pair is summed once); pairs between two particles of fixed sets are not
// summed. The constant, 3 pairs, is the ratio measured by `perf` on the Table-1 dam break on one
// process (per-particle work, the sub-steps, slot layout and cell list, about 15 % of a step;
// pair work about 63 % at 14 pairs a particle).
//
// Neighbours are counted on a grid of cells of side the reach (the 3^d cells around a particle,
// scaled by the ball's share of their volume): an estimate, which changes only the speed.

#include "fixedpoint/deterministic_math.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <unordered_map>
#include <vector>

namespace revsph::distributed {

// `points` (dimension values each) with `moving[i]` saying whether point i's set moves; the
// first `weighed` of them get a weight, the others (ghosts) are only counted as neighbours.
inline std::vector<float> estimated_work(std::span<const double> points,
                                         std::span<const unsigned char> moving, std::size_t weighed,
                                         int dimension, double reach) {
  constexpr double own_update_cost = 3.0; // in pairs
  const auto d = static_cast<std::size_t>(dimension);
  const std::size_t count = moving.size();
  struct Counts {
    std::uint32_t all = 0;
    std::uint32_t moving = 0;
  };
  // A cell's key: its integer coordinates, 21 bits each (offset so that they are positive).
  const auto key_of = [&](const std::int64_t* cell) {
    std::uint64_t key = 0;
    for (std::size_t k = 0; k < d; ++k) {
      key = (key << 21) | (static_cast<std::uint64_t>(cell[k] + (1 << 20)) & ((1U << 21) - 1));
    }
    return key;
  };
  const auto cell_of = [&](std::size_t i, std::int64_t* cell) {
    for (std::size_t k = 0; k < d; ++k) {
      cell[k] = static_cast<std::int64_t>(std::floor(points[i * d + k] / reach));
    }
  };
  std::unordered_map<std::uint64_t, Counts> cells;
  cells.reserve(count);
  std::int64_t cell[3] = {0, 0, 0};
  for (std::size_t i = 0; i < count; ++i) {
    cell_of(i, cell);
    Counts& counts = cells[key_of(cell)];
    ++counts.all;
    counts.moving += moving[i] != 0 ? 1U : 0U;
  }
  const double ball = dimension == 1   ? 2.0
                      : dimension == 2 ? std::numbers::pi
                                       : 4.0 / 3.0 * std::numbers::pi;
  const double ball_share = ball / dmath::integer_power(3.0, dimension);
  std::vector<float> work(weighed);
  std::int64_t around[3] = {0, 0, 0};
  const int neighbour_cells = dimension == 1 ? 3 : dimension == 2 ? 9 : 27;
  for (std::size_t i = 0; i < weighed; ++i) {
    cell_of(i, cell);
    double near = 0.0;
    for (int n = 0; n < neighbour_cells; ++n) {
      int rest = n;
      for (std::size_t k = 0; k < d; ++k) {
        around[k] = cell[k] + rest % 3 - 1;
        rest /= 3;
      }
      const auto found = cells.find(key_of(around));
      if (found != cells.end()) {
        near += moving[i] != 0 ? found->second.all : found->second.moving;
      }
    }
    work[i] = static_cast<float>(own_update_cost + 0.5 * near * ball_share);
  }
  return work;
}

} // namespace revsph::distributed
