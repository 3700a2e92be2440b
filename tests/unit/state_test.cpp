// The declared state: snapshots, restore, time reversal, hashing and comparison are generic over
// any struct of StateFields; tested here on a small state of two particle sets.

#include "core/arithmetic.hpp"
#include "core/state_snapshot.hpp"
#include "verify/state_compare.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace {

using revsph::Parity;
using revsph::StateField;

template <class Raw>
struct ToyState {
  StateField<Raw> position{
      {"fluid", "position", "m", Parity::even, 2, revsph::fixedpoint::Scale(-40), true}};
  StateField<Raw> velocity{
      {"fluid", "velocity", "m/s", Parity::odd, 2, revsph::fixedpoint::Scale(-30), true}};
  StateField<Raw> entropy{
      {"fluid", "entropy", "J/K", Parity::even, 1, revsph::fixedpoint::Scale(-20), true}};
  StateField<Raw> flux{
      {"other", "heat_flux", "W/m^2", Parity::odd, 1, revsph::fixedpoint::Scale(-20), true}};

  ToyState() {
    for_each_field([](auto& field) { field.resize(3); });
    std::int64_t value = -5;
    for_each_field([&](auto& field) {
      for (auto& v : field.all()) {
        v = static_cast<Raw>(value += 7);
      }
    });
  }

  template <class Visit>
  void for_each_field(Visit&& visit) {
    visit(position);
    visit(velocity);
    visit(entropy);
    visit(flux);
  }
};

TEST(StateSnapshot, CaptureAndRestoreRoundTrip) {
  ToyState<std::int64_t> state;
  const auto snapshot = revsph::capture_state(state);
  ASSERT_EQ(snapshot.fields.size(), 4u);
  EXPECT_EQ(snapshot.fields[1].info.name, "velocity");
  EXPECT_EQ(snapshot.fields[1].at(1, 2), state.velocity.at(1, 2));
  ToyState<std::int64_t> other;
  other.velocity.at(0, 0) = 999;
  revsph::restore_state(other, snapshot);
  EXPECT_EQ(revsph::capture_state(other).fields[1].bits, snapshot.fields[1].bits);
}

TEST(StateSnapshot, RestoreRejectsAnotherLayout) {
  ToyState<std::int64_t> state;
  auto snapshot = revsph::capture_state(state);
  snapshot.fields[2].info.scale = revsph::fixedpoint::Scale(-21);
  EXPECT_THROW(revsph::restore_state(state, snapshot), std::invalid_argument);
  snapshot = revsph::capture_state(state);
  snapshot.fields.pop_back();
  EXPECT_THROW(revsph::restore_state(state, snapshot), std::invalid_argument);
}

TEST(TimeReversal, NegatesExactlyTheOddVariablesOfEverySet) {
  ToyState<std::int64_t> state;
  const auto before = revsph::capture_state(state);
  revsph::apply_time_reversal<revsph::FixedArithmetic>(state);
  const auto after = revsph::capture_state(state);
  for (std::size_t f = 0; f < before.fields.size(); ++f) {
    const bool odd = before.fields[f].info.parity == Parity::odd;
    for (std::size_t i = 0; i < before.fields[f].bits.size(); ++i) {
      EXPECT_EQ(after.fields[f].bits[i],
                odd ? -before.fields[f].bits[i] : before.fields[f].bits[i]);
    }
  }
  revsph::apply_time_reversal<revsph::FixedArithmetic>(state);
  EXPECT_EQ(revsph::state_hash(revsph::capture_state(state)), revsph::state_hash(before));
}

TEST(TimeReversal, RefusesToWrapTheMostNegativeInteger) {
  ToyState<std::int64_t> state;
  state.velocity.at(0, 1) = std::numeric_limits<std::int64_t>::min();
  EXPECT_THROW(revsph::apply_time_reversal<revsph::FixedArithmetic>(state), std::overflow_error);
}

TEST(StateHash, ChangesWithEveryBitAndWithTheLayout) {
  ToyState<std::int64_t> state;
  const std::string reference = revsph::state_hash(revsph::capture_state(state));
  EXPECT_EQ(reference.size(), 64u);
  EXPECT_EQ(revsph::state_hash(revsph::capture_state(state)), reference) << "deterministic";
  for (int bit = 0; bit < 64; bit += 9) {
    ToyState<std::int64_t> changed;
    changed.entropy.at(0, 2) ^= std::int64_t{1} << bit;
    EXPECT_NE(revsph::state_hash(revsph::capture_state(changed)), reference) << bit;
  }
  ToyState<std::int64_t> rescaled;
  rescaled.position.info().scale = revsph::fixedpoint::Scale(-41);
  EXPECT_NE(revsph::state_hash(revsph::capture_state(rescaled)), reference);
}

TEST(StateHash, MatchesAnIndependentSha256OfTheSameBytes) {
  // SHA-256 of the empty state is the hash of no bytes at all: a published test vector.
  revsph::StateSnapshot empty;
  EXPECT_EQ(revsph::state_hash(empty),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(StateCompare, ReportsFirstDifferenceAndUnitsInTheLastPlace) {
  ToyState<std::int64_t> a;
  ToyState<std::int64_t> b;
  b.entropy.at(0, 1) += 3;
  b.flux.at(0, 2) -= 5;
  const auto comparison =
      revsph::compare_states(revsph::capture_state(a), revsph::capture_state(b));
  EXPECT_FALSE(comparison.identical);
  ASSERT_TRUE(comparison.first_difference);
  EXPECT_EQ(comparison.first_difference->variable, "entropy");
  EXPECT_EQ(comparison.first_difference->particle, 1u);
  ASSERT_EQ(comparison.differences.size(), 2u);
  EXPECT_EQ(comparison.differences[0].max_units_in_last_place, 3u);
  EXPECT_EQ(comparison.differences[1].particle_set, "other");
  EXPECT_EQ(comparison.differences[1].max_units_in_last_place, 5u);
  EXPECT_DOUBLE_EQ(comparison.differences[1].max_abs_difference, 5 * std::ldexp(1.0, -20));
  EXPECT_TRUE(revsph::compare_states(revsph::capture_state(a), revsph::capture_state(a)).identical);
}

TEST(StateCompare, MeasuresDoubleStateInFixedPointUnits) {
  ToyState<double> a;
  ToyState<double> b;
  b.velocity.at(1, 0) += 2.5 * std::ldexp(1.0, -30);
  const auto comparison =
      revsph::compare_states(revsph::capture_state(a), revsph::capture_state(b));
  ASSERT_EQ(comparison.differences.size(), 1u);
  EXPECT_EQ(comparison.differences[0].max_units_in_last_place, 3u);
  // +0 and -0 differ in their bits (FloPA can return -0 where +0 was): reported, 0 units apart.
  ToyState<double> c;
  c.entropy.at(0, 0) = 0.0;
  ToyState<double> d;
  d.entropy.at(0, 0) = -0.0;
  const auto zeros = revsph::compare_states(revsph::capture_state(c), revsph::capture_state(d));
  EXPECT_FALSE(zeros.identical);
  EXPECT_EQ(zeros.differences[0].max_units_in_last_place, 0u);
}

} // namespace
