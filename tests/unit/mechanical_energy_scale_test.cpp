// The energy that moved (core/mechanical_energy_scale.hpp) and energy.csv's two relative errors
// (core/energy_log.hpp) on hand-made budgets shaped like the built-in problems.

#include "core/energy_log.hpp"
#include "core/mechanical_energy_scale.hpp"
#include "hand_made_terms.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using revsph::EnergyBudget;
using revsph::EnergyLog;
using revsph::MechanicalEnergyScale;

EnergyBudget dam_break(double kinetic, double gravitational, double compressional) {
  return revsph::testing::hand_made_budget({{"kinetic", kinetic},
                                            {"gravitational", gravitational},
                                            {"compressional", compressional},
                                            {"wall", 0.0}});
}

TEST(MechanicalEnergyScale, DamBreakIsTheDropOfThePotentialEnergy) {
  MechanicalEnergyScale scale;
  scale.observe(dam_break(0.0, 19600.0, 4.8e6));
  EXPECT_TRUE(scale.started());
  EXPECT_EQ(scale.value(), 0.0) << "nothing has moved at rest";
  scale.observe(dam_break(6000.0, 13000.0, 4.8e6 + 600.0));
  EXPECT_DOUBLE_EQ(scale.value(), 6600.0);
  // Later the water sloshes back up: the scale keeps the largest drop seen.
  scale.observe(dam_break(2000.0, 17000.0, 4.8e6 + 600.0));
  EXPECT_DOUBLE_EQ(scale.value(), 6600.0);
}

TEST(MechanicalEnergyScale, KineticEnergyCountsWholeOtherTermsByTheirChange) {
  MechanicalEnergyScale scale;
  // A vortex: kinetic energy that barely changes, on top of a large constant reservoir.
  scale.observe(revsph::testing::hand_made_budget({{"kinetic", 0.08}, {"compressional", 77.8}}));
  EXPECT_DOUBLE_EQ(scale.value(), 0.08);
  scale.observe(revsph::testing::hand_made_budget({{"kinetic", 0.079}, {"compressional", 77.801}}));
  EXPECT_DOUBLE_EQ(scale.value(), 0.08);
}

TEST(MechanicalEnergyScale, DrivenFlowIsTheWorkOfItsWalls) {
  MechanicalEnergyScale scale;
  scale.observe(revsph::testing::hand_made_budget(
      {{"kinetic", 0.0}, {"dissipated", 0.0}, {"wall_work", 0.0}}));
  scale.observe(revsph::testing::hand_made_budget(
      {{"kinetic", 1.0}, {"dissipated", 2.0}, {"wall_work", -3.0}}));
  EXPECT_DOUBLE_EQ(scale.value(), 3.0);
}

TEST(MechanicalEnergyScale, RelativeErrorOfNothingMovedIsZeroOrInfinite) {
  EXPECT_EQ(revsph::mechanical_relative_error(0.0, 0.0), 0.0);
  EXPECT_TRUE(std::isinf(revsph::mechanical_relative_error(1e-9, 0.0)));
  EXPECT_DOUBLE_EQ(revsph::mechanical_relative_error(1.0, 4.0), 0.25);
}

TEST(EnergyLog, KeepsBothRelativeErrors) {
  EnergyLog log(std::nullopt);
  log.record(0, 0.0, dam_break(0.0, 19600.0, 4.8e6));
  log.record(100, 0.01, dam_break(7999.0, 11600.0, 4.8e6 + 2.0)); // E - E0 = 1
  EXPECT_DOUBLE_EQ(log.last_relative_error(), 1.0 / (4.8e6 + 19600.0));
  EXPECT_DOUBLE_EQ(log.last_mechanical_relative_error(), 1.0 / 8000.0);
  EXPECT_DOUBLE_EQ(log.mechanical_scale(), 8000.0);
  EXPECT_DOUBLE_EQ(log.max_mechanical_relative_error(), 1.0 / 8000.0);
  // The later half of a reversal continues E(0) and the scale.
  EnergyLog backward(std::nullopt);
  backward.continue_from(log);
  backward.record(100, 0.01, dam_break(7999.0, 11600.0, 4.8e6 + 4.0)); // E - E0 = 3
  EXPECT_DOUBLE_EQ(backward.last_mechanical_relative_error(), 3.0 / 8000.0);
  EXPECT_DOUBLE_EQ(backward.initial_total(), log.initial_total());
}

} // namespace
