// Every program that links the core waits at OpenMP barriers the short way
// (core/openmp_waiting.hpp): run a program that links the core and calls nothing of it, with
// the environment the user might have, and read back what its main saw.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

namespace {

std::string probe_output(const std::string& environment) {
  const std::string command =
      "env -u GOMP_SPINCOUNT -u OMP_WAIT_POLICY " + environment + " " + REVSPH_OPENMP_WAITING_PROBE;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) {
    return "popen failed";
  }
  std::array<char, 128> buffer{};
  std::string output;
  while (std::fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) {
    output += buffer.data();
  }
  return output;
}

TEST(OpenmpWaiting, ProgramLinkingTheCoreSpinsShortlyByDefault) {
  EXPECT_EQ(probe_output(""), "1000\n");
}

TEST(OpenmpWaiting, UsersOwnSpinCountIsKept) {
  EXPECT_EQ(probe_output("GOMP_SPINCOUNT=5"), "5\n");
}

TEST(OpenmpWaiting, UsersWaitPolicyIsKept) {
  EXPECT_EQ(probe_output("OMP_WAIT_POLICY=passive"), "unset\n");
}

} // namespace
