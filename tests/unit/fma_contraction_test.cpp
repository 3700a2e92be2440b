// The build must not contract a*b + c into a fused multiply-add: FMA changes the rounding of
// every force and drift, so a build with contraction would produce other hashes than one without
// (design note §6). multiply_add_unfused is compiled with the engine's own flags.

#include "core/determinism_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(FmaContraction, EngineCodeRoundsTheProductBeforeTheSum) {
  // a * b = 1 - 2^-60 exactly, which rounds to 1 in double; + (-1) gives 0 when the product is
  // rounded first, and -2^-60 when fused.
  volatile double a = 1.0 + std::ldexp(1.0, -30);
  volatile double b = 1.0 - std::ldexp(1.0, -30);
  volatile double c = -1.0;
  EXPECT_EQ(revsph::multiply_add_unfused(a, b, c), 0.0);
  EXPECT_EQ(std::fma(a, b, c), -std::ldexp(1.0, -60)) << "the test values do distinguish FMA";
}

} // namespace
