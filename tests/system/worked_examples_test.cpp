// The worked examples of docs/point-files.md and docs/periodic.md (issue 33), each run as its documented command: the
// script makes its input files (a CSV point file, an STL surface) next to a copy of the case,
// and `revsph verify` returns the run bit for bit (they are reversible), on 1 and 2 threads.

#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;
using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

const fs::path examples = fs::path(REVSPH_SOURCE_DIR) / "docs" / "examples";

// Runs `script` (with `arguments`) in the sandbox's folder; true if it succeeded.
bool run_script(const Sandbox& sandbox, const fs::path& script, const std::string& arguments) {
  const std::string command = "cd '" + sandbox.work().string() + "' && /usr/bin/python3 '" +
                              script.string() + "' " + arguments + " > /dev/null";
  return std::system(command.c_str()) == 0;
}

// `revsph verify CASE --steps 2000` on 1 and 2 threads: exit 0, bit for bit, and (if given) the
// energy scale `energy_moved` ("2.034112e+01"): the run's energy moved, computed from the file.
void expect_bitwise_on_one_and_two_threads(const Sandbox& sandbox, const std::string& case_file,
                                           const std::string& energy_moved = "") {
  for (const char* threads : {"1", "2"}) {
    const CommandResult result =
        sandbox.revsph({"verify", case_file, "--steps", "2000", "--threads", threads});
    EXPECT_EQ(result.exit_status, 0) << result;
    EXPECT_NE(result.out.find("verdict: bitwise identical"), std::string::npos) << result;
    if (!energy_moved.empty()) {
      EXPECT_NE(result.out.find("energy moved " + energy_moved), std::string::npos) << result;
    }
  }
}

TEST(WorkedExamples, CsvVortexPatchReturnsBitwise) {
  Sandbox sandbox;
  const fs::path folder = examples / "csv-vortex-patch";
  fs::copy_file(folder / "vortex-patch.toml", sandbox.work() / "vortex-patch.toml");
  ASSERT_TRUE(run_script(sandbox, folder / "make_points.py", "--out vortex_patch.csv"));
  // The file's velocities are the state's: the run's energy scale is the disc's kinetic energy
  // at the start, 1/2 rho dr^2 sum v^2 over the file's rows (20.34112 J/m).
  expect_bitwise_on_one_and_two_threads(sandbox, "vortex-patch.toml", "2.034112e+01");
}

TEST(WorkedExamples, StlDamBreakOntoAnObstacleReturnsBitwise) {
  Sandbox sandbox;
  const fs::path folder = examples / "stl-dambreak-3d";
  fs::copy_file(folder / "dambreak-obstacle.toml", sandbox.work() / "dambreak-obstacle.toml");
  ASSERT_TRUE(run_script(
      sandbox, fs::path(REVSPH_SOURCE_DIR) / "tools" / "geometry" / "make_obstacle_stl.py",
      "--box 0.6 0.075 0.0 0.7 0.175 0.15 --out obstacle.stl"));
  const CommandResult run =
      sandbox.revsph({"run", "dambreak-obstacle.toml", "--steps", "1", "--out", "run"});
  ASSERT_EQ(run.exit_status, 0) << run;
  // The tank's 4 128 wall particles and the obstacle's 4 x 4 x 6 filling its surface.
  EXPECT_NE(run.out.find("2000 fluid + 4224 wall"), std::string::npos) << run;
  expect_bitwise_on_one_and_two_threads(sandbox, "dambreak-obstacle.toml");
}

TEST(WorkedExamples, PeriodicShearLayerReturnsBitwise) {
  Sandbox sandbox;
  const fs::path folder = examples / "periodic-shear-layer";
  fs::copy_file(folder / "shear-layer.toml", sandbox.work() / "shear-layer.toml");
  ASSERT_TRUE(run_script(sandbox, folder / "make_points.py", "--out shear_layer.csv"));
  // 1/2 rho dr^2 sum (u^2 + v^2) over the file's 1 600 rows: the layers' kinetic energy.
  expect_bitwise_on_one_and_two_threads(sandbox, "shear-layer.toml", "4.339651e-01");
  // The images across the faces do not depend on the cell size: the same hash after 300 steps.
  std::string hashes[2];
  int n = 0;
  for (const char* factor : {"1.0", "1.7"}) {
    const CommandResult run = sandbox.revsph(
        {"run", "shear-layer.toml", "--steps", "300", "--out", std::string("run") + factor, "--set",
         std::string("discretisation.cell_size_factor=") + factor});
    ASSERT_EQ(run.exit_status, 0) << run;
    const std::size_t at = run.out.find("state hash: ");
    ASSERT_NE(at, std::string::npos) << run;
    hashes[n++] = run.out.substr(at, 76);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

} // namespace
