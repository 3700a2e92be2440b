// The worked examples of docs/point-files.md (issue 33), each run as its documented command: the
// script makes its input files next to a copy of the case, and `revsph verify` returns the run
// bit for bit (they are reversible), on 1 and 2 threads.

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

TEST(WorkedExamples, CsvVortexPatchReturnsBitwise) {
  Sandbox sandbox;
  const fs::path folder = examples / "csv-vortex-patch";
  fs::copy_file(folder / "vortex-patch.toml", sandbox.work() / "vortex-patch.toml");
  ASSERT_TRUE(run_script(sandbox, folder / "make_points.py", "--out vortex_patch.csv"));
  for (const char* threads : {"1", "2"}) {
    const CommandResult result =
        sandbox.revsph({"verify", "vortex-patch.toml", "--steps", "2000", "--threads", threads});
    EXPECT_EQ(result.exit_status, 0) << result;
    EXPECT_NE(result.out.find("verdict: bitwise identical"), std::string::npos) << result;
    // The file's velocities are the state's: the run's energy scale is the disc's kinetic
    // energy at the start, 1/2 rho dr^2 sum v^2 over the file's rows (20.34112 J/m).
    EXPECT_NE(result.out.find("energy moved 2.034112e+01"), std::string::npos) << result;
  }
}

} // namespace
