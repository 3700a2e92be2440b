// Periodic boundaries in every model (issue 33, item 2; docs/periodic.md): one small case of each
// with [domain] periodic = "x" returns bit for bit under `revsph verify`, on 1 and 2 threads. The
// wrap sits in the core's drifts (core/verlet.hpp; superfluid's own drift calls it too) and the
// images in the distribution, so every model gets both; the crossing of the faces themselves is
// checked by periodic_test (random states) and python.periodic (a shear layer in a moving frame).

#include "cli_sandbox.hpp"
#include "shear_layer_example.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

class PeriodicModels : public ::testing::TestWithParam<const char*> {};

TEST_P(PeriodicModels, SmallCaseWithPeriodicXReturnsBitwise) {
  Sandbox sandbox;
  for (const char* threads : {"1", "2"}) {
    const CommandResult result =
        sandbox.revsph({"verify", GetParam(), "--steps", "300", "--threads", threads, "--set",
                        "domain.periodic=\"x\""});
    EXPECT_EQ(result.exit_status, 0) << result;
    EXPECT_NE(result.out.find("verdict: bitwise identical"), std::string::npos) << result;
  }
}

// wcsph, entropic, shtc, superfluid, two_fluid.
INSTANTIATE_TEST_SUITE_P(OneCaseOfEachModel, PeriodicModels,
                         ::testing::Values("dambreak-small", "box-small", "beryllium-plate-small",
                                           "second-sound-small", "rayleigh-taylor-small"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             c = c == '-' ? '_' : c;
                           }
                           return name;
                         });

TEST(PeriodicDomain, RefusesGravityAlongAPeriodicAxisAndAPeriodTooShort) {
  Sandbox sandbox;
  const CommandResult gravity =
      sandbox.revsph({"run", "dambreak-small", "--steps", "1", "--set", "domain.periodic=\"y\""});
  EXPECT_EQ(gravity.exit_status, 2) << gravity;
  EXPECT_NE(gravity.err.find("domain.periodic"), std::string::npos) << gravity;
  const CommandResult axis =
      sandbox.revsph({"run", "dambreak-small", "--steps", "1", "--set", "domain.periodic=\"z\""});
  EXPECT_EQ(axis.exit_status, 2) << axis;
  EXPECT_NE(axis.err.find("names the axes that are periodic"), std::string::npos) << axis;
}

// The shear layer of docs/examples/periodic-shear-layer with 4 x 4 particles at dr = 0.25: the
// kernel's support (0.75 m) reaches across more than half the 1 m period; and the same case with
// the period cut to x < 0.7, which leaves a quarter of its particles outside.
TEST(PeriodicDomain, RefusesAPeriodTooShortAndParticlesOutsideIt) {
  Sandbox sandbox;
  ASSERT_TRUE(revsph::testing::write_shear_layer_example(sandbox, 4));
  const CommandResult short_period = sandbox.revsph(
      {"run", "shear-layer.toml", "--steps", "1", "--set", "discretisation.dr=0.25"});
  EXPECT_EQ(short_period.exit_status, 2) << short_period;
  EXPECT_NE(short_period.err.find("domain.periodic: the period along x (1.000000 m) must exceed "
                                  "twice"),
            std::string::npos)
      << short_period;
  const CommandResult outside =
      sandbox.revsph({"run", "shear-layer.toml", "--steps", "1", "--set", "discretisation.dr=0.25",
                      "--set", "domain.max=[0.7, 1.0]"});
  EXPECT_EQ(outside.exit_status, 2) << outside;
  EXPECT_NE(outside.err.find("lies outside the period"), std::string::npos) << outside;
}

} // namespace
