#include "core/openmp_waiting.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <unistd.h>

namespace revsph {

const char* openmp_spin_count_for(int other_runnable) {
  return other_runnable > 0 ? "100" : "1000";
}

int other_runnable_tasks() {
  int fewest = -1;
  for (int sample = 0; sample < 3; ++sample) {
    if (sample > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    // The fourth field of /proc/loadavg: runnable tasks / all tasks, this one included.
    std::ifstream loadavg("/proc/loadavg");
    std::string one, five, fifteen;
    int runnable = 0;
    char slash = 0;
    if (!(loadavg >> one >> five >> fifteen >> runnable >> slash) || slash != '/') {
      return 0;
    }
    const int others = std::max(runnable - 1, 0);
    fewest = fewest < 0 ? others : std::min(fewest, others);
  }
  return std::max(fewest, 0);
}

std::string openmp_waiting_description() {
  if (const char* spin_count = std::getenv("GOMP_SPINCOUNT")) {
    return std::string("spin count ") + spin_count;
  }
  if (const char* policy = std::getenv("OMP_WAIT_POLICY")) {
    return std::string("OMP_WAIT_POLICY=") + policy;
  }
  return "libgomp's default";
}

void choose_openmp_spinning(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
    return; // the user's choice, or this process is the re-executed one
  }
  if (argv == nullptr || argv[0] == nullptr ||
      setenv("GOMP_SPINCOUNT", openmp_spin_count_for(other_runnable_tasks()), 1) != 0) {
    return;
  }
  execv("/proc/self/exe", argv);
}

} // namespace revsph

// glibc calls the functions of .init_array with (argc, argv, envp): this one runs before main in
// every program linked with the core. The symbol below is what the core's link option
// (-u revsph_openmp_waiting_anchor, core/CMakeLists.txt) asks for, so that the linker takes this
// file out of the static library even when nothing else in it is called.
extern "C" {
int revsph_openmp_waiting_anchor = 0;
}

namespace {

[[gnu::constructor]] void choose_openmp_spinning_before_main(int /*argc*/, char** argv,
                                                             char** /*envp*/) {
  revsph::choose_openmp_spinning(argv);
}

} // namespace
