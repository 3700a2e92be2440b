// Restart: a run continued from a snapshot is the same run, bit for bit.

#include "core/snapshot_file.hpp"
#include "simulation_fixture.hpp"
#include "temp_directory.hpp"
#include "tools/revsph/commands.hpp"
#include "verify/snapshot_check.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <vector>

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

// The last row of a run's energy.csv, by column name.
std::map<std::string, double> last_energy_row(const fs::path& csv) {
  std::ifstream in(csv);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line)) {
    last = line;
  }
  std::map<std::string, double> row;
  std::stringstream names(header), values(last);
  std::string name, value;
  while (std::getline(names, name, ',') && std::getline(values, value, ',')) {
    row[name.substr(0, name.find(" ["))] = std::stod(value); // header cells: name [unit]
  }
  return row;
}

// `case_name` with `overrides` run n steps into DIR/whole (snapshots at least every n / 2), then
// continued from its step-n/2 snapshot for n / 2 steps into DIR/second.
void run_whole_then_continue(const fs::path& directory, const std::string& case_name,
                             const std::vector<std::string>& overrides, std::int64_t n) {
  RunOptions whole;
  whole.case_options.case_path = case_name;
  whole.case_options.overrides = overrides;
  whole.out_dir = (directory / "whole").string();
  whole.steps = n;
  ASSERT_EQ(run(whole), 0);
  RunOptions second_half;
  second_half.case_options.from_snapshot =
      (directory / "whole" / "snapshots" / snapshot_name(n / 2)).string();
  second_half.out_dir = (directory / "second").string();
  second_half.steps = n / 2;
  ASSERT_EQ(run(second_half), 0);
}

// The fountain with its heater and a conducting cooler: the energy given from outside is kept
// by the model, not by the particles; the snapshot carries it, so that the restarted run's
// budget (heater_input, wall_exchange, total) goes on as if never cut.
TEST(Restart, EnergyAccountsOfHeaterAndWallsGoOn) {
  TempDirectory directory("revsph-restart-test");
  const std::int64_t n = 60;
  run_whole_then_continue(directory.path(), "fountain-small",
                          {"physics.heat_conductivity=6.2", "physics.viscosity=1e-4",
                           "heater.power=80", "heater.centre=[0.0, 0.008]", "heater.support=0.004",
                           "heater.ramp_time=1e-4", "output.snapshot_every=30"},
                          n);

  const auto middle = revsph::read_checked_snapshot(directory.path() / "whole" / "snapshots" /
                                                    snapshot_name(n / 2));
  ASSERT_EQ(middle.metadata.energy_accounts.size(), 2u);
  const auto uninterrupted = last_energy_row(directory.path() / "whole" / "energy.csv");
  const auto restarted = last_energy_row(directory.path() / "second" / "energy.csv");
  EXPECT_GT(-uninterrupted.at("heater_input"), 0.0) << "the heater gave energy";
  for (const char* column : {"heater_input", "wall_exchange", "thermal", "total"}) {
    EXPECT_EQ(restarted.at(column), uninterrupted.at(column)) << column;
  }
  EXPECT_LT(restarted.at("relative_error"), 1e-6);
}

// After run_whole_then_continue: the continued run ends at step n in the uninterrupted run's
// state, with energy.csv's last row the same in `columns`, its dissipated energy positive.
void expect_same_end_and_accounts(const fs::path& folder, std::int64_t n,
                                  std::initializer_list<const char*> columns) {
  const auto uninterrupted_end =
      revsph::read_checked_snapshot(folder / "whole" / "snapshots" / snapshot_name(n));
  const auto restarted_end =
      revsph::read_checked_snapshot(folder / "second" / "snapshots" / snapshot_name(n));
  EXPECT_EQ(restarted_end.metadata.state_hash, uninterrupted_end.metadata.state_hash);
  const auto uninterrupted = last_energy_row(folder / "whole" / "energy.csv");
  const auto restarted = last_energy_row(folder / "second" / "energy.csv");
  EXPECT_GT(uninterrupted.at("dissipated"), 0.0);
  for (const char* column : columns) {
    EXPECT_EQ(restarted.at(column), uninterrupted.at(column)) << column;
  }
}

// The two-fluid rotating cylinder: the mutual friction's L(t) decays with the time (eq. 9), and
// the dissipated energy and the walls' work are the model's accounts. A continued run must take
// the time from the step count and the accounts from the snapshot: same state, same budget. Also
// with the wall-grip options (README "Wall grip"): the wall friction held at L0, the undiluted
// viscosity and the wall turning rigidly (its positions and velocities are in the snapshot).
class TwoFluidRestart : public ::testing::TestWithParam<std::vector<std::string>> {};

TEST_P(TwoFluidRestart, FrictionClockAndAccountsGoOn) {
  TempDirectory directory("revsph-restart-test");
  const std::int64_t n = 60;
  std::vector<std::string> overrides{"output.snapshot_every=30", "output.energy_every=30"};
  overrides.insert(overrides.end(), GetParam().begin(), GetParam().end());
  run_whole_then_continue(directory.path(), "rotating-cylinder-small", overrides, n);
  expect_same_end_and_accounts(directory.path(), n,
                               {"dissipated", "wall_work", "force_work", "total"});
}

INSTANTIATE_TEST_SUITE_P(TwoFluid, TwoFluidRestart,
                         ::testing::Values(std::vector<std::string>{},
                                           std::vector<std::string>{
                                               "mutual_friction.wall_line_density=initial",
                                               "physics.separate_phase_viscosity=undiluted",
                                               "particles[1].wall_motion=rigid"}));

// The settling dam break (wcsph with its artificial viscosity): the dissipated energy is the
// model's account; a continued run takes it from the snapshot, with the same state and budget.
TEST(Restart, WcsphDissipatedAccountGoesOn) {
  TempDirectory directory("revsph-restart-test");
  const std::int64_t n = 600;
  run_whole_then_continue(directory.path(), "dambreak-settling",
                          {"output.snapshot_every=300", "output.energy_every=300"}, n);
  expect_same_end_and_accounts(directory.path(), n, {"dissipated", "kinetic", "total"});
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

// Continued at another time step (say half the snapshot's, to see whether a fault depends on
// it), the run's clock goes on from the snapshot's time, not from steps * the new dt: --t-end
// means the simulated time, and the models that read the clock (a heater's ramp) see it.
TEST(Restart, ContinuedAtAnotherTimeStepKeepsTheSnapshotsTime) {
  TempDirectory directory("revsph-restart-test");
  RunOptions first;
  first.case_options.case_path = "dambreak-small";
  first.case_options.overrides = {"discretisation.courant_number=0.1"}; // dt = 0.5e-4 s
  first.out_dir = (directory.path() / "first").string();
  first.steps = 200; // t = 0.01 s
  ASSERT_EQ(run(first), 0);

  RunOptions second;
  second.case_options.from_snapshot =
      (directory.path() / "first" / "snapshots" / snapshot_name(200)).string();
  second.case_options.overrides = {"discretisation.courant_number=0.05"}; // dt = 0.25e-4 s
  second.out_dir = (directory.path() / "second").string();
  second.t_end = 0.015;
  ASSERT_EQ(run(second), 0);
  const fs::path end = directory.path() / "second" / "snapshots" / snapshot_name(400);
  ASSERT_TRUE(fs::exists(end)) << "0.005 s more at dt = 0.25e-4 s is 200 steps: step 400";
  const auto restarted = revsph::read_checked_snapshot(end);
  EXPECT_NEAR(restarted.metadata.time, 0.015, 1e-12);
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
