// The half pair list over cell-ordered points against brute force; the striped parallel pair loop
// (no lost updates, floating-point sums independent of the thread count); the per-particle exact
// sums and their overflow detection.

#include "core/arithmetic.hpp"
#include "core/cell_list.hpp"
#include "core/pair_list.hpp"
#include "core/pair_sums.hpp"
#include "core/threads.hpp"

#include "cell_ordered_cloud.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using revsph::Box;
using revsph::CellList;
using revsph::CoordinateArrays;
using revsph::HalfPairList;

template <int D>
struct CellOrdered {
  CellList<D> cells;
  CoordinateArrays<D> slot_points;
};

// Random points (clustered in one corner, so cells are unequally full, with exact duplicates and
// points on the domain boundary), put in cell order.
template <int D>
CellOrdered<D> cell_ordered_points(std::size_t n, const Box<D>& box, double cell_size,
                                   std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  CoordinateArrays<D> points;
  for (int k = 0; k < D; ++k) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    points[k].resize(n);
    for (double& x : points[k]) {
      const double u = unit(rng);
      x = box.min[k] + (box.max[k] - box.min[k]) * u * u;
    }
    points[k][1] = points[k][0];
    points[k][2] = box.max[k];
    points[k][3] = box.min[k];
  }
  CellOrdered<D> result{CellList<D>(box, cell_size, 1 << 22), {}};
  result.cells.build(revsph::view_of<D>(points));
  result.slot_points = revsph::testing::in_cell_order<D>(result.cells, points);
  return result;
}

template <int D>
std::set<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const CoordinateArrays<D>& x,
                                                                    double radius) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const std::size_t n = x[0].size();
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = x[k][a] - x[k][b];
        r_squared += d * d;
      }
      if (r_squared < radius * radius) {
        pairs.emplace(a, b);
      }
    }
  }
  return pairs;
}

template <int D>
void expect_brute_force_pairs(std::size_t n, double radius, double cell_size, std::uint64_t seed) {
  Box<D> box;
  for (int k = 0; k < D; ++k) {
    box.min[k] = -0.5;
    box.max[k] = 0.5 + 0.3 * k;
  }
  const CellOrdered<D> points = cell_ordered_points<D>(n, box, cell_size, seed);
  HalfPairList pairs;
  pairs.build<D>(points.cells, revsph::view_of<D>(points.slot_points), radius);

  std::set<std::pair<std::uint32_t, std::uint32_t>> listed;
  std::size_t listed_count = 0;
  std::size_t slots_seen = 0;
  for (const HalfPairList::Stripe& stripe : pairs.stripes()) {
    ASSERT_EQ(stripe.first_slot, slots_seen) << "stripes must tile the slots in order";
    slots_seen += stripe.slot_count;
    for (std::uint32_t local = 0; local < stripe.slot_count; ++local) {
      const std::uint32_t a = stripe.first_slot + local;
      std::uint32_t previous = a;
      for (std::uint32_t i = stripe.offsets[local]; i < stripe.offsets[local + 1]; ++i) {
        const std::uint32_t b = stripe.partners[i];
        EXPECT_GT(b, previous) << "partners of " << a << " must be ascending and above it";
        previous = b;
        listed.emplace(a, b);
        ++listed_count;
      }
    }
  }
  EXPECT_EQ(slots_seen, n);
  EXPECT_EQ(listed_count, listed.size()) << "a pair is listed twice";
  EXPECT_EQ(listed_count, pairs.pair_count());
  EXPECT_EQ(listed, brute_force_pairs<D>(points.slot_points, radius));
}

TEST(HalfPairList, MatchesBruteForceIn1D) {
  expect_brute_force_pairs<1>(3000, 0.002, 0.002, 1);
  expect_brute_force_pairs<1>(3000, 0.002, 0.0035, 2); // cells larger than the radius
  expect_brute_force_pairs<1>(100, 0.3, 0.3, 3);       // few cells
}

TEST(HalfPairList, MatchesBruteForceIn2D) {
  expect_brute_force_pairs<2>(3000, 0.05, 0.05, 1);
  expect_brute_force_pairs<2>(3000, 0.05, 0.08, 2); // cells larger than the radius
  expect_brute_force_pairs<2>(500, 0.3, 0.3, 3);    // few cells per axis
}

TEST(HalfPairList, MatchesBruteForceIn3D) {
  expect_brute_force_pairs<3>(3000, 0.1, 0.1, 4);
  expect_brute_force_pairs<3>(3000, 0.1, 0.13, 5);
  expect_brute_force_pairs<3>(300, 0.6, 0.6, 6); // one or two cells per axis
}

// The listed pairs, each with the stripe it is listed in, in list order.
std::vector<std::tuple<std::size_t, std::uint32_t, std::uint32_t>>
listed_in_order(const HalfPairList& pairs) {
  std::vector<std::tuple<std::size_t, std::uint32_t, std::uint32_t>> listed;
  for (std::size_t s = 0; s < pairs.stripes().size(); ++s) {
    const HalfPairList::Stripe& stripe = pairs.stripes()[s];
    for (std::uint32_t local = 0; local < stripe.slot_count; ++local) {
      for (std::uint32_t i = stripe.offsets[local]; i < stripe.offsets[local + 1]; ++i) {
        listed.emplace_back(s, stripe.first_slot + local, stripe.partners[i]);
      }
    }
  }
  return listed;
}

TEST(HalfPairList, FilteredCopyKeepsExactlyTheWantedPairsInTheirOrder) {
  const CellOrdered<2> points = cell_ordered_points<2>(3000, Box<2>{{0, 0}, {1, 1}}, 0.05, 8);
  HalfPairList all;
  all.build<2>(points.cells, revsph::view_of<2>(points.slot_points), 0.05);
  // Slots divisible by three stand for the fixed particles: pairs of two of them are dropped.
  const auto keep = [](std::uint32_t a, std::uint32_t b) { return a % 3 != 0 || b % 3 != 0; };
  HalfPairList kept;
  kept.assign_filtered(all, [](std::uint32_t, std::uint32_t) { return false; });
  EXPECT_EQ(kept.pair_count(), 0u);
  kept.assign_filtered(all, keep); // reuses the emptied copy's stripes
  auto expected = listed_in_order(all);
  std::erase_if(expected,
                [&](const auto& pair) { return !keep(std::get<1>(pair), std::get<2>(pair)); });
  ASSERT_GT(expected.size(), 0u);
  ASSERT_LT(expected.size(), all.pair_count());
  EXPECT_EQ(listed_in_order(kept), expected);
  EXPECT_EQ(kept.pair_count(), expected.size());
  ASSERT_EQ(kept.stripes().size(), all.stripes().size());
  for (std::size_t s = 0; s < all.stripes().size(); ++s) {
    EXPECT_EQ(kept.stripes()[s].first_slot, all.stripes()[s].first_slot);
    EXPECT_EQ(kept.stripes()[s].slot_count, all.stripes()[s].slot_count);
  }
}

TEST(HalfPairList, RejectsARadiusBeyondTheCellSize) {
  const CellOrdered<2> points = cell_ordered_points<2>(10, Box<2>{{0, 0}, {1, 1}}, 0.1, 7);
  HalfPairList pairs;
  EXPECT_THROW(pairs.build<2>(points.cells, revsph::view_of<2>(points.slot_points), 0.2),
               std::invalid_argument);
}

// Quantity 0 of `slot` as a value; false if it overflowed or is not finite.
template <class Arith>
bool try_value(revsph::PairSums<Arith, 1>& sums, std::size_t slot, double& value) {
  int failed = 0;
  const bool valid = sums.convert(slot, failed);
  value = sums.value(0, slot);
  return valid;
}

// Scatter-adds a term per pair to both particles, the way the SPH loops do, in double.
std::vector<double> striped_double_sums(const HalfPairList& pairs, const CoordinateArrays<2>& x) {
  revsph::PairSums<revsph::FloatArithmetic, 1> sums(
      revsph::SummedQuantity{"term", revsph::fixedpoint::Scale(0)});
  sums.reset(x[0].size());
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      const double term = std::sin(x[0][a] * 17.0 + x[1][b] * 3.0) / 7.0;
      sums.add(a, 0, term);
      sums.add(b, 0, 0.5 * term);
    }
  });
  std::vector<double> values(x[0].size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    try_value(sums, i, values[i]);
  }
  return values;
}

TEST(HalfPairList, StripedLoopSumsEveryPairOnceForAnyThreadCount) {
  const Box<2> box{{-0.5, -0.5}, {0.5, 0.8}};
  const CellOrdered<2> points = cell_ordered_points<2>(20000, box, 0.02, 8);
  HalfPairList pairs;
  pairs.build<2>(points.cells, revsph::view_of<2>(points.slot_points), 0.02);

  // Integer counts: every pair must reach both particles exactly once (no lost updates).
  std::vector<std::uint64_t> count(points.slot_points[0].size(), 0);
  revsph::set_thread_count(2);
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    count[a] += partners.size();
    for (const std::uint32_t b : partners) {
      ++count[b];
    }
  });
  std::uint64_t total = 0;
  for (const std::uint64_t c : count) {
    total += c;
  }
  EXPECT_EQ(total, 2 * pairs.pair_count());

  // Floating-point sums: the order of the terms per particle is fixed by the stripes alone.
  revsph::set_thread_count(1);
  const std::vector<double> one_thread = striped_double_sums(pairs, points.slot_points);
  revsph::set_thread_count(2);
  const std::vector<double> two_threads = striped_double_sums(pairs, points.slot_points);
  revsph::set_thread_count(3);
  const std::vector<double> three_threads = striped_double_sums(pairs, points.slot_points);
  for (std::size_t i = 0; i < one_thread.size(); ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(one_thread[i]),
              std::bit_cast<std::uint64_t>(two_threads[i]))
        << "particle " << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(one_thread[i]),
              std::bit_cast<std::uint64_t>(three_threads[i]))
        << "particle " << i;
  }
}

// The exact per-particle sums of the pair loops (core/pair_sums.hpp).
TEST(ExactSums, AreExactAndIndependentOfTheOrder) {
  const revsph::fixedpoint::Scale scale(-40);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> term(-1000.0, 1000.0);
  std::vector<double> terms(1000);
  for (double& t : terms) {
    t = term(rng);
  }
  using Sums = revsph::PairSums<revsph::FixedArithmetic, 1>;
  Sums forward(revsph::SummedQuantity{"term", scale});
  Sums backward(revsph::SummedQuantity{"term", scale});
  forward.reset(1);
  backward.reset(1);
  std::int64_t expected = 0;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    forward.add(0, 0, terms[i]);
    backward.add(0, 0, terms[terms.size() - 1 - i]);
    expected += std::llrint(terms[i] * std::ldexp(1.0, 40));
  }
  double forward_value = 0.0;
  double backward_value = 0.0;
  ASSERT_TRUE(try_value(forward, 0, forward_value));
  ASSERT_TRUE(try_value(backward, 0, backward_value));
  EXPECT_EQ(forward_value, backward_value);
  EXPECT_EQ(forward_value, revsph::fixedpoint::to_real(expected, scale));
}

TEST(ExactSums, ReportOverflowAndUnrepresentableTerms) {
  const revsph::fixedpoint::Scale scale(0);
  revsph::PairSums<revsph::FixedArithmetic, 1> sums(revsph::SummedQuantity{"term", scale});
  sums.reset(3);
  sums.add_raw(0, 0, INT64_MAX - 1);
  sums.add(0, 0, 1.0);
  double value = 0.0;
  EXPECT_TRUE(try_value(sums, 0, value)); // exactly INT64_MAX
  sums.add(0, 0, 1.0);
  EXPECT_FALSE(try_value(sums, 0, value)) << "the running total left int64";
  sums.add(1, 0, std::nan(""));
  EXPECT_FALSE(try_value(sums, 1, value));
  sums.add(2, 0, 1e30); // beyond 2^63 units
  EXPECT_FALSE(try_value(sums, 2, value));
}

} // namespace
