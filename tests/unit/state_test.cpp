// The declared state: snapshots, restore, time reversal, hashing and comparison are generic over
// any struct of StateFields; tested here on a small state of two particle sets.

#include "core/arithmetic.hpp"
#include "core/particle_sets.hpp"
#include "core/state_snapshot.hpp"
#include "verify/state_compare.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <tuple>

namespace {

using revsph::Parity;
using revsph::StateField;

using revsph::Motion;
using revsph::SetInfo;

template <class Raw>
struct ToyFluid {
  static constexpr SetInfo set{.name = "fluid", .motion = Motion::moving};
  StateField<Raw> position{{.name = "position", .unit = "m", .components = 2}};
  StateField<Raw> velocity{
      {.name = "velocity", .unit = "m/s", .parity = Parity::odd, .components = 2}};
  StateField<Raw> entropy{{.name = "entropy", .unit = "J/K"}};
  auto fields() { return std::tie(position, velocity, entropy); }
};

template <class Raw>
struct ToyOther {
  static constexpr SetInfo set{.name = "other", .motion = Motion::fixed};
  StateField<Raw> flux{{.name = "heat_flux", .unit = "W/m^2", .parity = Parity::odd}};
  auto fields() { return std::tie(flux); }
};

template <class Raw>
struct ToyState {
  ToyFluid<Raw> fluid;
  ToyOther<Raw> other;
  auto sets() { return std::tie(fluid, other); }

  ToyState() {
    revsph::declare_state(*this);
    fluid.position.set_scale(revsph::fixedpoint::Scale(-40));
    fluid.velocity.set_scale(revsph::fixedpoint::Scale(-30));
    fluid.entropy.set_scale(revsph::fixedpoint::Scale(-20));
    other.flux.set_scale(revsph::fixedpoint::Scale(-20));
    revsph::resize_set(fluid, 3);
    revsph::resize_set(other, 3);
    std::int64_t value = -5;
    revsph::for_each_field(*this, [&](auto& field) {
      for (auto& v : field.all()) {
        v = static_cast<Raw>(value += 7);
      }
    });
  }
};

// The declaration itself: names from the sets, a missing scale or a set of two lengths refused.
TEST(StateDeclaration, StampsSetNamesAndRequiresScalesAndOneLengthPerSet) {
  ToyState<std::int64_t> state;
  EXPECT_EQ(state.fluid.velocity.info().particle_set, "fluid");
  EXPECT_EQ(state.other.flux.info().particle_set, "other");
  EXPECT_NO_THROW(revsph::require_complete(state));
  const auto sizes = revsph::set_sizes(state);
  ASSERT_EQ(sizes.size(), 2u);
  EXPECT_EQ(sizes[0].particle_set, "fluid");
  EXPECT_TRUE(sizes[0].moving);
  EXPECT_FALSE(sizes[1].moving);

  ToyState<std::int64_t> unscaled;
  unscaled.other.flux = StateField<std::int64_t>({.name = "heat_flux", .unit = "W/m^2"});
  unscaled.other.flux.set_particle_set("other");
  unscaled.other.flux.resize(3);
  EXPECT_THROW(revsph::require_complete(unscaled), std::logic_error);

  ToyState<std::int64_t> uneven;
  uneven.fluid.entropy.resize(4);
  EXPECT_THROW(revsph::require_complete(uneven), std::logic_error);
}

TEST(StateSnapshot, CaptureAndRestoreRoundTrip) {
  ToyState<std::int64_t> state;
  const auto snapshot = revsph::capture_state(state);
  ASSERT_EQ(snapshot.fields.size(), 4u);
  EXPECT_EQ(snapshot.fields[1].info.name, "velocity");
  EXPECT_EQ(snapshot.fields[1].at(1, 2), state.fluid.velocity.at(1, 2));
  ToyState<std::int64_t> other;
  other.fluid.velocity.at(0, 0) = 999;
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
  revsph::apply_time_reversal(state);
  const auto after = revsph::capture_state(state);
  for (std::size_t f = 0; f < before.fields.size(); ++f) {
    const bool odd = before.fields[f].info.parity == Parity::odd;
    for (std::size_t i = 0; i < before.fields[f].bits.size(); ++i) {
      EXPECT_EQ(after.fields[f].bits[i],
                odd ? -before.fields[f].bits[i] : before.fields[f].bits[i]);
    }
  }
  revsph::apply_time_reversal(state);
  EXPECT_EQ(revsph::state_hash(revsph::capture_state(state)), revsph::state_hash(before));
}

TEST(TimeReversal, RefusesToWrapTheMostNegativeInteger) {
  ToyState<std::int64_t> state;
  state.fluid.velocity.at(0, 1) = std::numeric_limits<std::int64_t>::min();
  EXPECT_THROW(revsph::apply_time_reversal(state), std::overflow_error);
}

TEST(StateHash, ChangesWithEveryBitAndWithTheLayout) {
  ToyState<std::int64_t> state;
  const std::string reference = revsph::state_hash(revsph::capture_state(state));
  EXPECT_EQ(reference.size(), 64u);
  EXPECT_EQ(revsph::state_hash(revsph::capture_state(state)), reference) << "deterministic";
  for (int bit = 0; bit < 64; bit += 9) {
    ToyState<std::int64_t> changed;
    changed.fluid.entropy.at(0, 2) ^= std::int64_t{1} << bit;
    EXPECT_NE(revsph::state_hash(revsph::capture_state(changed)), reference) << bit;
  }
  ToyState<std::int64_t> rescaled;
  rescaled.fluid.position.set_scale(revsph::fixedpoint::Scale(-41));
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
  b.fluid.entropy.at(0, 1) += 3;
  b.other.flux.at(0, 2) -= 5;
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
  b.fluid.velocity.at(1, 0) += 2.5 * std::ldexp(1.0, -30);
  const auto comparison =
      revsph::compare_states(revsph::capture_state(a), revsph::capture_state(b));
  ASSERT_EQ(comparison.differences.size(), 1u);
  EXPECT_EQ(comparison.differences[0].max_units_in_last_place, 3u);
  // +0 and -0 differ in their bits (FloPA can return -0 where +0 was): reported, 0 units apart.
  ToyState<double> c;
  c.fluid.entropy.at(0, 0) = 0.0;
  ToyState<double> d;
  d.fluid.entropy.at(0, 0) = -0.0;
  const auto zeros = revsph::compare_states(revsph::capture_state(c), revsph::capture_state(d));
  EXPECT_FALSE(zeros.identical);
  EXPECT_EQ(zeros.differences[0].max_units_in_last_place, 0u);
}

} // namespace
