// The partition of space among the processes (core/distributed/spatial_partition.hpp), for both
// of Zoltan's methods in 2D and 3D, on whatever number of processes CTest starts (1, 2, 3):
// every particle gets one owner, the one owner_of names; the counts are balanced; and the ghost
// rule is complete: for every pair closer than the reach whose particles have different owners,
// each particle is needed as a ghost by the other's owner (processes_near), so that owner can
// form the pair.

#include "core/distributed/processes.hpp"
#include "core/distributed/spatial_partition.hpp"
#include "process_share.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using revsph::distributed::PartitionMethod;
using revsph::distributed::process_count;
using revsph::distributed::process_rank;
using revsph::distributed::SpatialPartition;

// Every process makes the same points (process_share.hpp splits them).
std::vector<double> all_points(int dimension, std::size_t count) {
  std::mt19937_64 generator(2024);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> points(count * static_cast<std::size_t>(dimension));
  for (std::size_t i = 0; i < points.size(); ++i) {
    // A column twice as tall as wide: the cuts must not all be vertical.
    points[i] = uniform(generator) * ((i % static_cast<std::size_t>(dimension)) == 1 ? 2.0 : 1.0);
  }
  return points;
}

class Partition : public ::testing::TestWithParam<std::tuple<int, PartitionMethod>> {};

TEST_P(Partition, OwnsEachParticleOnceBalancedAndListsEveryGhost) {
  const auto [dimension, method] = GetParam();
  const std::size_t d = static_cast<std::size_t>(dimension);
  const std::size_t count = dimension == 2 ? 3000 : 4000;
  const double reach = dimension == 2 ? 0.06 : 0.15;
  const std::vector<double> points = all_points(dimension, count);
  const ProcessShare share = round_robin_share(points, d);
  const std::vector<double>& mine = share.coordinates;
  const std::vector<std::uint64_t>& my_indices = share.indices;
  SpatialPartition partition(dimension, method);
  const std::vector<int> owners = partition.balance(mine, my_indices);
  // No ASSERT before the last collective call: a process that returned early would leave the
  // others waiting in it.
  EXPECT_EQ(owners.size(), my_indices.size());
  std::size_t disagreeing = 0;
  for (std::size_t j = 0; j < std::min(owners.size(), my_indices.size()); ++j) {
    disagreeing += partition.owner_of({mine.data() + j * d, d}) != owners[j] ? 1 : 0;
  }
  EXPECT_EQ(disagreeing, 0U);
  // Every process can name every point's owner from the kept cuts.
  std::vector<int> owner(count);
  std::vector<std::int64_t> owned(static_cast<std::size_t>(process_count()), 0);
  for (std::size_t i = 0; i < count; ++i) {
    owner[i] = std::clamp(partition.owner_of({points.data() + i * d, d}), 0, process_count() - 1);
    ++owned[static_cast<std::size_t>(owner[i])];
  }
  const double fair = static_cast<double>(count) / process_count();
  for (const std::int64_t n : owned) {
    EXPECT_LT(std::abs(static_cast<double>(n) - fair), 0.02 * fair + 2.0);
  }
  // Completeness of the ghosts, pair by pair (each process checks the pairs of its own points).
  std::vector<int> near;
  std::size_t split_pairs = 0;
  for (std::size_t j = 0; j < my_indices.size(); ++j) {
    const std::size_t a = my_indices[j];
    partition.processes_near({points.data() + a * d, d}, reach, owner[a], near);
    EXPECT_EQ(std::count(near.begin(), near.end(), owner[a]), 0);
    for (std::size_t b = 0; b < count; ++b) {
      double squared = 0.0;
      for (std::size_t k = 0; k < d; ++k) {
        const double delta = points[a * d + k] - points[b * d + k];
        squared += delta * delta;
      }
      if (b != a && squared < reach * reach && owner[b] != owner[a]) {
        ++split_pairs;
        EXPECT_NE(std::find(near.begin(), near.end(), owner[b]), near.end())
            << "particle " << a << " is not sent to the owner of its neighbour " << b;
      }
    }
  }
  const auto total_split =
      revsph::distributed::sum_over_processes(static_cast<std::int64_t>(split_pairs));
  if (process_count() > 1) {
    EXPECT_GT(total_split, 0); // the check above was not empty
  } else {
    EXPECT_EQ(total_split, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(DimensionsAndMethods, Partition,
                         ::testing::Combine(::testing::Values(2, 3),
                                            ::testing::Values(PartitionMethod::coordinate_bisection,
                                                              PartitionMethod::hilbert_curve)),
                         [](const auto& parameters) {
                           return std::to_string(std::get<0>(parameters.param)) + "d_" +
                                  revsph::distributed::to_string(std::get<1>(parameters.param));
                         });

} // namespace
