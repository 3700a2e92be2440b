// state_distance: per variable, the largest and RMS difference in physical units (norm over the
// components of each particle) and in units of the last place, for fixed-point and double state.

#include "core/state_snapshot.hpp"
#include "verify/state_distance.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <stdexcept>

namespace {

using revsph::FieldSnapshot;
using revsph::Parity;
using revsph::RawKind;
using revsph::StateSnapshot;
using revsph::VariableInfo;

constexpr int velocity_exponent = -30;
constexpr int density_exponent = -20;

FieldSnapshot field(VariableInfo info, RawKind kind, std::size_t count) {
  FieldSnapshot snapshot{std::move(info), kind, count, {}};
  snapshot.bits.resize(count * static_cast<std::size_t>(snapshot.info.components));
  for (std::size_t i = 0; i < snapshot.bits.size(); ++i) {
    const auto value = static_cast<std::int64_t>(1000 + 37 * i);
    snapshot.bits[i] =
        kind == RawKind::fixed_point
            ? value
            : std::bit_cast<std::int64_t>(static_cast<double>(value) * snapshot.info.scale.unit());
  }
  return snapshot;
}

// Four particles: a 2D velocity and a scalar density, then a set of one particle.
StateSnapshot toy_state(RawKind kind = RawKind::fixed_point) {
  StateSnapshot state;
  state.fields.push_back(field({"fluid", "velocity", "m/s", Parity::odd, 2,
                                revsph::fixedpoint::Scale(velocity_exponent), true},
                               kind, 4));
  state.fields.push_back(field({"fluid", "density", "kg/m^3", Parity::even, 1,
                                revsph::fixedpoint::Scale(density_exponent), true},
                               kind, 4));
  state.fields.push_back(field({"wall", "position", "m", Parity::even, 2,
                                revsph::fixedpoint::Scale(density_exponent), false},
                               kind, 1));
  return state;
}

double velocity_unit() {
  return std::ldexp(1.0, velocity_exponent);
}

TEST(StateDistance, EqualStatesHaveZeroDistance) {
  const StateSnapshot state = toy_state();
  const revsph::StateDistance distance = revsph::state_distance(state, state);
  EXPECT_TRUE(distance.identical());
  EXPECT_TRUE(distance.differing().empty());
  EXPECT_TRUE(distance.table().empty());
  ASSERT_EQ(distance.variables.size(), 3u);
  EXPECT_EQ(distance.variables[0].max_difference, 0.0);
  EXPECT_EQ(distance.variables[0].max_units_in_last_place, 0u);
  EXPECT_GT(distance.variables[0].reference_rms, 0.0);
}

TEST(StateDistance, OneUnitChangeIsFoundInItsVariable) {
  const StateSnapshot from = toy_state();
  StateSnapshot to = from;
  // Particle 2, component 1 of the velocity: one unit in the last place.
  to.fields[0].bits[1 * 4 + 2] += 1;
  const revsph::StateDistance distance = revsph::state_distance(from, to);
  EXPECT_FALSE(distance.identical());
  const auto differing = distance.differing();
  ASSERT_EQ(differing.size(), 1u);
  const revsph::VariableDistance& velocity = *differing[0];
  EXPECT_EQ(velocity.name(), "fluid.velocity");
  EXPECT_EQ(velocity.unit, "m/s");
  EXPECT_EQ(velocity.differing_values, 1u);
  EXPECT_EQ(velocity.total_values, 8u);
  EXPECT_EQ(velocity.worst_particle, 2u);
  EXPECT_EQ(velocity.max_units_in_last_place, 1u);
  EXPECT_DOUBLE_EQ(velocity.rms_units_in_last_place, std::sqrt(1.0 / 8.0));
  EXPECT_DOUBLE_EQ(velocity.max_difference, velocity_unit());
  // One particle of four differs: RMS over the particles is half the largest.
  EXPECT_DOUBLE_EQ(velocity.rms_difference, velocity_unit() / 2.0);
  ASSERT_EQ(distance.table().size(), 1u);
  EXPECT_EQ(distance.table()[0].rfind("fluid.velocity: max ", 0), 0u) << distance.table()[0];
}

TEST(StateDistance, PhysicalDifferenceIsTheNormOverComponents) {
  const StateSnapshot from = toy_state();
  StateSnapshot to = from;
  // Particle 0 moves by (3, -4) units, particle 3 by (0, 2): norms 5 and 2.
  to.fields[0].bits[0] += 3;
  to.fields[0].bits[4] -= 4;
  to.fields[0].bits[4 + 3] += 2;
  // The density of particle 1 changes by 1000 units.
  to.fields[1].bits[1] -= 1000;
  const revsph::StateDistance distance = revsph::state_distance(from, to);
  const auto differing = distance.differing();
  ASSERT_EQ(differing.size(), 2u);
  const revsph::VariableDistance& velocity = *differing[0];
  EXPECT_DOUBLE_EQ(velocity.max_difference, 5.0 * velocity_unit());
  EXPECT_DOUBLE_EQ(velocity.rms_difference, std::sqrt((25.0 + 4.0) / 4.0) * velocity_unit());
  EXPECT_EQ(velocity.worst_particle, 0u);
  EXPECT_EQ(velocity.max_units_in_last_place, 4u);
  EXPECT_DOUBLE_EQ(velocity.rms_units_in_last_place, std::sqrt((9.0 + 16.0 + 4.0) / 8.0));
  const revsph::VariableDistance& density = *differing[1];
  EXPECT_EQ(density.name(), "fluid.density");
  EXPECT_DOUBLE_EQ(density.max_difference, 1000.0 * std::ldexp(1.0, density_exponent));
  EXPECT_DOUBLE_EQ(density.rms_difference, 500.0 * std::ldexp(1.0, density_exponent));
  EXPECT_EQ(density.max_units_in_last_place, 1000u);
}

TEST(StateDistance, DoubleStateIsMeasuredInTheScaleUnit) {
  const StateSnapshot from = toy_state(RawKind::ieee_double);
  StateSnapshot to = from;
  // 2.5 scale units: physically 2.5 * 2^-30 m/s, 3 units in the last place (rounded up).
  const double value = std::bit_cast<double>(from.fields[0].bits[5]);
  to.fields[0].bits[5] = std::bit_cast<std::int64_t>(value + 2.5 * velocity_unit());
  const revsph::StateDistance distance = revsph::state_distance(from, to);
  ASSERT_EQ(distance.differing().size(), 1u);
  const revsph::VariableDistance& velocity = *distance.differing()[0];
  EXPECT_NEAR(velocity.max_difference, 2.5 * velocity_unit(), 1e-6 * velocity_unit());
  EXPECT_EQ(velocity.max_units_in_last_place, 3u);
  EXPECT_EQ(velocity.worst_particle, 1u);
}

TEST(StateDistance, RejectsStatesOfAnotherLayout) {
  const StateSnapshot from = toy_state();
  StateSnapshot fewer = from;
  fewer.fields.pop_back();
  EXPECT_THROW(revsph::state_distance(from, fewer), std::invalid_argument);
  StateSnapshot rescaled = from;
  rescaled.fields[1].info.scale = revsph::fixedpoint::Scale(density_exponent - 1);
  EXPECT_THROW(revsph::state_distance(from, rescaled), std::invalid_argument);
}

} // namespace
