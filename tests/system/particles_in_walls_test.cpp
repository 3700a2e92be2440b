// `revsph run` counts the moving particles that pass into a wall (tools/revsph/particle_checks.hpp):
// a fluid falling through a floor that does not push back (wall energy 0) gets a warning naming
// the floor's block, and diagnostics.csv's particles_in_walls at the end equals the count made
// here from the last snapshot with the box test itself; the dam break of the shipped case keeps
// its fluid out of its container (0, no warning), as does a tank whose floor is a sloped stl
// ramp, though its fluid settles into the notches of the ramp's staircase of wall particles,
// under the smooth surface. Both progress lines give min r/dr.

#include "cli_sandbox.hpp"
#include "ramp_stl.hpp"

#include "core/logged_rows.hpp"
#include "core/snapshot_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace {

using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

// 100 fluid particles above a floor 0.1 m thick, in a gravity of 100 m/s^2, with nothing to hold
// them: by step 100 (t = 0.06 s) they have fallen 0.18 m, half of them into the floor.
const char* falling_case = R"(model = "wcsph"
dimension = 2
name = "through-the-floor"

[physics]
rest_density = 1000.0
sound_speed = 20.0
gravity = 100.0

[discretisation]
dr = 0.02
support_radius_over_dr = 3.0
courant_number = 0.2

[wall]
energy_per_mass = 0.0

[domain]
min = [-0.2, -1.0]
max = [0.4, 0.3]

[[particles]]
kind = "fluid"
min = [0.0, 0.0]
max = [0.2, 0.2]

[[particles]]
kind = "wall"
min = [-0.06, -0.1]
max = [0.26, 0.0]

[output]
energy_every = 10
)";

// The last row's particles_in_walls, and whether the column is there.
double last_in_walls(const std::filesystem::path& csv, bool& found) {
  const revsph::LoggedRows logged = revsph::read_logged_rows(csv);
  found = false;
  for (std::size_t c = 0; c < logged.columns.size(); ++c) {
    if (logged.columns[c] == "particles_in_walls" && !logged.rows.empty()) {
      found = true;
      return logged.rows.back()[c];
    }
  }
  return -1.0;
}

TEST(ParticlesInWalls, AFluidFallingThroughAFloorIsCountedAndWarnedOf) {
  Sandbox sandbox;
  sandbox.write_case(falling_case);
  const CommandResult result =
      sandbox.revsph({"run", "case.toml", "--steps", "100", "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_NE(result.out.find("fluid particles inside walls (particles[1] \"wall\" holds "),
            std::string::npos)
      << result;
  EXPECT_NE(result.out.find("check the wall's energy per mass, the sound speed and dt"),
            std::string::npos)
      << result;
  EXPECT_NE(result.out.find("min r/dr = "), std::string::npos) << result;
  EXPECT_NE(
      revsph::testing::read_file(sandbox.out() / "diagnostics.csv").find("particles_in_walls [1]"),
      std::string::npos);

  bool found = false;
  const double logged = last_in_walls(sandbox.out() / "diagnostics.csv", found);
  ASSERT_TRUE(found);
  EXPECT_GT(logged, 0.0);
  std::ifstream summary_file(sandbox.out() / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_GE(summary["diagnostics"]["max_particles_in_walls"].get<double>(), logged);
  EXPECT_EQ(summary["units"]["particles_in_walls"], "1");

  // The floor's own test on the last snapshot's positions: strictly inside [min, max].
  const revsph::Snapshot last = revsph::read_snapshot(summary["last_snapshot"].get<std::string>());
  EXPECT_EQ(last.metadata.step, 100);
  const revsph::FieldSnapshot* position = last.state.find("fluid", "position");
  ASSERT_NE(position, nullptr);
  int inside = 0;
  for (std::size_t i = 0; i < position->count; ++i) {
    const double x = position->real(0, i);
    const double y = position->real(1, i);
    inside += x > -0.06 && x < 0.26 && y > -0.1 && y < 0.0 ? 1 : 0;
  }
  EXPECT_EQ(logged, static_cast<double>(inside));
}

TEST(ParticlesInWalls, TheDamBreakKeepsItsFluidOutOfItsContainer) {
  Sandbox sandbox;
  const CommandResult result =
      sandbox.revsph({"run", "dambreak-small", "--steps", "300", "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(result.out.find("warning:"), std::string::npos) << result;
  EXPECT_NE(result.out.find("min r/dr = "), std::string::npos) << result;
  const revsph::LoggedRows logged = revsph::read_logged_rows(sandbox.out() / "diagnostics.csv");
  ASSERT_EQ(logged.columns.back(), "particles_in_walls");
  ASSERT_EQ(logged.rows.size(), 4u); // steps 0, 100, 200, 300
  for (const std::vector<double>& row : logged.rows) {
    EXPECT_EQ(row.back(), 0.0) << "step " << row.front();
  }
}

TEST(ParticlesInWalls, AFluidOnASlopedStlRampIsInNoWall) {
  Sandbox sandbox;
  sandbox.write_case(revsph::testing::ramp_case("ramp.stl"));
  std::ofstream(sandbox.work() / "ramp.stl") << revsph::testing::ramp_stl();
  const CommandResult result =
      sandbox.revsph({"run", "case.toml", "--steps", "200", "--set", "output.snapshot_every=100",
                      "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(result.out.find("warning:"), std::string::npos) << result;
  const revsph::LoggedRows logged = revsph::read_logged_rows(sandbox.out() / "diagnostics.csv");
  ASSERT_EQ(logged.rows.size(), 5u); // steps 0, 50, ..., 200
  for (const std::vector<double>& row : logged.rows) {
    EXPECT_EQ(row.back(), 0.0) << "step " << row.front();
  }
  // What the ramp's surface alone would count: fluid under z = 0.04 + 0.3 x, within 0.4 dr of
  // it (the staircase's notches are no deeper).
  const revsph::Snapshot last =
      revsph::read_snapshot(sandbox.out() / "snapshots" / "step_000000200.h5");
  const revsph::FieldSnapshot* position = last.state.find("fluid", "position");
  ASSERT_NE(position, nullptr);
  int under = 0;
  for (std::size_t i = 0; i < position->count; ++i) {
    const double x = position->real(0, i);
    const double depth = 0.04 + 0.3 * x - position->real(2, i);
    if (x > 0.0 && x < 0.4 && depth > 0.0) {
      ++under;
      EXPECT_LT(depth, 0.4 * 0.02);
    }
  }
  EXPECT_GT(under, 0);
}

} // namespace
