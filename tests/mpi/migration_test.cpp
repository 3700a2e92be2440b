// Particles moving to their new owners (core/distributed/migration.hpp) on whatever number of
// processes CTest starts (1, 2, 3): every particle ends on the process it was sent to, exactly
// once, its rows intact (two fields of different widths and types), and each process holds its
// particles in global-index order.

#include "core/distributed/migration.hpp"
#include "core/distributed/processes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using namespace revsph::distributed;

// Particle i's values, computable by any process: its field rows are functions of i.
std::int64_t raw_value(std::uint64_t i, std::size_t j) {
  return static_cast<std::int64_t>(i * 1000003U + j * 7U) - 5000000;
}
double real_value(std::uint64_t i) {
  return static_cast<double>(i) * 0.125 - 3.0;
}
int new_owner(std::uint64_t i) {
  return static_cast<int>((i * 2654435761U) % static_cast<std::uint64_t>(process_count()));
}

TEST(Migration, EveryParticleReachesItsOwnerOnceInIndexOrder) {
  constexpr std::uint64_t count = 3001;
  constexpr std::size_t width = 3;
  // Each process starts with a shuffled share of the particles.
  std::vector<std::uint64_t> indices;
  for (std::uint64_t i = 0; i < count; ++i) {
    if (static_cast<int>(i % static_cast<std::uint64_t>(process_count())) == process_rank()) {
      indices.push_back(i);
    }
  }
  std::shuffle(indices.begin(), indices.end(), std::mt19937_64(7 + process_rank()));
  std::vector<std::int64_t> raws;
  std::vector<double> reals;
  std::vector<int> owners;
  for (const std::uint64_t i : indices) {
    for (std::size_t j = 0; j < width; ++j) {
      raws.push_back(raw_value(i, j));
    }
    reals.push_back(real_value(i));
    owners.push_back(new_owner(i));
  }
  const Migration migration(owners, indices);
  const std::vector<std::int64_t> moved_raws =
      migration.move(std::span<const std::int64_t>(raws), width);
  const std::vector<double> moved_reals = migration.move(std::span<const double>(reals), 1);
  const std::vector<std::uint64_t>& after = migration.global_indices_after();
  EXPECT_EQ(after.size(), migration.count_after());
  EXPECT_TRUE(std::is_sorted(after.begin(), after.end()));
  std::size_t wrong = 0;
  for (std::size_t n = 0; n < std::min(after.size(), moved_reals.size()); ++n) {
    wrong += new_owner(after[n]) != process_rank() ? 1 : 0;
    wrong += moved_reals[n] != real_value(after[n]) ? 1 : 0;
    for (std::size_t j = 0; j < width; ++j) {
      wrong += moved_raws[n * width + j] != raw_value(after[n], j) ? 1 : 0;
    }
  }
  EXPECT_EQ(wrong, 0U);
  std::uint64_t mine = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    mine += new_owner(i) == process_rank() ? 1 : 0;
  }
  EXPECT_EQ(after.size(), mine);
  EXPECT_EQ(sum_over_processes(static_cast<std::int64_t>(after.size())),
            static_cast<std::int64_t>(count));
  if (process_count() == 1) {
    EXPECT_EQ(migration.moved_count(), 0);
  }
}

} // namespace
