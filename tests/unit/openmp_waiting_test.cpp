// Every program that links the core chooses how its threads wait at OpenMP barriers from the
// machine's load (core/openmp_waiting.hpp): run a program that links the core and calls nothing
// of it, with the environment the user might have, and read back what its main saw.

#include "core/openmp_waiting.hpp"

#include <gtest/gtest.h>

#include <array>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

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

TEST(OpenmpWaiting, SpinLongOnAnIdleMachineShortOnASharedOne) {
  EXPECT_STREQ(revsph::openmp_spin_count_for(0), "1000");
  EXPECT_STREQ(revsph::openmp_spin_count_for(1), "100");
  EXPECT_STREQ(revsph::openmp_spin_count_for(7), "100");
}

// Whatever else runs on the machine now, the program sets one of the two counts.
TEST(OpenmpWaiting, ProgramLinkingTheCoreChoosesASpinCount) {
  const std::string chosen = probe_output("");
  EXPECT_TRUE(chosen == "1000\n" || chosen == "100\n") << chosen;
}

// Beside two busy processes there is always another runnable task: the short count.
TEST(OpenmpWaiting, ProgramBesideBusyProcessesSpinsShortly) {
  std::vector<pid_t> busy;
  for (int i = 0; i < 2; ++i) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      volatile unsigned long spin = 0;
      while (true) {
        spin = spin + 1;
      }
    }
    busy.push_back(pid);
  }
  usleep(20000); // let them start running
  EXPECT_GE(revsph::other_runnable_tasks(), 1);
  const std::string chosen = probe_output("");
  for (const pid_t pid : busy) {
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
  }
  EXPECT_EQ(chosen, "100\n");
}

TEST(OpenmpWaiting, UsersOwnSpinCountIsKept) {
  EXPECT_EQ(probe_output("GOMP_SPINCOUNT=5"), "5\n");
}

TEST(OpenmpWaiting, UsersWaitPolicyIsKept) {
  EXPECT_EQ(probe_output("OMP_WAIT_POLICY=passive"), "unset\n");
}

} // namespace
