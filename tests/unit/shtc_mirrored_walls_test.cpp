// Mirrored no-slip walls of SHTC-SPH (models/shtc/mirrored_walls.hpp): a wall particle shows the
// material 2 v_w minus the Shepard average of the fluid's velocity around it — exactly that for a
// uniform flow, odd in all velocities bit for bit, the same bits for any thread count, and v_w
// where no fluid is in reach.

#include "core/threads.hpp"
#include "models/shtc/mirrored_walls.hpp"

#include "cell_ordered_cloud.hpp"
#include "dimensions.hpp"
#include "shtc_sums.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <random>

namespace {

using revsph::CoordinateArrays;
using revsph::testing::Cloud;
using revsph::testing::jittered_lattice;

// The lowest rows (last coordinate below 0.15, about two rows of the lattice) are the wall.
template <int D>
std::vector<std::uint8_t> lowest_rows_are_walls(const Cloud<D>& cloud) {
  std::vector<std::uint8_t> is_wall;
  for (const double height : cloud.x[D - 1]) {
    is_wall.push_back(height < 0.15);
  }
  return is_wall;
}

template <int D>
CoordinateArrays<D> mirrored(const Cloud<D>& cloud, const std::vector<std::uint8_t>& is_wall,
                             CoordinateArrays<D> velocity) {
  const revsph::WendlandQuintic<D> kernel(cloud.support);
  return revsph::testing::mirrored_velocities<D>(kernel, cloud.x, cloud.mass, is_wall, velocity);
}

// Random fluid velocities; the walls' own velocity is (0.3, ...) along the wall.
template <int D>
CoordinateArrays<D> random_velocity(const std::vector<std::uint8_t>& is_wall, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> speed(0.0, 1.0);
  CoordinateArrays<D> v;
  for (int k = 0; k < D; ++k) {
    for (std::size_t a = 0; a < is_wall.size(); ++a) {
      v[k].push_back(is_wall[a] ? (k == 0 ? 0.3 : 0.0) : speed(rng));
    }
  }
  return v;
}

template <int D>
void expect_same_bits(const CoordinateArrays<D>& expected, const CoordinateArrays<D>& actual,
                      double sign) {
  for (int k = 0; k < D; ++k) {
    ASSERT_EQ(expected[k].size(), actual[k].size());
    for (std::size_t a = 0; a < expected[k].size(); ++a) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(actual[k][a]),
                std::bit_cast<std::uint64_t>(sign * expected[k][a]))
          << "slot " << a << ", component " << k;
    }
  }
}

REVSPH_DIMENSION_TEST_SUITE(ShtcMirroredWalls);

TYPED_TEST(ShtcMirroredWalls, ShowTwiceTheWallVelocityMinusAUniformFlow) {
  constexpr int D = TypeParam::value;
  const Cloud<D> cloud = jittered_lattice<D>(D == 2 ? 16 : 7, 11);
  const auto is_wall = lowest_rows_are_walls<D>(cloud);
  CoordinateArrays<D> v;
  for (int k = 0; k < D; ++k) {
    for (std::size_t a = 0; a < is_wall.size(); ++a) {
      v[k].push_back(is_wall[a] ? 0.25 * (k + 1) : 1.0 - 0.5 * k);
    }
  }
  const CoordinateArrays<D> shown = mirrored<D>(cloud, is_wall, v);
  int walls = 0;
  for (std::size_t a = 0; a < is_wall.size(); ++a) {
    for (int k = 0; k < D; ++k) {
      const double expected = is_wall[a] ? 2.0 * 0.25 * (k + 1) - (1.0 - 0.5 * k) : v[k][a];
      // Exact sums round each of the ~30 terms of a wall particle once, to 2^-42 (weights) and
      // 2^-43 (weighted velocities; test_sum_scales): a few 1e-14 of the quotient at weight ~50.
      EXPECT_NEAR(shown[k][a], expected, 1e-12) << "slot " << a;
    }
    walls += is_wall[a];
  }
  EXPECT_GT(walls, 0);
}

TYPED_TEST(ShtcMirroredWalls, AreOddInTheVelocitiesBitForBit) {
  constexpr int D = TypeParam::value;
  const Cloud<D> cloud = jittered_lattice<D>(D == 2 ? 16 : 7, 12);
  const auto is_wall = lowest_rows_are_walls<D>(cloud);
  const CoordinateArrays<D> v = random_velocity<D>(is_wall, 13);
  CoordinateArrays<D> reversed = v;
  for (int k = 0; k < D; ++k) {
    for (double& component : reversed[k]) {
      component = -component;
    }
  }
  expect_same_bits<D>(mirrored<D>(cloud, is_wall, v), mirrored<D>(cloud, is_wall, reversed), -1.0);
}

TYPED_TEST(ShtcMirroredWalls, AreTheSameForAnyThreadCount) {
  constexpr int D = TypeParam::value;
  const Cloud<D> cloud = jittered_lattice<D>(D == 2 ? 30 : 10, 14);
  const auto is_wall = lowest_rows_are_walls<D>(cloud);
  const CoordinateArrays<D> v = random_velocity<D>(is_wall, 15);
  revsph::set_thread_count(1);
  const CoordinateArrays<D> one = mirrored<D>(cloud, is_wall, v);
  revsph::set_thread_count(2);
  expect_same_bits<D>(one, mirrored<D>(cloud, is_wall, v), 1.0);
}

TEST(ShtcMirroredWallsSetup, AWallOutOfTheFluidsReachKeepsItsVelocity) {
  const Cloud<2> cloud = revsph::testing::two_isolated_points();
  const std::vector<std::uint8_t> is_wall{1, 0};
  const CoordinateArrays<2> v{std::vector<double>{0.5, 2.0}, std::vector<double>{-0.5, 3.0}};
  const CoordinateArrays<2> shown = mirrored<2>(cloud, is_wall, v);
  EXPECT_EQ(shown[0][0], 0.5);
  EXPECT_EQ(shown[1][0], -0.5);
  EXPECT_EQ(shown[0][1], 2.0);
}

} // namespace
