#include "tools/revsph/openmp_waiting.hpp"

#include <cstdlib>
#include <unistd.h>

namespace revsph::cli {

void use_short_openmp_spinning(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
    return; // the user's choice, or this process is the re-executed one
  }
  if (setenv("GOMP_SPINCOUNT", "1000", 1) != 0) {
    return;
  }
  execv("/proc/self/exe", argv);
}

} // namespace revsph::cli
