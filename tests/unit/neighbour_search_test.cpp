// The cell-list neighbour search against brute force, and its independence of the cell size,
// the storage order and the thread count.

#include "core/cell_list.hpp"
#include "core/neighbour_list.hpp"
#include "core/threads.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace {

using revsph::Box;
using revsph::CellList;
using revsph::CoordinateArrays;
using revsph::NeighbourList;
using revsph::SelfPairs;

template <int D>
CoordinateArrays<D> random_points(std::size_t n, const Box<D>& box, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  CoordinateArrays<D> points;
  for (int k = 0; k < D; ++k) {
    std::uniform_real_distribution<double> coordinate(box.min[k], box.max[k]);
    points[k].resize(n);
    for (double& x : points[k]) {
      x = coordinate(rng);
    }
  }
  // Some exact duplicates and points on the domain boundary, the corner cases of a cell list.
  for (int k = 0; k < D; ++k) {
    points[k][1] = points[k][0];
    points[k][2] = box.max[k];
    points[k][3] = box.min[k];
  }
  return points;
}

template <int D>
NeighbourList cell_list_neighbours(const CoordinateArrays<D>& targets,
                                   const CoordinateArrays<D>& queries, const Box<D>& domain,
                                   double radius, double cell_size, SelfPairs self_pairs) {
  CellList<D> cells(domain, cell_size, 1 << 22);
  cells.build(revsph::view_of<D>(targets));
  NeighbourList list;
  revsph::find_neighbours<D>(cells, revsph::view_of<D>(targets), revsph::view_of<D>(queries),
                             radius, self_pairs, list);
  return list;
}

void expect_same(const NeighbourList& expected, const NeighbourList& actual) {
  ASSERT_EQ(expected.query_count(), actual.query_count());
  for (std::size_t a = 0; a < expected.query_count(); ++a) {
    const auto e = expected.of(a);
    const auto f = actual.of(a);
    ASSERT_TRUE(std::equal(e.begin(), e.end(), f.begin(), f.end())) << "query " << a;
  }
}

template <int D>
void check_against_brute_force(std::size_t n, double radius, std::uint64_t seed) {
  Box<D> domain;
  domain.min.fill(-1.0);
  domain.max.fill(2.0);
  const auto points = random_points<D>(n, domain, seed);
  const auto reference = revsph::find_neighbours_brute_force<D>(
      revsph::view_of<D>(points), revsph::view_of<D>(points), radius, SelfPairs::excluded);
  ASSERT_GT(reference.pair_count(), n) << "the test needs points with several neighbours";
  for (const double factor : {1.0, 1.37, 2.5}) {
    expect_same(reference, cell_list_neighbours<D>(points, points, domain, radius, factor * radius,
                                                   SelfPairs::excluded));
  }
  // Queries against another point set, self pairs included (the fluid-wall search).
  const auto others = random_points<D>(n / 3, domain, seed + 1);
  expect_same(revsph::find_neighbours_brute_force<D>(revsph::view_of<D>(others),
                                                     revsph::view_of<D>(points), radius,
                                                     SelfPairs::included),
              cell_list_neighbours<D>(others, points, domain, radius, radius, SelfPairs::included));
}

TEST(NeighbourSearch, MatchesBruteForceIn1D) {
  check_against_brute_force<1>(3000, 0.002, 1);
  check_against_brute_force<1>(200, 0.05, 2);
}

TEST(NeighbourSearch, MatchesBruteForceIn2D) {
  check_against_brute_force<2>(3000, 0.12, 1);
  check_against_brute_force<2>(500, 0.4, 2);
}

TEST(NeighbourSearch, MatchesBruteForceIn3D) {
  check_against_brute_force<3>(3000, 0.3, 3);
  check_against_brute_force<3>(400, 0.7, 4);
}

template <int D>
void check_storage_order_independence() {
  Box<D> domain;
  domain.min.fill(0.0);
  domain.max.fill(1.0);
  const std::size_t n = 2000;
  const auto points = random_points<D>(n, domain, 9);
  const double radius = D == 2 ? 0.06 : 0.15;
  const auto reference =
      cell_list_neighbours<D>(points, points, domain, radius, radius, SelfPairs::excluded);
  // Store the same points in a shuffled order; map the results back through the permutation.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(10));
  CoordinateArrays<D> shuffled;
  for (int k = 0; k < D; ++k) {
    shuffled[k].resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      shuffled[k][i] = points[k][order[i]];
    }
  }
  const auto permuted =
      cell_list_neighbours<D>(shuffled, shuffled, domain, radius, radius, SelfPairs::excluded);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::uint32_t> mapped;
    for (const std::uint32_t j : permuted.of(i)) {
      mapped.push_back(order[j]);
    }
    std::sort(mapped.begin(), mapped.end());
    const auto expected = reference.of(order[i]);
    ASSERT_TRUE(std::equal(expected.begin(), expected.end(), mapped.begin(), mapped.end()));
  }
}

TEST(NeighbourSearch, DoesNotDependOnStorageOrder) {
  check_storage_order_independence<2>();
  check_storage_order_independence<3>();
}

TEST(NeighbourSearch, DoesNotDependOnThreadCount) {
  Box<2> domain{{0.0, 0.0}, {1.0, 1.0}};
  const auto points = random_points<2>(20000, domain, 12);
  const int threads = revsph::thread_count();
  revsph::set_thread_count(1);
  const auto one = cell_list_neighbours<2>(points, points, domain, 0.02, 0.02, SelfPairs::excluded);
  revsph::set_thread_count(2);
  const auto two = cell_list_neighbours<2>(points, points, domain, 0.02, 0.02, SelfPairs::excluded);
  revsph::set_thread_count(threads);
  EXPECT_EQ(one.offsets, two.offsets);
  EXPECT_EQ(one.indices, two.indices);
}

TEST(CellList, RejectsAPointOutsideTheDomain) {
  Box<2> domain{{0.0, 0.0}, {1.0, 1.0}};
  CoordinateArrays<2> points{{{0.5, 0.2, 1.2}, {0.5, 0.3, 0.5}}};
  CellList<2> cells(domain, 0.1, 1000);
  try {
    cells.build(revsph::view_of<2>(points));
    FAIL() << "expected PointOutsideDomain";
  } catch (const revsph::PointOutsideDomain& outside) {
    EXPECT_EQ(outside.index(), 2u);
  }
  points[0][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(cells.build(revsph::view_of<2>(points)), revsph::PointOutsideDomain);
}

TEST(CellList, LimitsTheNumberOfCellsOfAHugeDomain) {
  Box<3> domain{{0.0, 0.0, 0.0}, {1000.0, 1000.0, 1000.0}};
  CellList<3> cells(domain, 0.01, 100000);
  EXPECT_LE(cells.cell_count(), 100000u);
  EXPECT_GE(cells.cell_size(), 0.01);
}

} // namespace
