// NeighbourRows against the brute-force neighbour search: each row's movable neighbours (itself
// excluded), then its fixed ones, ascending, with separations and distances bit for bit, in 1D,
// 2D and 3D, before and after the movable points move.

#include "core/neighbour_list.hpp"
#include "core/neighbour_rows.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace revsph {
namespace {

// n points uniform in the box [0, 1]^D, with point 1 on top of point 0 (a zero distance).
template <int D>
CoordinateArrays<D> scattered(std::size_t n, std::mt19937_64& engine) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CoordinateArrays<D> points;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      points[k].push_back(i == 1 ? points[k][0] : unit(engine));
    }
  }
  return points;
}

// What one row visit saw.
template <int D>
struct VisitedRow {
  std::vector<std::uint32_t> movable;
  std::vector<std::uint32_t> fixed;
  bool exact = true; // every separation and distance as computed directly
};

template <int D>
bool exact(const CoordinateView<D>& rows, std::size_t a, const CoordinateView<D>& others,
           const RowNeighbour<D>& neighbour) {
  Vec<D> separation{};
  const double distance =
      std::sqrt(squared_distance<D>(rows, a, others, neighbour.index, separation));
  return separation == neighbour.separation && distance == neighbour.distance;
}

template <int D>
std::vector<VisitedRow<D>> visit_rows(const NeighbourRows<D>& rows,
                                      const CoordinateView<D>& movable,
                                      const CoordinateView<D>& fixed) {
  std::vector<VisitedRow<D>> visited(rows.row_count());
  rows.for_each_row([&](std::size_t a, const NeighbourRow<D>& row) {
    VisitedRow<D>& seen = visited[a];
    row.for_each_movable([&](const RowNeighbour<D>& b) {
      seen.movable.push_back(b.index);
      seen.exact = seen.exact && exact<D>(movable, a, movable, b);
    });
    row.for_each_fixed([&](const RowNeighbour<D>& f) {
      seen.fixed.push_back(f.index);
      seen.exact = seen.exact && exact<D>(movable, a, fixed, f);
    });
  });
  return visited;
}

template <int D>
void expect_rows_as_brute_force(const NeighbourRows<D>& rows, const CoordinateArrays<D>& movable,
                                const CoordinateArrays<D>& fixed, double radius) {
  const CoordinateView<D> movable_view = view_of<D>(movable);
  const CoordinateView<D> fixed_view = view_of<D>(fixed);
  const NeighbourList of_movable =
      find_neighbours_brute_force<D>(movable_view, movable_view, radius, SelfPairs::excluded);
  const NeighbourList of_fixed =
      find_neighbours_brute_force<D>(fixed_view, movable_view, radius, SelfPairs::included);
  ASSERT_GT(of_movable.pair_count(), movable[0].size()) << "the test needs several neighbours";
  ASSERT_GT(of_fixed.pair_count(), 0u);
  ASSERT_EQ(rows.row_count(), movable[0].size());
  EXPECT_EQ(rows.movable_pair_count(), of_movable.pair_count());
  const std::vector<VisitedRow<D>> visited = visit_rows<D>(rows, movable_view, fixed_view);
  for (std::size_t a = 0; a < rows.row_count(); ++a) {
    const auto movable_expected = of_movable.of(a);
    const auto fixed_expected = of_fixed.of(a);
    EXPECT_EQ(visited[a].movable,
              std::vector<std::uint32_t>(movable_expected.begin(), movable_expected.end()))
        << "row " << a;
    EXPECT_EQ(visited[a].fixed,
              std::vector<std::uint32_t>(fixed_expected.begin(), fixed_expected.end()))
        << "row " << a;
    EXPECT_EQ(rows.movable_neighbour_count(a), movable_expected.size()) << "row " << a;
    EXPECT_TRUE(visited[a].exact) << "row " << a;
  }
}

template <int D>
void check_dimension(std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  // About 12 neighbours per point: the radius holds 12 / n of the unit box's volume.
  const std::size_t n = 300;
  const double radius = std::pow(12.0 / n, 1.0 / D);
  CoordinateArrays<D> movable = scattered<D>(n, engine);
  const CoordinateArrays<D> fixed = scattered<D>(n / 4, engine);
  Box<D> domain;
  domain.min.fill(-0.5);
  domain.max.fill(1.5);
  NeighbourRows<D> rows(domain, radius, n, view_of<D>(fixed));
  rows.update(view_of<D>(movable));
  expect_rows_as_brute_force<D>(rows, movable, fixed, radius);
  // Move every point and update: the rows follow.
  const CoordinateArrays<D> shift = scattered<D>(n, engine);
  for (int k = 0; k < D; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      movable[k][i] += 0.3 * (shift[k][i] - 0.5);
    }
  }
  rows.update(view_of<D>(movable));
  expect_rows_as_brute_force<D>(rows, movable, fixed, radius);
}

TEST(NeighbourRows, MatchBruteForceIn1D) {
  check_dimension<1>(3);
}

TEST(NeighbourRows, MatchBruteForceIn2D) {
  check_dimension<2>(5);
}

TEST(NeighbourRows, MatchBruteForceIn3D) {
  check_dimension<3>(7);
}

} // namespace
} // namespace revsph
