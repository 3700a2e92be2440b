// diagnostics.csv's companion in summary.json: the smallest and the largest value of each
// diagnostic over the run (issue 33's fault list: a quantity that only falls, such as the
// thermal walls' entropy, reported a "max" of 0 while it fell to -1.45).

#include "core/diagnostics_log.hpp"
#include "hand_made_terms.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace {

TEST(DiagnosticsLog, KeepsTheSmallestAndTheLargestOfEach) {
  revsph::DiagnosticsLog log(std::nullopt);
  log.record(0, 0.0, revsph::testing::hand_made_terms({{"falling", 0.0}, {"rising", 1.0}}));
  log.record(1, 0.1, revsph::testing::hand_made_terms({{"falling", -0.7}, {"rising", 3.0}}));
  log.record(2, 0.2, revsph::testing::hand_made_terms({{"falling", -1.45}, {"rising", 2.0}}));
  ASSERT_EQ(log.minima().size(), 2u);
  EXPECT_EQ(log.minima()[0].value, -1.45);
  EXPECT_EQ(log.maxima()[0].value, 0.0);
  EXPECT_EQ(log.minima()[1].value, 1.0);
  EXPECT_EQ(log.maxima()[1].value, 3.0);
  EXPECT_EQ(log.minima()[0].name, "falling");
}

} // namespace
