// The smallest distance between two particles, not both fixed (core/smallest_distance.hpp),
// against every pair (O(N^2)) on random point sets in 2D and 3D: the same bits when it is within
// the cell size; no less than the true one beyond; fixed-fixed pairs never count.

#include "core/smallest_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace revsph {
namespace {

template <int D>
CoordinateArrays<D> random_points(std::size_t n, double side, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(0.0, side);
  CoordinateArrays<D> points;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      points[k].push_back(coordinate(rng));
    }
  }
  return points;
}

template <int D>
double brute_force(const CoordinateArrays<D>& points, std::size_t moving) {
  const CoordinateView<D> view = view_of<D>(points);
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points[0].size(); ++i) {
    for (std::size_t j = i + 1; j < points[0].size(); ++j) {
      if (i >= moving && j >= moving) {
        continue; // both fixed
      }
      smallest = std::min(smallest, std::sqrt(squared_distance<D>(view, i, j)));
    }
  }
  return smallest;
}

template <int D>
void expect_as_brute_force(std::size_t n, double side, double cell_size) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const CoordinateArrays<D> points = random_points<D>(n, side, seed);
    for (const std::size_t moving : {n, n / 2, std::size_t{1}}) {
      const double expected = brute_force<D>(points, moving);
      const double found = smallest_distance<D>(view_of<D>(points), moving, cell_size);
      if (expected <= cell_size) {
        EXPECT_EQ(found, expected) << "seed " << seed << ", " << moving << " moving";
      } else {
        EXPECT_GE(found, expected) << "seed " << seed << ", " << moving << " moving";
      }
    }
  }
}

TEST(SmallestDistance, AsEveryPairIn2D) {
  // 400 points in a unit square: about 0.05 apart on average, the closest pair much closer.
  expect_as_brute_force<2>(400, 1.0, 0.05);
}

TEST(SmallestDistance, AsEveryPairIn3D) {
  expect_as_brute_force<3>(500, 1.0, 0.1);
}

TEST(SmallestDistance, FixedPairsDoNotCount) {
  // Two fixed points 0.01 apart, a moving one 0.5 from both.
  CoordinateArrays<2> points{std::vector<double>{0.5, 0.0, 0.01},
                             std::vector<double>{0.5, 0.0, 0.0}};
  const double found = smallest_distance<2>(view_of<2>(points), 1, 1.0);
  EXPECT_DOUBLE_EQ(found, std::sqrt(0.49 * 0.49 + 0.5 * 0.5));
  EXPECT_EQ(smallest_distance<2>(view_of<2>(points), 0, 1.0),
            std::numeric_limits<double>::infinity());
}

TEST(SmallestDistance, SparsePointsGiveNoLessThanTheTruth) {
  // Cells far smaller than the spacing: the pairs in neighbouring cells, if any, or none.
  const CoordinateArrays<2> points = random_points<2>(50, 1.0, 7);
  const double found = smallest_distance<2>(view_of<2>(points), 50, 1e-3);
  EXPECT_GE(found, brute_force<2>(points, 50));
}

} // namespace
} // namespace revsph
