#pragma once
// The distributed lane's starting split: every process makes the same points, and process r
// holds those whose index is r modulo the process count (so no process starts with a region of
// its own).

#include "core/distributed/processes.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

struct ProcessShare {
  std::vector<double> coordinates; // point after point, `dimension` values each
  std::vector<std::uint64_t> indices;
};

inline ProcessShare round_robin_share(const std::vector<double>& points, std::size_t dimension) {
  ProcessShare share;
  const auto processes = static_cast<std::size_t>(revsph::distributed::process_count());
  const auto rank = static_cast<std::size_t>(revsph::distributed::process_rank());
  for (std::size_t i = 0; i < points.size() / dimension; ++i) {
    if (i % processes == rank) {
      share.coordinates.insert(share.coordinates.end(),
                               points.begin() + static_cast<std::ptrdiff_t>(i * dimension),
                               points.begin() + static_cast<std::ptrdiff_t>((i + 1) * dimension));
      share.indices.push_back(i);
    }
  }
  return share;
}
