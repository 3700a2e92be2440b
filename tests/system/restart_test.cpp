// Restart: a run continued from a snapshot is the same run, bit for bit.

#include "core/snapshot_file.hpp"
#include "simulation_fixture.hpp"
#include "temp_directory.hpp"
#include "tools/revsph/commands.hpp"
#include "verify/snapshot_check.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace {

namespace fs = std::filesystem;
using revsph::cli::RunOptions;
using revsph::testing::TempDirectory;

std::string snapshot_name(std::int64_t step) {
  char name[64];
  std::snprintf(name, sizeof name, "step_%09lld.h5", static_cast<long long>(step));
  return name;
}

// `revsph run` through the CLI library, quietly.
int run(RunOptions options) {
  std::fflush(stdout);
  return revsph::cli::run_command(options);
}

TEST(Restart, HalfRunPlusRestartPlusHalfRunEqualsOneRun) {
  TempDirectory directory("revsph-restart-test");
  const std::int64_t n = 1000;

  RunOptions whole;
  whole.case_options.case_path = "dambreak-small";
  whole.case_options.overrides = {"output.snapshot_every=250"};
  whole.out_dir = (directory.path() / "whole").string();
  whole.steps = n;
  ASSERT_EQ(run(whole), 0);

  RunOptions first_half = whole;
  first_half.out_dir = (directory.path() / "first").string();
  first_half.steps = n / 2;
  ASSERT_EQ(run(first_half), 0);

  RunOptions second_half;
  second_half.case_options.from_snapshot =
      (directory.path() / "first" / "snapshots" / snapshot_name(n / 2)).string();
  second_half.out_dir = (directory.path() / "second").string();
  second_half.steps = n / 2;
  ASSERT_EQ(run(second_half), 0);

  const auto uninterrupted =
      revsph::read_checked_snapshot(directory.path() / "whole" / "snapshots" / snapshot_name(n));
  const auto restarted =
      revsph::read_checked_snapshot(directory.path() / "second" / "snapshots" / snapshot_name(n));
  EXPECT_EQ(restarted.metadata.step, n);
  EXPECT_EQ(restarted.metadata.state_hash, uninterrupted.metadata.state_hash);
  // And both equal the state of a simulation stepped n times in memory.
  auto simulation = revsph::testing::make_simulation("dambreak-small");
  simulation->advance(n);
  EXPECT_EQ(revsph::testing::hash_of(*simulation), uninterrupted.metadata.state_hash);
  // The restarted run measures its energy error against the original E(0).
  ASSERT_TRUE(restarted.metadata.reference_energy.has_value());
  EXPECT_EQ(*restarted.metadata.reference_energy, *uninterrupted.metadata.reference_energy);
  // Intermediate snapshots of the restarted run match too (step 750).
  EXPECT_EQ(
      revsph::read_checked_snapshot(directory.path() / "second" / "snapshots" / snapshot_name(750))
          .metadata.state_hash,
      revsph::read_checked_snapshot(directory.path() / "whole" / "snapshots" / snapshot_name(750))
          .metadata.state_hash);
}

TEST(Restart, OverridesOfTheOriginalRunAreKept) {
  TempDirectory directory("revsph-restart-test");
  RunOptions first;
  first.case_options.case_path = "dambreak-small";
  first.case_options.overrides = {"discretisation.courant_number=0.1"};
  first.out_dir = (directory.path() / "first").string();
  first.steps = 200;
  ASSERT_EQ(run(first), 0);

  RunOptions second;
  second.case_options.from_snapshot =
      (directory.path() / "first" / "snapshots" / snapshot_name(200)).string();
  second.out_dir = (directory.path() / "second").string();
  second.steps = 200;
  ASSERT_EQ(run(second), 0);
  const auto restarted =
      revsph::read_checked_snapshot(directory.path() / "second" / "snapshots" / snapshot_name(400));
  EXPECT_DOUBLE_EQ(restarted.metadata.dt, 0.5e-4) << "dt of the overridden Courant number";
  ASSERT_EQ(restarted.metadata.overrides.size(), 1u);

  auto simulation = revsph::testing::make_simulation("dambreak-small",
                                                     {{"discretisation.courant_number", "0.1"}});
  simulation->advance(400);
  EXPECT_EQ(revsph::testing::hash_of(*simulation), restarted.metadata.state_hash);
}

TEST(Restart, VerifyCanStartFromASnapshot) {
  TempDirectory directory("revsph-restart-test");
  RunOptions first;
  first.case_options.case_path = "dambreak-small";
  first.out_dir = (directory.path() / "first").string();
  first.steps = 300;
  ASSERT_EQ(run(first), 0);
  revsph::cli::VerifyCommandOptions verify;
  verify.case_options.from_snapshot =
      (directory.path() / "first" / "snapshots" / snapshot_name(300)).string();
  verify.steps = 300;
  std::fflush(stdout);
  EXPECT_EQ(revsph::cli::verify_command(verify), 0);
}

} // namespace
