// The ghost exchange (core/distributed/ghost_plan.hpp) on whatever number of processes CTest
// starts (1, 2, 3): each process owns the points of its region; after one exchange it holds, as
// ghosts, every other process's point within the reach of one of its own (the pairs it must
// form), with the coordinates bit for bit, and no point of its own. On one process there are no
// ghosts.

#include "core/distributed/ghost_plan.hpp"
#include "core/distributed/processes.hpp"
#include "core/distributed/spatial_partition.hpp"
#include "process_share.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace {

using namespace revsph::distributed;

TEST(GhostPlan, DeliversEveryNeighbourFromOtherProcessesBitForBit) {
  constexpr int dimension = 2;
  constexpr std::size_t d = dimension;
  constexpr std::size_t count = 2500;
  constexpr double reach = 0.07;
  std::mt19937_64 generator(99);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> points(count * d);
  for (double& x : points) {
    x = uniform(generator);
  }
  // Start from a round-robin split, balance, then keep the points of this process's region.
  const ProcessShare held = round_robin_share(points, d);
  SpatialPartition partition(dimension, PartitionMethod::coordinate_bisection);
  partition.balance(held.coordinates, held.indices);
  std::vector<double> mine;
  std::vector<std::uint64_t> my_indices;
  std::vector<int> owner(count);
  for (std::size_t i = 0; i < count; ++i) {
    owner[i] = partition.owner_of({points.data() + i * d, d});
    if (owner[i] == process_rank()) {
      mine.insert(mine.end(), points.begin() + static_cast<std::ptrdiff_t>(i * d),
                  points.begin() + static_cast<std::ptrdiff_t>((i + 1) * d));
      my_indices.push_back(i);
    }
  }
  const GhostPlan plan(partition, mine, reach);
  const std::vector<std::uint64_t> ghost_indices =
      plan.exchange(std::span<const std::uint64_t>(my_indices), 1);
  const std::vector<double> ghost_points = plan.exchange(std::span<const double>(mine), d);
  EXPECT_EQ(ghost_indices.size(), plan.ghost_count());
  EXPECT_EQ(ghost_points.size(), plan.ghost_count() * d);
  const std::set<std::uint64_t> ghosts(ghost_indices.begin(), ghost_indices.end());
  EXPECT_EQ(ghosts.size(), ghost_indices.size()); // each ghost once
  std::size_t wrong_coordinates = 0;
  for (std::size_t g = 0; g < std::min(ghost_indices.size(), ghost_points.size() / d); ++g) {
    EXPECT_NE(owner[ghost_indices[g]], process_rank());
    for (std::size_t k = 0; k < d; ++k) {
      wrong_coordinates += ghost_points[g * d + k] != points[ghost_indices[g] * d + k] ? 1 : 0;
    }
  }
  EXPECT_EQ(wrong_coordinates, 0U);
  std::size_t missing = 0, needed = 0;
  for (const std::uint64_t a : my_indices) {
    for (std::size_t b = 0; b < count; ++b) {
      const double dx = points[a * d] - points[b * d];
      const double dy = points[a * d + 1] - points[b * d + 1];
      if (owner[b] != process_rank() && dx * dx + dy * dy < reach * reach) {
        ++needed;
        missing += ghosts.count(b) == 0 ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(missing, 0U);
  const std::int64_t all_needed = sum_over_processes(static_cast<std::int64_t>(needed));
  if (process_count() == 1) {
    EXPECT_EQ(plan.ghost_count(), 0U);
    EXPECT_EQ(all_needed, 0);
  } else {
    EXPECT_GT(all_needed, 0);
  }
}

} // namespace
