// The run's health checks (core/run_health.hpp): each check (energy error, max|v|/c, merged
// pairs) warns once, at the record that first crosses its limit, and makes the run unhealthy
// with a reason naming the largest value and where it was first crossed; a NaN crosses any
// limit; a check without its reading is not made; a continued run replays the rows it keeps
// without warning again; the [health] keys' bad values are refused.

#include "core/run_health.hpp"

#include "core/case_keys.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace revsph {
namespace {

HealthReading reading(double energy_error, double speed_over_c, std::uint64_t merged_pairs) {
  HealthReading r;
  r.energy_error = energy_error;
  r.speed_over_c = speed_over_c;
  r.merged_pairs = merged_pairs;
  return r;
}

TEST(RunHealth, EachCheckWarnsOnceWhenFirstCrossed) {
  RunHealth health(HealthLimits{0.01, 1.0, 0.1, 1e-6});
  EXPECT_TRUE(health.observe(0, 0.0, reading(0.0, 0.5, 0)).empty());
  EXPECT_TRUE(health.observe(100, 0.5, reading(0.01, 1.0, 0)).empty()) << "at the limit: healthy";
  EXPECT_TRUE(health.healthy());
  EXPECT_TRUE(health.reasons().empty());

  const std::vector<std::string> speed = health.observe(200, 1.0, reading(0.001, 2.5, 0));
  ASSERT_EQ(speed.size(), 1u);
  EXPECT_EQ(speed[0], "warning: step 200, t = 1 s: max|v|/c = 2.5 above "
                      "health.max_speed_over_c = 1: check the sound speed, dt and the forces");
  EXPECT_FALSE(health.healthy());
  EXPECT_TRUE(health.observe(300, 1.5, reading(0.001, 70.0, 0)).empty()) << "warned already";

  HealthReading both = reading(0.5, 3.0, 14);
  both.close_pairs = 20;
  const std::vector<std::string> lines = health.observe(400, 2.0, both);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("energy error 0.5 above health.max_energy_error = 0.01"),
            std::string::npos)
      << lines[0];
  EXPECT_EQ(lines[1], "warning: step 400, t = 2 s: merged pairs = 14 (particles closer than "
                      "1e-06 dr, health.merged_pair_fraction): particles have merged; 20 pairs "
                      "closer than 0.1 dr");
  health.observe(500, 2.5, reading(0.2, 1.0, 3));

  const std::vector<std::string> reasons = health.reasons();
  ASSERT_EQ(reasons.size(), 3u);
  EXPECT_EQ(reasons[0], "energy error reached 0.5, above health.max_energy_error = 0.01; first "
                        "at step 400, t = 2 s");
  EXPECT_EQ(reasons[1], "max|v|/c reached 70, above health.max_speed_over_c = 1; first at step "
                        "200, t = 1 s");
  EXPECT_EQ(reasons[2], "merged pairs reached 14 (particles closer than 1e-06 dr, "
                        "health.merged_pair_fraction); first at step 400, t = 2 s");
}

TEST(RunHealth, NaNCrossesAndAMissingReadingIsNoCheck) {
  RunHealth health(default_health_limits());
  EXPECT_TRUE(health.observe(0, 0.0, HealthReading{}).empty());
  HealthReading close_only;
  close_only.close_pairs = 100; // counted, not checked
  EXPECT_TRUE(health.observe(5, 0.05, close_only).empty());
  EXPECT_TRUE(health.healthy());
  HealthReading nan;
  nan.energy_error = NAN;
  EXPECT_EQ(health.observe(10, 0.1, nan).size(), 1u);
  EXPECT_FALSE(health.healthy());
  ASSERT_EQ(health.reasons().size(), 1u);
  EXPECT_NE(health.reasons()[0].find("energy error reached nan"), std::string::npos)
      << health.reasons()[0];
}

TEST(RunHealth, AContinuedRunReplaysItsRowsWithoutWarningAgain) {
  LoggedRows energy;
  energy.columns = {"step",  "time",           "kinetic",
                    "total", "relative_error", "mechanical_relative_error"};
  // A flow driven from rest: 0 / 0 at the start, which is no error.
  energy.rows = {{0, 0.0, 0.0, 0.0, NAN, 0.0}, {100, 0.5, 1.0, 1.0e-3, 0.001, 0.0}};
  LoggedRows diagnostics;
  diagnostics.columns = {"step", "time", "speed_over_c", "close_pairs", "merged_pairs"};
  diagnostics.rows = {{0, 0.0, 0.1, 0.0, 0.0}, {100, 0.5, 0.2, 7.0, 2.0}};
  RunHealth health(default_health_limits());
  health.replay(energy, diagnostics);
  EXPECT_FALSE(health.healthy());
  ASSERT_EQ(health.reasons().size(), 1u);
  EXPECT_NE(health.reasons()[0].find("merged pairs reached 2 "), std::string::npos);
  EXPECT_NE(health.reasons()[0].find("first at step 100, t = 0.5 s"), std::string::npos);
  // The pairs were the earlier run's to warn of; the speed is this one's.
  EXPECT_TRUE(health.observe(200, 1.0, reading(0.0, 0.3, 5)).empty());
  EXPECT_EQ(health.observe(300, 1.5, reading(0.0, 15.0, 5)).size(), 1u);
}

TEST(RunHealth, ReadsTheHealthTableAndRefusesBadLimits) {
  const auto limits_of = [](const std::string& table) {
    const CaseFile case_file = CaseFile::parse("[health]\n" + table, "case.toml");
    case_file.use_keys({&common_case_keys()});
    return read_health_limits(case_file);
  };
  const HealthLimits defaults = limits_of("");
  EXPECT_EQ(defaults.max_energy_error, default_health_limits().max_energy_error);
  EXPECT_EQ(defaults.max_speed_over_c, default_health_limits().max_speed_over_c);
  EXPECT_EQ(defaults.close_pair_fraction, default_health_limits().close_pair_fraction);
  EXPECT_EQ(defaults.merged_pair_fraction, default_health_limits().merged_pair_fraction);
  const HealthLimits given =
      limits_of("max_energy_error = 0.5\nmax_speed_over_c = 0\nclose_pair_fraction = 0\n"
                "merged_pair_fraction = 0.01\n");
  EXPECT_EQ(given.max_energy_error, 0.5);
  EXPECT_TRUE(std::isinf(given.max_speed_over_c));
  EXPECT_EQ(given.close_pair_fraction, 0.0);
  EXPECT_EQ(given.merged_pair_fraction, 0.01);
  EXPECT_THROW(limits_of("max_energy_error = -0.1\n"), CaseError);
  EXPECT_THROW(limits_of("max_energy_error = inf\n"), CaseError);
  EXPECT_THROW(limits_of("max_speed_over_c = -1\n"), CaseError);
  EXPECT_THROW(limits_of("max_speed_over_c = nan\n"), CaseError);
  EXPECT_THROW(limits_of("close_pair_fraction = 1.5\n"), CaseError);
  EXPECT_THROW(limits_of("close_pair_fraction = -0.1\n"), CaseError);
  EXPECT_THROW(limits_of("merged_pair_fraction = 2\n"), CaseError);
}

} // namespace
} // namespace revsph
