// `revsph entropy` on a run of every model with its default particle set (issue 33's fault list:
// it failed on shtc runs until --particle-set material was given, and on entropic runs for every
// set, whose state has momenta, not velocities).

#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

struct ModelRun {
  std::string model_case;
  std::string expected_set; // the set the default picks
};

class EntropyCli : public ::testing::TestWithParam<ModelRun> {};

TEST_P(EntropyCli, DefaultSetWorksForEveryModel) {
  Sandbox sandbox;
  const fs::path run = sandbox.work() / "run";
  const CommandResult made = sandbox.revsph(
      {"run", GetParam().model_case, "--steps", "4", "--threads", "1", "--out", run.string()});
  ASSERT_EQ(made.exit_status, 0) << made;
  const CommandResult result = sandbox.revsph({"entropy", run.string(), "--no-plots"});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_NE(result.out.find(" " + GetParam().expected_set + " particles"), std::string::npos)
      << result;
  EXPECT_TRUE(fs::is_regular_file(run / "analysis" / "entropy.csv"));
}

// An --out that cannot be created is bad input (exit 2, one line), not a filesystem error (exit 3).
TEST(EntropyCliOut, OutputDirectoryThatCannotBeCreatedIsBadInput) {
  Sandbox sandbox;
  const fs::path run = sandbox.work() / "run";
  const CommandResult made =
      sandbox.revsph({"run", "dambreak-small", "--steps", "2", "--out", run.string()});
  ASSERT_EQ(made.exit_status, 0) << made;
  const fs::path blocker = sandbox.work() / "blocker";
  std::ofstream(blocker) << "a file\n";
  const CommandResult result = sandbox.revsph(
      {"entropy", run.string(), "--no-plots", "--out", (blocker / "analysis").string()});
  EXPECT_EQ(result.exit_status, 2) << result;
  EXPECT_NE(result.err.find("--out: "), std::string::npos) << result;
  EXPECT_NE(result.err.find(" is not a directory"), std::string::npos) << result;
}

// The snapshots analysed are the run's series, the one run.xdmf and the Python reader use: a run
// stopped off its output cadence and continued in its folder keeps that stop's snapshot on disk,
// out of the series.
TEST(EntropyCliSeries, LeavesOutAnEarlierSegmentsOffCadenceEnd) {
  Sandbox sandbox;
  const fs::path run = sandbox.work() / "run";
  const CommandResult first = sandbox.revsph({"run", "dambreak-small", "--steps", "7", "--set",
                                              "output.snapshot_every=5", "--out", run.string()});
  ASSERT_EQ(first.exit_status, 0) << first;
  const fs::path stop = run / "snapshots" / "step_000000007.h5";
  const CommandResult second = sandbox.revsph({"run", "--from", stop.string(), "--steps", "5"});
  ASSERT_EQ(second.exit_status, 0) << second;
  ASSERT_TRUE(fs::is_regular_file(stop));
  const CommandResult result = sandbox.revsph({"entropy", run.string(), "--no-plots"});
  ASSERT_EQ(result.exit_status, 0) << result;
  std::ifstream csv(run / "analysis" / "entropy.csv");
  std::string line;
  std::getline(csv, line); // header
  std::vector<std::string> steps;
  while (std::getline(csv, line)) {
    const std::size_t phase_end = line.find(',');
    steps.push_back(line.substr(phase_end + 1, line.find(',', phase_end + 1) - phase_end - 1));
  }
  // Every 5 steps and the last, step 12.
  EXPECT_EQ(steps, (std::vector<std::string>{"0", "5", "10", "12"})) << result;
}

INSTANTIATE_TEST_SUITE_P(Models, EntropyCli,
                         ::testing::Values(ModelRun{"dambreak-small", "fluid"},
                                           ModelRun{"twisting-column-small", "material"},
                                           ModelRun{"box-small", "gas"},
                                           ModelRun{"droplet-small", "fluid"},
                                           ModelRun{"rayleigh-taylor-small", "superfluid"}),
                         [](const ::testing::TestParamInfo<ModelRun>& param) {
                           std::string name = param.param.model_case;
                           for (char& c : name) {
                             c = c == '-' ? '_' : c;
                           }
                           return name;
                         });

} // namespace
