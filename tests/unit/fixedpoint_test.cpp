// Properties of the fixed-point core that exact reversibility rests on (design note §1–3).

#include "core/arithmetic.hpp"
#include "fixedpoint/conversion.hpp"
#include "fixedpoint/exact_sum.hpp"
#include "fixedpoint/fixed_vector.hpp"

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using revsph::fixedpoint::ExactSum;
using revsph::fixedpoint::FixedScalar;
using revsph::fixedpoint::FixedVector;
using revsph::fixedpoint::OverflowError;
using revsph::fixedpoint::Scale;
using revsph::fixedpoint::to_fixed;
using revsph::fixedpoint::try_to_fixed;

std::int64_t convert(double value, const Scale& scale) {
  std::int64_t raw = 0;
  EXPECT_TRUE(try_to_fixed(value, scale, raw)) << value;
  return raw;
}

// Random doubles spread over many binades, both signs.
double random_value(std::mt19937_64& rng, double max_magnitude) {
  std::uniform_real_distribution<double> exponent(-30.0, std::log2(max_magnitude));
  std::uniform_int_distribution<int> sign(0, 1);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  return (sign(rng) ? -1.0 : 1.0) * mantissa(rng) * std::exp2(std::floor(exponent(rng)));
}

TEST(FixedPointConversion, IsOddSymmetricForRandomValues) {
  std::mt19937_64 rng(20261122);
  const Scale scale(-40);
  for (int i = 0; i < 200000; ++i) {
    const double y = random_value(rng, 1e6);
    ASSERT_EQ(convert(-y, scale), -convert(y, scale)) << "y = " << y;
  }
}

TEST(FixedPointConversion, IsOddSymmetricAtHalfwayCases) {
  // y = (k + 1/2) units sits exactly between two raw values: a floor-based or shift-based
  // rounding would send +y and -y to different magnitudes.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> raw(-(std::int64_t{1} << 50), std::int64_t{1} << 50);
  const Scale scale(-20);
  for (int i = 0; i < 100000; ++i) {
    const double y = (static_cast<double>(raw(rng)) + 0.5) * scale.unit();
    const std::int64_t up = convert(y, scale);
    ASSERT_EQ(convert(-y, scale), -up) << "y = " << y;
    ASSERT_EQ(std::abs(up) % 2, 0) << "ties go to the even neighbour";
  }
  EXPECT_EQ(convert(0.5 * scale.unit(), scale), 0);
  EXPECT_EQ(convert(1.5 * scale.unit(), scale), 2);
  EXPECT_EQ(convert(-2.5 * scale.unit(), scale), -2);
}

TEST(FixedPointConversion, RoundTripsExactlyBelowTwoToThe53) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> raw(-(std::int64_t{1} << 53), std::int64_t{1} << 53);
  const Scale scale(-49);
  for (int i = 0; i < 100000; ++i) {
    const std::int64_t r = raw(rng);
    ASSERT_EQ(convert(revsph::fixedpoint::to_real(r, scale), scale), r);
  }
}

TEST(FixedPointArithmetic, AddingAndSubtractingAnIncrementRestoresTheValue) {
  // The drift and the kick add round(increment) and, after time reversal, round(-increment).
  std::mt19937_64 rng(3);
  const Scale scale(-43);
  for (int i = 0; i < 100000; ++i) {
    std::int64_t x = convert(random_value(rng, 1e3), scale);
    const std::int64_t original = x;
    const double increment = random_value(rng, 10.0);
    ASSERT_TRUE(revsph::FixedArithmetic::try_increment(x, increment, scale));
    ASSERT_TRUE(revsph::FixedArithmetic::try_increment(x, -increment, scale));
    ASSERT_EQ(x, original);
  }
  const FixedScalar x{123456789, scale};
  const FixedScalar d{-987654321, scale};
  EXPECT_EQ(((x + d) - d).raw, x.raw);
  const auto v = FixedVector<3>::from_real({1.5, -2.25, 3.0}, scale, "v");
  const auto dv = FixedVector<3>::from_real({1e-9, 7.0, -0.125}, scale, "dv");
  EXPECT_EQ(((v + dv) - dv).raw, v.raw);
}

TEST(ExactSum, IsIdenticalUnderRandomPermutationsAndMatchesABigIntegerSum) {
  std::mt19937_64 rng(5);
  const Scale scale(-30);
  std::vector<double> terms(5000);
  for (double& t : terms) {
    t = random_value(rng, 1e4);
  }
  // Oracle: the same rounded terms added in arbitrary precision (Boost.Multiprecision).
  boost::multiprecision::cpp_int oracle = 0;
  for (const double t : terms) {
    oracle += convert(t, scale);
  }
  std::int64_t reference = 0;
  {
    ExactSum sum(scale);
    for (const double t : terms) {
      sum.add(t);
    }
    ASSERT_TRUE(sum.try_raw(reference));
  }
  EXPECT_EQ(boost::multiprecision::cpp_int(reference), oracle);
  for (int permutation = 0; permutation < 100; ++permutation) {
    std::shuffle(terms.begin(), terms.end(), rng);
    ExactSum sum(scale);
    for (const double t : terms) {
      sum.add(t);
    }
    std::int64_t raw = 0;
    ASSERT_TRUE(sum.try_raw(raw));
    ASSERT_EQ(raw, reference) << "permutation " << permutation;
  }
  // Where a plain double sum depends on the order, the exact sum does not.
  const double a = 1e16;
  const double b = 1.0;
  EXPECT_NE((a + b) - a, (a - a) + b);
  ExactSum first(Scale(0));
  ExactSum second(Scale(0));
  for (const double t : {a, b, -a}) {
    first.add(t);
  }
  for (const double t : {a, -a, b}) {
    second.add(t);
  }
  std::int64_t first_raw = 0;
  std::int64_t second_raw = 0;
  ASSERT_TRUE(first.try_raw(first_raw) && second.try_raw(second_raw));
  EXPECT_EQ(first_raw, 1);
  EXPECT_EQ(second_raw, 1);
}

TEST(ExactSum, ToleratesIntermediateTotalsBeyondInt64) {
  // Partial sums may leave the int64 range as long as the final total fits.
  const Scale scale(0);
  ExactSum sum(scale);
  const double big = 0x1p62;
  sum.add(big);
  sum.add(big);
  sum.add(big); // 3 * 2^62 > 2^63
  sum.add(-big);
  sum.add(-big);
  std::int64_t raw = 0;
  ASSERT_TRUE(sum.try_raw(raw));
  EXPECT_EQ(raw, std::int64_t{1} << 62);
}

TEST(OverflowDetection, ConversionOutOfRangeOrNotFiniteIsReported) {
  const Scale scale(-40);
  std::int64_t raw = 0;
  EXPECT_FALSE(try_to_fixed(scale.max_magnitude(), scale, raw));
  EXPECT_FALSE(try_to_fixed(-scale.max_magnitude(), scale, raw));
  EXPECT_TRUE(try_to_fixed(scale.max_magnitude() * 0.999, scale, raw));
  EXPECT_FALSE(try_to_fixed(std::numeric_limits<double>::quiet_NaN(), scale, raw));
  EXPECT_FALSE(try_to_fixed(std::numeric_limits<double>::infinity(), scale, raw));
  EXPECT_FALSE(try_to_fixed(-std::numeric_limits<double>::infinity(), scale, raw));
  EXPECT_THROW(to_fixed(1e300, scale, "test quantity"), OverflowError);
  try {
    to_fixed(1e300, scale, "fluid velocity");
  } catch (const OverflowError& error) {
    EXPECT_NE(std::string(error.what()).find("fluid velocity"), std::string::npos);
  }
}

TEST(OverflowDetection, AdditionNegationAndSumsDoNotWrap) {
  const Scale scale(-10);
  constexpr auto max = std::numeric_limits<std::int64_t>::max();
  constexpr auto min = std::numeric_limits<std::int64_t>::min();
  EXPECT_THROW(revsph::fixedpoint::add_checked(max, 1, "x"), OverflowError);
  EXPECT_THROW(revsph::fixedpoint::add_checked(min, -1, "x"), OverflowError);
  EXPECT_THROW((void)(FixedScalar{max, scale} + FixedScalar{1, scale}), OverflowError);
  EXPECT_THROW((void)(-FixedScalar{min, scale}), OverflowError);
  std::int64_t negated = 0;
  EXPECT_FALSE(revsph::fixedpoint::try_negate(min, negated));

  std::int64_t x = max - 5;
  EXPECT_FALSE(revsph::FixedArithmetic::try_increment(x, 10.0 * scale.unit(), scale));
  EXPECT_EQ(x, max - 5) << "a failed increment leaves the value untouched";

  ExactSum sum(Scale(0));
  sum.add(0x1p62);
  sum.add(0x1p62);
  std::int64_t raw = 0;
  EXPECT_FALSE(sum.try_raw(raw)) << "2^63 does not fit in int64";
  ExactSum poisoned(Scale(0));
  poisoned.add(std::numeric_limits<double>::quiet_NaN());
  poisoned.add(1.0);
  EXPECT_FALSE(poisoned.try_raw(raw));
}

TEST(Scale, CoversTheRequestedMagnitudeWithTheRequestedResolution) {
  const Scale positions = Scale::covering(4.1, 52);
  EXPECT_EQ(positions.exponent(), -49);
  EXPECT_GE(positions.max_magnitude(), 4.1 * std::exp2(10));
  EXPECT_LE(4.1 / positions.unit(), std::exp2(53)) << "positions stay exact as doubles";
  EXPECT_EQ(Scale(-3).unit(), 0.125);
  EXPECT_THROW(Scale::covering(0.0, 10), std::invalid_argument);
}

TEST(RoundingMode, IsRoundToNearest) {
  EXPECT_NO_THROW(revsph::fixedpoint::require_round_to_nearest());
}

} // namespace
