// The central promise: forward N steps, time reversal, N steps, time reversal returns every raw
// integer of the initial state. And the verifier that checks it can fail.

#include "reversibility_expectations.hpp"
#include "simulation_fixture.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

namespace {

using revsph::Simulation;
using revsph::StateSnapshot;
using revsph::VerifyOptions;
using revsph::VerifyPhase;
using revsph::testing::make_simulation;
using revsph::testing::reversal_of;

// Changes one raw integer of one variable by one unit, through the public state interface.
void nudge(Simulation& simulation, const std::string& set, const std::string& variable,
           std::size_t particle, int component) {
  StateSnapshot state = simulation.capture_state();
  revsph::FieldSnapshot* field = state.find(set, variable);
  ASSERT_NE(field, nullptr);
  field->bits[static_cast<std::size_t>(component) * field->count + particle] += 1;
  simulation.restore_state(state);
}

TEST(Reversibility, DambreakSmallReturnsBitwiseAfter5000StepsEachWay) {
  auto simulation = make_simulation("dambreak-small");
  const auto report = reversal_of(*simulation, 5000);
  EXPECT_TRUE(report.identical()) << report.comparison.verdict();
  EXPECT_EQ(report.initial_hash, report.final_hash);
  EXPECT_NE(report.initial_hash, report.turning_point_hash) << "the fluid did move";
}

TEST(Reversibility, EverySubstepIsSelfInverseUnderTimeReversal) {
  auto simulation = make_simulation("dambreak-small");
  simulation->advance(300); // a state with motion and wall contact
  revsph::testing::expect_substeps_undo_themselves(*simulation);
}

TEST(Reversibility, Dambreak3DReturnsBitwise) {
  auto simulation = make_simulation("dambreak-3d-small");
  const auto report = reversal_of(*simulation, 400);
  EXPECT_TRUE(report.identical()) << report.comparison.verdict();
}

// The 1D path (kernel, lattice, cell and pair lists): 2 000 steps each way on 1 and 2 threads,
// and every sub-step self-inverse on its own.
TEST(Reversibility, Column1DReturnsBitwiseOnOneAndTwoThreads) {
  revsph::testing::expect_returns_on_one_and_two_threads(
      "column-1d", 2000, {}, "", "the column did move",
      [](Simulation& simulation) { revsph::testing::expect_substeps_undo_themselves(simulation); });
}

TEST(Reversibility, FloatingPointVariantDoesNotReturnAndReportsHowFar) {
  auto simulation = make_simulation("dambreak-small", {}, revsph::Arithmetic::floating);
  const auto report = reversal_of(*simulation, 500);
  ASSERT_FALSE(report.identical());
  ASSERT_TRUE(report.comparison.first_difference.has_value());
  bool position_differs = false;
  for (const auto& difference : report.comparison.differences) {
    position_differs = position_differs || difference.variable == "position";
    EXPECT_GT(difference.max_abs_difference, 0.0);
    EXPECT_LT(difference.max_abs_difference, 1e-6) << "round-off, not a broken scheme";
  }
  EXPECT_TRUE(position_differs);
}

TEST(Verifier, ReportsAOneUnitChangeMadeDuringTheRun) {
  auto simulation = make_simulation("dambreak-small");
  VerifyOptions options;
  options.steps = 300;
  options.after_step = [](Simulation& s, VerifyPhase phase, std::int64_t step) {
    if (phase == VerifyPhase::forward && step == 150) {
      nudge(s, "fluid", "velocity", 1234, 1);
    }
  };
  const auto report = revsph::verify_reversibility(*simulation, options);
  EXPECT_FALSE(report.identical());
  EXPECT_NE(report.comparison.verdict().find("NOT identical"), std::string::npos);
}

TEST(Verifier, NamesExactlyTheParticleChangedJustBeforeTheComparison) {
  auto simulation = make_simulation("dambreak-small");
  VerifyOptions options;
  options.steps = 200;
  options.before_compare = [](Simulation& s) { nudge(s, "fluid", "velocity", 4321, 0); };
  const auto report = revsph::verify_reversibility(*simulation, options);
  ASSERT_FALSE(report.identical());
  const auto& first = *report.comparison.first_difference;
  EXPECT_EQ(first.particle_set, "fluid");
  EXPECT_EQ(first.particle, 4321u);
  EXPECT_EQ(first.variable, "velocity[0]");
  EXPECT_EQ(first.actual - first.expected, 1);
  ASSERT_EQ(report.comparison.differences.size(), 1u);
  EXPECT_EQ(report.comparison.differences[0].differing_values, 1u);
  EXPECT_EQ(report.comparison.differences[0].max_units_in_last_place, 1u);
  EXPECT_NE(report.comparison.verdict().find("fluid particle 4321, velocity[0]"), std::string::npos)
      << report.comparison.verdict();
  // The distance names the same variable: one unit of its scale, at that particle.
  ASSERT_TRUE(report.distance.has_value());
  const auto differing = report.distance->differing();
  ASSERT_EQ(differing.size(), 1u);
  EXPECT_EQ(differing[0]->name(), "fluid.velocity");
  EXPECT_EQ(differing[0]->worst_particle, 4321u);
  EXPECT_EQ(differing[0]->max_units_in_last_place, 1u);
  const StateSnapshot state = simulation->capture_state();
  EXPECT_EQ(differing[0]->max_difference, state.find("fluid", "velocity")->info.scale.unit());
}

TEST(Verifier, IdenticalReturnHasNoDistance) {
  auto simulation = make_simulation("dambreak-small");
  const auto report = reversal_of(*simulation, 20);
  EXPECT_TRUE(report.identical());
  EXPECT_FALSE(report.distance.has_value());
}

} // namespace
