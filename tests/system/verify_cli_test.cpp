// `revsph verify` end to end: a case with irreversible terms runs the reversal experiment and is
// told how far it landed, its energy budget and its entropy, with a verdict and an exit status
// that follow docs/verify.md; the reversible path still answers "bitwise identical".

#include "cli_sandbox.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
  }
  return lines;
}

// The one line starting with `prefix` (fails the test if there is not exactly one).
std::string line_starting(const CommandResult& result, const std::string& prefix) {
  std::vector<std::string> found;
  for (const std::string& line : lines_of(result.out)) {
    if (line.rfind(prefix, 0) == 0) {
      found.push_back(line);
    }
  }
  EXPECT_EQ(found.size(), 1u) << "lines starting with \"" << prefix << "\": " << result;
  return found.empty() ? std::string() : found[0];
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(VerifyCli, IrreversibleCaseRunsTheReversalAndReportsDistanceBudgetAndEntropy) {
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph(
      {"verify", "cavity-re100-small", "--steps", "200", "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(result.err, "") << result;
  EXPECT_TRUE(contains(result.out, "irreversible term: relaxation: relaxation of the distortion"))
      << result;
  EXPECT_TRUE(contains(result.out, "backward 400/400 steps")) << "both halves ran: " << result;

  const std::string velocity = line_starting(result, "  material.velocity: max ");
  EXPECT_TRUE(contains(velocity, " m/s, RMS ")) << velocity;
  EXPECT_TRUE(contains(velocity, "units in the last place")) << velocity;
  const std::string budget = line_starting(result, "energy budget: max |E(t) - E(0)| / largest ");
  EXPECT_TRUE(contains(budget, "(tolerance 1.0e-02)")) << budget;
  const std::string entropy = line_starting(result, "entropy of the material speeds");
  EXPECT_TRUE(contains(entropy, "start ") && contains(entropy, "turning point ")) << entropy;
  const std::string verdict = line_starting(result, "verdict: ");
  EXPECT_EQ(verdict.rfind("verdict: not reversible by design: 1 irreversible term (relaxation: "
                          "relaxation of the distortion); returned to within ",
                          0),
            0u)
      << verdict;
  EXPECT_TRUE(contains(verdict, " m/s (material.velocity)")) << verdict;
  EXPECT_TRUE(contains(verdict, "; energy budget closes to ")) << verdict;

  std::ifstream summary_file(sandbox.out() / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary["verdict"], verdict.substr(std::string("verdict: ").size()));
  EXPECT_EQ(summary["exit_status"], 0);
  EXPECT_EQ(summary["identical"], false);
  ASSERT_EQ(summary["irreversible_terms"].size(), 1u);
  const nlohmann::json& distance = summary["distance"]["material.velocity"];
  EXPECT_EQ(distance["unit"], "m/s");
  const double max = distance["max"].get<double>();
  const double rms = distance["rms"].get<double>();
  EXPECT_GT(rms, 0.0);
  EXPECT_LE(rms, max);
  EXPECT_LT(max, 1.0) << "the fluid came back close to rest";
  EXPECT_GT(distance["max_units_in_last_place"].get<double>(), 0.0);
  EXPECT_EQ(summary["energy_budget"]["closes"], true);
  EXPECT_LE(summary["energy_budget"]["max_relative_error"].get<double>(), 1e-2);
  EXPECT_EQ(summary["entropy"]["particle_set"], "material");
  EXPECT_TRUE(summary["energy"].contains("max_mechanical_relative_error_forward"));
  for (const char* half : {"forward", "backward"}) {
    EXPECT_TRUE(fs::is_regular_file(sandbox.out() / half / "energy.csv")) << half;
    EXPECT_TRUE(fs::is_directory(sandbox.out() / half / "snapshots")) << half;
  }
}

TEST(VerifyCli, IrreversibleCaseFailsWhenItsBudgetDoesNotClose) {
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph(
      {"verify", "cavity-re100-small", "--steps", "20", "--energy-tolerance", "1e-12"});
  EXPECT_EQ(result.exit_status, 1) << result;
  EXPECT_TRUE(contains(line_starting(result, "verdict: "), "energy budget does NOT close: "))
      << result;
}

// The WCSPH model's artificial viscosity is an irreversible term like SHTC's relaxation: verify
// names it with its placement, says how far the dam break lands, and checks the budget with the
// dissipated energy in it.
TEST(VerifyCli, ArtificialViscosityIsReportedIrreversibleWithHowFarItLands) {
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph({"verify", "dambreak-settling", "--steps", "200"});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_TRUE(contains(result.out, "irreversible term: artificial_viscosity: Monaghan's artificial "
                                   "viscosity (alpha = 0.1"))
      << result;
  EXPECT_TRUE(contains(result.out, "half steps at the step's ends")) << result;
  EXPECT_TRUE(contains(line_starting(result, "  fluid.velocity: max "), " m/s, RMS ")) << result;
  const std::string verdict = line_starting(result, "verdict: ");
  EXPECT_EQ(verdict.rfind("verdict: not reversible by design: 1 irreversible term "
                          "(artificial_viscosity: Monaghan's artificial viscosity); returned to "
                          "within ",
                          0),
            0u)
      << verdict;
  EXPECT_TRUE(contains(verdict, " m (fluid.position)")) << verdict;
  EXPECT_TRUE(contains(verdict, "; energy budget closes to ")) << verdict;
}

TEST(VerifyCli, ReversibleCaseStillReturnsBitwise) {
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph({"verify", "dambreak-small", "--steps", "200"});
  EXPECT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(line_starting(result, "verdict: ").rfind("verdict: bitwise identical (", 0), 0u)
      << result;
  EXPECT_FALSE(contains(result.out, "distance of the returned state")) << result;
  EXPECT_FALSE(contains(result.out, "irreversible")) << result;
}

TEST(VerifyCli, FloatArithmeticReportsHowFarItLanded) {
  Sandbox sandbox;
  const CommandResult result =
      sandbox.revsph({"verify", "dambreak-small", "--arithmetic", "float", "--steps", "100"});
  EXPECT_EQ(result.exit_status, 1) << result;
  EXPECT_TRUE(contains(result.out, "over the unit of the variable's fixed-point scale, rounded up "
                                   "(not IEEE ULPs)"))
      << result;
  EXPECT_TRUE(contains(line_starting(result, "  fluid.position: max "), " m, RMS ")) << result;
  EXPECT_TRUE(contains(line_starting(result, "verdict: "), "NOT identical")) << result;
}

} // namespace
