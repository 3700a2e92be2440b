// Snapshot files: exact round trip of any declared state, metadata, atomic writing, and clear
// refusals of files that are not (or no longer) snapshots.

#include "core/fault.hpp"
#include "core/hdf5_handle.hpp"
#include "core/sha256.hpp"
#include "core/snapshot_file.hpp"
#include "temp_directory.hpp"
#include "verify/snapshot_check.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>

namespace {

namespace fs = std::filesystem;
using revsph::FieldSnapshot;
using revsph::Parity;
using revsph::RawKind;
using revsph::SnapshotError;
using revsph::SnapshotMetadata;
using revsph::StateSnapshot;
using revsph::testing::TempDirectory;

StateSnapshot toy_state() {
  StateSnapshot state;
  FieldSnapshot position{
      {"fluid", "position", "m", Parity::even, 3, revsph::fixedpoint::Scale(-40), true},
      RawKind::fixed_point,
      4,
      {}};
  for (int i = 0; i < 12; ++i) {
    position.bits.push_back(i * 1000003 - 5);
  }
  position.bits[5] = std::numeric_limits<std::int64_t>::max();
  position.bits[6] = std::numeric_limits<std::int64_t>::min() + 1;
  FieldSnapshot entropy{
      {"fluid", "entropy", "J/K", Parity::even, 1, revsph::fixedpoint::Scale(-20), true},
      RawKind::ieee_double,
      4,
      {}};
  for (const double value : {1.5, -0.0, 1e-300, -7.25}) {
    entropy.bits.push_back(std::bit_cast<std::int64_t>(value));
  }
  FieldSnapshot flux{{"ghost", "flux", "W", Parity::odd, 2, revsph::fixedpoint::Scale(3), false},
                     RawKind::fixed_point,
                     0,
                     {}};
  state.fields = {position, entropy, flux};
  return state;
}

SnapshotMetadata toy_metadata(const StateSnapshot& state) {
  SnapshotMetadata metadata;
  metadata.model = "toy";
  metadata.dimension = 3;
  metadata.arithmetic = revsph::Arithmetic::floating;
  metadata.case_name = "toy case";
  metadata.case_source = "toy.toml";
  metadata.case_text = "model = \"toy\"\n# ünïcödé\n";
  metadata.overrides = {"a.b=1", "c=[1, 2]"};
  metadata.step = 123456789012;
  metadata.time = 0.1 + 0.2;
  metadata.dt = 1e-4;
  metadata.reference_energy = -12.5;
  const std::string stl("solid\0\xff end", 12); // any bytes, a NUL among them
  metadata.inputs = {{"tank.stl", "/cases/tank.stl", revsph::sha256_hex(stl), stl},
                     {"points.csv", "/cases/points.csv", revsph::sha256_hex(""), ""}};
  metadata.run_end_step = 3000;
  metadata.run_end_origin = "--steps 3000 given at step 0";
  metadata.state_hash = revsph::state_hash(state);
  metadata.code_version = "1.2.3";
  metadata.git_commit = "abc";
  metadata.build_type = "Release";
  metadata.build_flags = "-O2";
  return metadata;
}

// EXPECT_EQ(actual.*member, expected.*member) for each member in order ("member i" in the
// message, i counted from 0).
template <class T, class... Types>
void expect_equal_members(const T& actual, const T& expected, Types T::*... members) {
  int index = 0;
  auto expect_equal = [&](auto member) {
    EXPECT_EQ(actual.*member, expected.*member) << "member " << index;
    ++index;
  };
  (expect_equal(members), ...);
}

TEST(SnapshotFile, RoundTripsStateAndMetadataExactly) {
  TempDirectory directory("revsph-snapshot-test");
  const StateSnapshot state = toy_state();
  const SnapshotMetadata metadata = toy_metadata(state);
  const fs::path path = directory.path() / "toy.h5";
  const std::vector<revsph::ParticleView> views = {
      {"fluid", "temperature", "K", 1, {300.0, 301.0, 302.0, 303.0}}};
  const auto sets = revsph::write_snapshot(path, metadata, state, views);
  EXPECT_FALSE(fs::exists(path.string() + ".tmp")) << "renamed into place";
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].name, "fluid");
  EXPECT_EQ(sets[0].count, 4u);
  EXPECT_EQ(sets[0].fields.back().name, "kind");

  const revsph::Snapshot read = revsph::read_checked_snapshot(path);
  ASSERT_EQ(read.state.fields.size(), state.fields.size());
  for (std::size_t f = 0; f < state.fields.size(); ++f) {
    const FieldSnapshot& a = state.fields[f];
    const FieldSnapshot& b = read.state.fields[f];
    EXPECT_EQ(b.info.particle_set, a.info.particle_set);
    EXPECT_EQ(b.info.name, a.info.name);
    EXPECT_EQ(b.info.unit, a.info.unit);
    EXPECT_EQ(b.info.parity, a.info.parity);
    EXPECT_EQ(b.info.components, a.info.components);
    EXPECT_EQ(b.info.scale.exponent(), a.info.scale.exponent());
    EXPECT_EQ(b.info.evolved, a.info.evolved);
    EXPECT_EQ(b.kind, a.kind);
    EXPECT_EQ(b.count, a.count);
    EXPECT_EQ(b.bits, a.bits);
  }
  EXPECT_EQ(revsph::state_hash(read.state), metadata.state_hash);
  using M = SnapshotMetadata;
  expect_equal_members(read.metadata, metadata, &M::model, &M::dimension, &M::arithmetic,
                       &M::case_name, &M::case_source, &M::case_text, &M::overrides, &M::step,
                       &M::time, &M::dt, &M::reference_energy, &M::code_version, &M::build_flags,
                       &M::inputs, &M::run_end_step, &M::run_end_time, &M::run_end_origin);
}

// An input file whose bytes changed since they were recorded is refused: a restart would rebuild
// another case.
TEST(SnapshotFile, RefusesAnInputFileThatLostItsHash) {
  TempDirectory directory("revsph-snapshot-test");
  const StateSnapshot state = toy_state();
  SnapshotMetadata metadata = toy_metadata(state);
  metadata.inputs[0].bytes[0] = 'S';
  const fs::path path = directory.path() / "tampered.h5";
  revsph::write_snapshot(path, metadata, state, std::vector<revsph::ParticleView>{});
  try {
    revsph::read_checked_snapshot(path);
    FAIL() << "accepted";
  } catch (const SnapshotError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("/inputs/0 (tank.stl): its bytes do not have their "
                        "recorded sha256"),
              std::string::npos)
        << error.what();
  }
}

TEST(SnapshotFile, RefusesMissingForeignAndTruncatedFiles) {
  TempDirectory directory("revsph-snapshot-test");
  auto message_of = [](const fs::path& path) {
    try {
      revsph::read_checked_snapshot(path);
    } catch (const SnapshotError& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(message_of(directory.path() / "none.h5").find("no such snapshot"), std::string::npos);

  const fs::path text = directory.path() / "text.h5";
  std::ofstream(text) << "model = \"wcsph\"\n";
  EXPECT_NE(message_of(text).find("not an HDF5 file"), std::string::npos);

  const StateSnapshot state = toy_state();
  const fs::path good = directory.path() / "good.h5";
  revsph::write_snapshot(good, toy_metadata(state), state, std::vector<revsph::ParticleView>{});
  const fs::path truncated = directory.path() / "truncated.h5";
  fs::copy_file(good, truncated);
  fs::resize_file(truncated, fs::file_size(good) / 2);
  const std::string truncated_message = message_of(truncated);
  EXPECT_NE(truncated_message.find(truncated.string()), std::string::npos) << truncated_message;
  EXPECT_EQ(truncated_message.find("(accepted)"), std::string::npos);

  // A snapshot whose state no longer matches its recorded hash is refused.
  revsph::SnapshotMetadata wrong_hash = toy_metadata(state);
  wrong_hash.state_hash = std::string(64, '0');
  const fs::path damaged = directory.path() / "damaged.h5";
  revsph::write_snapshot(damaged, wrong_hash, state, std::vector<revsph::ParticleView>{});
  EXPECT_NE(message_of(damaged).find("does not match the hash"), std::string::npos);
}

TEST(SnapshotFile, RefusesOtherFormatsAndVersions) {
  TempDirectory directory("revsph-snapshot-test");
  const StateSnapshot state = toy_state();
  const fs::path path = directory.path() / "versioned.h5";
  revsph::write_snapshot(path, toy_metadata(state), state, std::vector<revsph::ParticleView>{});
  {
    revsph::hdf5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open");
    revsph::hdf5::write_int_attribute(file.id(), "format_version", 99);
  }
  try {
    revsph::read_snapshot(path);
    FAIL() << "a version-99 snapshot was accepted";
  } catch (const SnapshotError& error) {
    EXPECT_NE(std::string(error.what()).find("version 99"), std::string::npos) << error.what();
  }
  {
    revsph::hdf5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open");
    revsph::hdf5::write_string_attribute(file.id(), "format", "something-else");
  }
  try {
    revsph::read_snapshot(path);
    FAIL() << "a foreign HDF5 file was accepted";
  } catch (const SnapshotError& error) {
    EXPECT_NE(std::string(error.what()).find("not a revsph snapshot"), std::string::npos);
  }
}

} // namespace

namespace {

// Views are streamed into the file; a fault while deriving them keeps the exact state, the views
// written so far, and says why.
TEST(SnapshotFile, KeepsStateAndEarlierViewsWhenDerivingAViewFaults) {
  TempDirectory directory("revsph-snapshot-test");
  const StateSnapshot state = toy_state();
  const fs::path path = directory.path() / "fault.h5";
  const auto sets =
      revsph::write_snapshot(path, toy_metadata(state), state, [](const revsph::ViewSink& sink) {
        sink({"fluid", "temperature", "K", 1, {300.0, 301.0, 302.0, 303.0}});
        throw revsph::SimulationFault({"fluid", 2, "density", "not positive"}, 7);
      });
  const revsph::Snapshot read = revsph::read_checked_snapshot(path);
  EXPECT_NE(read.metadata.derived_fields_error.find("not positive"), std::string::npos);
  ASSERT_FALSE(sets.empty());
  bool has_temperature = false;
  for (const auto& field : sets[0].fields) {
    has_temperature = has_temperature || field.name == "temperature";
  }
  EXPECT_TRUE(has_temperature) << "the view written before the fault stays";
}

} // namespace
