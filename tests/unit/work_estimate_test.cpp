// The partition's estimate of each particle's work (core/distributed/work_estimate.hpp) against
// neighbours counted directly: a square lattice of unit spacing, reach 3, where a particle has 28
// neighbours within the reach (the estimate counts a particle itself
// among them); a fixed particle counts its moving neighbours only, and one with
// none costs its own update alone.

#include "core/distributed/work_estimate.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using revsph::distributed::estimated_work;

TEST(WorkEstimate, InteriorParticleOfALatticeCountsItsNeighbours) {
  std::vector<double> points;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      points.push_back(i + 0.5);
      points.push_back(j + 0.5);
    }
  }
  const std::vector<unsigned char> moving(points.size() / 2, 1);
  const std::vector<float> work = estimated_work(points, moving, moving.size(), 2, 3.0);
  const float interior = work[15 * 30 + 15];
  // Own update (3) plus half the 28 neighbours: 17; the grid of cells estimates 17.1.
  EXPECT_NEAR(interior, 3.0 + 0.5 * 28, 0.1 * (3.0 + 0.5 * 28));
  // A corner has a quarter of the neighbours (the cells count 36 of the interior's 81).
  EXPECT_LT(work[0] - 3.0F, 0.5F * (interior - 3.0F));
}

TEST(WorkEstimate, FixedParticleCountsMovingNeighboursOnly) {
  // Particle 0 fixed, among fixed particles 1-3 and moving 4-5; particle 6 fixed, far away.
  const std::vector<double> points = {0.5, 0.5, 1.5, 0.5, 0.5, 1.5,  1.5,
                                      1.5, 2.5, 0.5, 0.5, 2.5, 50.5, 50.5};
  const std::vector<unsigned char> moving = {0, 0, 0, 0, 1, 1, 0};
  const std::vector<float> work = estimated_work(points, moving, moving.size(), 2, 3.0);
  const float per_neighbour = 0.5F * 3.14159265F / 9.0F;
  EXPECT_NEAR(work[0], 3.0F + 2 * per_neighbour, 1e-5);
  EXPECT_NEAR(work[4], 3.0F + 6 * per_neighbour, 1e-5); // moving: every particle around
  EXPECT_NEAR(work[6], 3.0F, 1e-6);
}

TEST(WorkEstimate, GhostsCountAsNeighboursWithoutWeights) {
  const std::vector<double> points = {0.5, 0.5, 1.5, 0.5};
  const std::vector<unsigned char> moving = {1, 1};
  const std::vector<float> own_only = estimated_work(points, moving, 1, 2, 3.0);
  ASSERT_EQ(own_only.size(), 1U);
  EXPECT_NEAR(own_only[0], 3.0F + 2 * 0.5F * 3.14159265F / 9.0F, 1e-5);
}

} // namespace
