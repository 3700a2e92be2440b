// What `revsph run --help` tells a user (issue 33's fault list): the exit statuses, and that
// after --from --steps counts more steps while --t-end is the absolute time the run ends at.

#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

TEST(CliHelp, RunHelpGivesExitStatusesAndHowLengthsCountAfterFrom) {
  Sandbox sandbox;
  const CommandResult result = sandbox.revsph({"run", "--help"});
  ASSERT_EQ(result.exit_status, 0) << result;
  for (const std::string part : {"Exit status: 0 ", "2 bad input", "3 the simulation stopped",
                                 "after --from: this many more steps", "absolute: after --from"}) {
    EXPECT_NE(result.out.find(part), std::string::npos) << part << "\n" << result;
  }
}

} // namespace
