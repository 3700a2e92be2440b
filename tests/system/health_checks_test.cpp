// `revsph run`'s health checks (core/run_health.hpp, docs/running.md "Health checks"): the
// periodic shear layer of docs/examples (its vortices), blown up by the anti-clump force, ends
// unhealthy with warnings, exit 0, and exit 3 with --strict; pairs of particles closer than a
// fraction of dr are counted in diagnostics.csv (close_pairs, merged_pairs) as a count over
// every pair of the snapshot's positions finds them; the shipped dam break and a driven cavity
// starting at rest stay healthy.

#include "cli_sandbox.hpp"
#include "shear_layer_example.hpp"

#include "core/logged_rows.hpp"
#include "core/snapshot_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

// 10 x 10 fluid particles at rest, and 2 x 2 more 0.05 dr beside four of them (overlapping
// blocks are refused only closer than 1e-6 dr): 4 pairs closer than 0.1 dr at the start.
const char* merged_pairs = R"(model = "wcsph"
dimension = 2
name = "merged-pairs"

[physics]
rest_density = 1000.0
sound_speed = 20.0
gravity = 0.0

[discretisation]
dr = 0.02
support_radius_over_dr = 3.0
courant_number = 0.2

[domain]
min = [-0.1, -0.1]
max = [0.3, 0.3]

[[particles]]
kind = "fluid"
min = [0.0, 0.0]
max = [0.2, 0.2]

[[particles]]
kind = "fluid"
min = [0.081, 0.08]
max = [0.121, 0.12]

[output]
energy_every = 20
)";

nlohmann::json read_summary(const Sandbox& sandbox) {
  std::ifstream file(sandbox.out() / "summary.json");
  return nlohmann::json::parse(file);
}

// The column `name` of diagnostics.csv, row by row.
std::vector<double> column(const Sandbox& sandbox, const std::string& name) {
  const revsph::LoggedRows logged = revsph::read_logged_rows(sandbox.out() / "diagnostics.csv");
  std::vector<double> values;
  for (std::size_t c = 0; c < logged.columns.size(); ++c) {
    if (logged.columns[c] == name) {
      for (const std::vector<double>& row : logged.rows) {
        values.push_back(row[c]);
      }
    }
  }
  return values;
}

// Every pair of fluid particles of a snapshot closer than `distance`.
int pairs_closer_than(const std::string& snapshot, double distance) {
  const revsph::Snapshot read = revsph::read_snapshot(snapshot);
  const revsph::FieldSnapshot* position = read.state.find("fluid", "position");
  int pairs = 0;
  for (std::size_t a = 0; a < position->count; ++a) {
    for (std::size_t b = a + 1; b < position->count; ++b) {
      pairs += std::hypot(position->real(0, a) - position->real(0, b),
                          position->real(1, a) - position->real(1, b)) < distance
                   ? 1
                   : 0;
    }
  }
  return pairs;
}

TEST(HealthChecks, AShearLayerBlownUpByTheAntiClumpForceIsUnhealthy) {
  // 20 x 20 particles (dr = 0.05), whose layers roll up into vortices; the anti-clump force of
  // paper 1 App. A at p0 = 10 Pa (rho c^2 = 100 Pa) kicks the pairs that the vortices bring
  // closer than dr / 2: by step 400 (t = 1.2 s) energy has come from nowhere (the force's work
  // is outside the budget; relative_error 1.02) and max|v|/c is 4.4, by step 500 49.5. The same
  // run without the force stays below 0.16 and 2e-5.
  Sandbox sandbox;
  ASSERT_TRUE(revsph::testing::write_shear_layer_example(sandbox, 20));
  const std::vector<std::string> run = {
      "run",   "shear-layer.toml",       "--steps", "500",
      "--set", "discretisation.dr=0.05", "--set",   "physics.anti_clump_pressure=10",
      "--out", sandbox.out().string()};
  const CommandResult result = sandbox.revsph(run);
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_NE(result.out.find("above health.max_speed_over_c = 10: "), std::string::npos) << result;
  EXPECT_NE(result.out.find("above health.max_energy_error = 0.5 "), std::string::npos) << result;
  const nlohmann::json summary = read_summary(sandbox);
  EXPECT_TRUE(summary["completed"].get<bool>());
  EXPECT_FALSE(summary["healthy"].get<bool>());
  ASSERT_GE(summary["health_reasons"].size(), 2u);
  EXPECT_GT(summary["diagnostics"]["max_speed_over_c"].get<double>(), 10.0);
  EXPECT_GT(summary["energy"]["max_relative_error"].get<double>(), 0.5);

  std::vector<std::string> strict = run;
  strict.push_back("--strict");
  strict.push_back("--force");
  const CommandResult strict_result = sandbox.revsph(strict);
  EXPECT_EQ(strict_result.exit_status, 3) << strict_result;
  EXPECT_NE(strict_result.err.find("revsph: error: the run is unhealthy (--strict): "),
            std::string::npos)
      << strict_result;
  EXPECT_FALSE(read_summary(sandbox)["healthy"].get<bool>());
}

TEST(HealthChecks, MergedPairsAreCountedAsEveryPairFindsThem) {
  // With merged pairs taken as closer than dr / 10 here (the set-up refuses particles of two
  // blocks closer than 1e-6 of their spacing, the default), the 4 pairs at the start are merged
  // and close; both counts of the last record are those over every pair of the last snapshot.
  Sandbox sandbox;
  sandbox.write_case(merged_pairs);
  const CommandResult result = sandbox.revsph(
      {"run", "case.toml", "--steps", "200", "--out", sandbox.out().string(), "--set",
       "output.snapshot_every=200", "--set", "health.merged_pair_fraction=0.1", "--set",
       "health.close_pair_fraction=0.5"});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_NE(result.out.find("warning: step 0, t = 0 s: merged pairs = 4 (particles closer than "
                            "0.1 dr, health.merged_pair_fraction): particles have merged; 4 "
                            "pairs closer than 0.5 dr"),
            std::string::npos)
      << result;
  const std::vector<double> merged = column(sandbox, "merged_pairs");
  const std::vector<double> close = column(sandbox, "close_pairs");
  ASSERT_EQ(merged.size(), 11u);
  ASSERT_EQ(close.size(), 11u);
  EXPECT_EQ(merged.front(), 4.0);
  const nlohmann::json summary = read_summary(sandbox);
  const std::string last = summary["last_snapshot"].get<std::string>();
  EXPECT_EQ(merged.back(), pairs_closer_than(last, 0.1 * 0.02));
  EXPECT_EQ(close.back(), pairs_closer_than(last, 0.5 * 0.02));
  EXPECT_FALSE(summary["healthy"].get<bool>());
  EXPECT_EQ(summary["units"]["merged_pairs"], "1");
  EXPECT_GE(summary["diagnostics"]["max_merged_pairs"].get<double>(), 4.0);

  // The default limit: the same pairs are close, not merged.
  const CommandResult by_default = sandbox.revsph(
      {"run", "case.toml", "--steps", "20", "--out", sandbox.out().string(), "--force"});
  ASSERT_EQ(by_default.exit_status, 0) << by_default;
  EXPECT_EQ(by_default.out.find("warning:"), std::string::npos) << by_default;
  EXPECT_EQ(column(sandbox, "close_pairs").front(), 4.0);
  EXPECT_EQ(column(sandbox, "merged_pairs").front(), 0.0);
  EXPECT_TRUE(read_summary(sandbox)["healthy"].get<bool>());
}

TEST(HealthChecks, TheShippedDamBreakStaysHealthy) {
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph(
      {"run", "dambreak-small", "--steps", "300", "--strict", "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(result.out.find("warning:"), std::string::npos) << result;
  const nlohmann::json summary = read_summary(sandbox);
  EXPECT_TRUE(summary["healthy"].get<bool>());
  EXPECT_TRUE(summary["health_reasons"].empty());
  EXPECT_EQ(column(sandbox, "merged_pairs").size(), column(sandbox, "speed_over_c").size());
  EXPECT_FALSE(column(sandbox, "merged_pairs").empty());
}

TEST(HealthChecks, ADrivenCavityStartingAtRestIsHealthy) {
  // E(0) = 0 and every term 0 at the start: energy.csv's first relative_error is 0 / 0, which is
  // no error.
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph(
      {"run", "cavity-re100-small", "--steps", "200", "--strict", "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(result.out.find("warning:"), std::string::npos) << result;
  EXPECT_TRUE(read_summary(sandbox)["healthy"].get<bool>());
}

} // namespace
