// The pairs of particles closer than a distance (core/close_pairs.hpp), against every pair
// (O(N^2)) with the nearest periodic image on random point sets in 1D, 2D and 3D, with and
// without periodic axes and fixed points: the same count, for any thread count; fixed-fixed pairs
// never count.

#include "core/close_pairs.hpp"

#include "core/threads.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace revsph {
namespace {

template <int D>
CoordinateArrays<D> random_points(std::size_t n, const PeriodicBox& box, unsigned seed) {
  std::mt19937_64 rng(seed);
  CoordinateArrays<D> points;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      points[k].push_back(std::uniform_real_distribution<double>(box.min[k], box.max[k])(rng));
    }
  }
  return points;
}

// Every pair, each axis's separation through the nearest image on a periodic one.
template <int D>
std::uint64_t brute_force(const CoordinateArrays<D>& points, std::size_t moving, double distance,
                          const PeriodicBox& box) {
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < points[0].size(); ++i) {
    for (std::size_t j = i + 1; j < points[0].size(); ++j) {
      if (i >= moving && j >= moving) {
        continue; // both fixed
      }
      double squared = 0.0;
      for (int k = 0; k < D; ++k) {
        double d = std::fabs(points[k][i] - points[k][j]);
        if (box.periodic[k]) {
          d = std::min(d, box.length(k) - d);
        }
        squared += d * d;
      }
      count += squared < distance * distance ? 1 : 0;
    }
  }
  return count;
}

template <int D>
void expect_as_brute_force(std::size_t n, double distance, const std::string& periodic) {
  PeriodicBox box;
  for (int k = 0; k < D; ++k) {
    box.min[k] = -0.5;
    box.max[k] = 0.5 + 0.25 * k;
    box.periodic[k] = periodic.find(static_cast<char>('x' + k)) != std::string::npos;
  }
  std::uint64_t pairs_seen = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const CoordinateArrays<D> points = random_points<D>(n, box, seed);
    for (const std::size_t moving : {n, n / 2, std::size_t{1}}) {
      const std::uint64_t expected = brute_force<D>(points, moving, distance, box);
      pairs_seen += expected;
      for (const int threads : {1, 2}) {
        set_thread_count(threads);
        EXPECT_EQ(count_close_pairs<D>(view_of<D>(points), moving, distance, box), expected)
            << "seed " << seed << ", " << moving << " moving, " << threads << " threads";
      }
    }
  }
  EXPECT_GT(pairs_seen, 0u) << "no close pair to count: the test checks nothing";
}

TEST(ClosePairs, AsEveryPairIn1D) {
  expect_as_brute_force<1>(300, 0.002, "");
  expect_as_brute_force<1>(300, 0.002, "x");
}

TEST(ClosePairs, AsEveryPairIn2D) {
  // 600 points in about a unit square, pairs closer than 0.01: a few dozen, some across faces.
  expect_as_brute_force<2>(600, 0.01, "");
  expect_as_brute_force<2>(600, 0.01, "x");
  expect_as_brute_force<2>(600, 0.01, "xy");
}

TEST(ClosePairs, AsEveryPairIn3D) {
  expect_as_brute_force<3>(800, 0.04, "");
  expect_as_brute_force<3>(800, 0.04, "xyz");
}

TEST(ClosePairs, APairAcrossAPeriodicFaceCountsOnce) {
  PeriodicBox box;
  box.periodic = {true, false, false};
  box.min = {0.0, 0.0, 0.0};
  box.max = {1.0, 1.0, 0.0};
  // 0.002 apart through the face x = 0 = 1, and a third point far from both.
  CoordinateArrays<2> points{std::vector<double>{0.001, 0.999, 0.5},
                             std::vector<double>{0.5, 0.5, 0.5}};
  EXPECT_EQ(count_close_pairs<2>(view_of<2>(points), 3, 0.01, box), 1u);
  EXPECT_EQ(count_close_pairs<2>(view_of<2>(points), 3, 0.001, box), 0u);
  EXPECT_EQ(count_close_pairs<2>(view_of<2>(points), 3, 0.01, PeriodicBox{}), 0u);
}

TEST(ClosePairs, FixedPairsDoNotCount) {
  // Two fixed points at the same place, a moving one 0.005 from the first.
  CoordinateArrays<2> points{std::vector<double>{0.5, 0.0, 0.0},
                             std::vector<double>{0.505, 0.5, 0.5}};
  EXPECT_EQ(count_close_pairs<2>(view_of<2>(points), 1, 0.01, PeriodicBox{}), 0u);
  points[0][0] = 0.0;
  EXPECT_EQ(count_close_pairs<2>(view_of<2>(points), 1, 0.01, PeriodicBox{}), 2u);
  EXPECT_EQ(count_close_pairs<2>(view_of<2>(points), 0, 0.01, PeriodicBox{}), 0u);
}

} // namespace
} // namespace revsph
