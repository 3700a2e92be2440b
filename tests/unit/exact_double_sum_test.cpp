// The order-independent sum of doubles (fixedpoint/exact_double_sum.hpp): the same bits for any
// order and any split into parts, and the correctly rounded total where naive summation is not.

#include "fixedpoint/exact_double_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using revsph::fixedpoint::ExactDoubleSum;

double exact_sum(const std::vector<double>& terms) {
  ExactDoubleSum sum;
  for (const double t : terms) {
    sum.add(t);
  }
  return sum.value();
}

// Terms over 600 decimal orders of magnitude, both signs, subnormals included.
std::vector<double> wide_terms() {
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> terms;
  for (int i = 0; i < 20000; ++i) {
    terms.push_back(uniform(generator) * std::ldexp(1.0, static_cast<int>(i % 2000) - 1060));
  }
  terms.push_back(std::numeric_limits<double>::denorm_min());
  terms.push_back(-3.0 * std::numeric_limits<double>::denorm_min());
  return terms;
}

TEST(ExactDoubleSum, SameBitsForAnyOrderAndAnySplit) {
  std::vector<double> terms = wide_terms();
  const double reference = exact_sum(terms);
  std::mt19937_64 generator(11);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(terms.begin(), terms.end(), generator);
    EXPECT_EQ(exact_sum(terms), reference);
    // Three parts added separately, then merged (threads, processes).
    ExactDoubleSum parts[3];
    for (std::size_t i = 0; i < terms.size(); ++i) {
      parts[i % 3].add(terms[i]);
    }
    parts[2].add(parts[0]);
    parts[2].add(parts[1]);
    EXPECT_EQ(parts[2].value(), reference);
    EXPECT_EQ(ExactDoubleSum::from_units(parts[2].units(), true).value(), reference);
  }
}

// The fixed-size image that carries a sum to another process gives back the same sum: positive,
// negative, zero, the widest total, and one with a non-finite term.
TEST(ExactDoubleSum, ImageRoundTrips) {
  std::vector<ExactDoubleSum> sums(5);
  for (const double term : wide_terms()) {
    sums[0].add(term);
    sums[1].add(-term);
  }
  const double largest = std::numeric_limits<double>::max();
  for (int i = 0; i < 1000; ++i) {
    sums[3].add(-largest); // 1 000 times the largest double: near the top of the 2 240 bits
  }
  sums[4].add(1.0);
  sums[4].add(std::numeric_limits<double>::infinity());
  for (const ExactDoubleSum& sum : sums) {
    const ExactDoubleSum back = ExactDoubleSum::from_image(sum.image());
    EXPECT_TRUE(back.units() == sum.units());
    EXPECT_EQ(back.finite(), sum.finite());
  }
  EXPECT_EQ(ExactDoubleSum::from_image(sums[1].image()).value(), -sums[0].value());
}

// Where naive left-to-right summation loses everything, the exact total survives.
TEST(ExactDoubleSum, CancellationKeepsTheSmallTerm) {
  EXPECT_EQ(exact_sum({1.0, 1e-300, -1.0}), 1e-300);
  EXPECT_EQ(exact_sum({1e308, 1e308, -1e308}), 1e308); // no overflow in between
  // The doubles nearest 0.1, 0.2 and 0.3 sum to 2^-55 exactly (naive: 2^-54).
  EXPECT_EQ(exact_sum({0.1, 0.2, -0.3}), std::ldexp(1.0, -55));
}

// Ties round to even: 1 + 2^-53 lies halfway between 1 and its successor 1 + 2^-52 and rounds to
// 1 (even); any amount more rounds up.
TEST(ExactDoubleSum, RoundsToNearestTiesToEven) {
  const double half_ulp = std::ldexp(1.0, -53);
  EXPECT_EQ(exact_sum({1.0, half_ulp}), 1.0);
  EXPECT_EQ(exact_sum({1.0, half_ulp, std::ldexp(1.0, -200)}), 1.0 + 2.0 * half_ulp);
  EXPECT_EQ(exact_sum({1.0 + 2.0 * half_ulp, half_ulp}), 1.0 + 4.0 * half_ulp); // odd: up
  EXPECT_EQ(exact_sum({}), 0.0);
}

TEST(ExactDoubleSum, NonFiniteTermGivesNaNAndOverflowGivesInfinity) {
  EXPECT_TRUE(std::isnan(exact_sum({1.0, std::numeric_limits<double>::infinity()})));
  EXPECT_TRUE(std::isnan(exact_sum({std::numeric_limits<double>::quiet_NaN()})));
  const double largest = std::numeric_limits<double>::max();
  EXPECT_EQ(exact_sum({largest, largest}), std::numeric_limits<double>::infinity());
}

} // namespace
