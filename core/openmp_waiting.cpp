#include "core/openmp_waiting.hpp"

#include <cstdlib>
#include <unistd.h>

namespace revsph {

void use_short_openmp_spinning(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
    return; // the user's choice, or this process is the re-executed one
  }
  if (argv == nullptr || argv[0] == nullptr || setenv("GOMP_SPINCOUNT", "1000", 1) != 0) {
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

[[gnu::constructor]] void short_openmp_spinning_before_main(int /*argc*/, char** argv,
                                                            char** /*envp*/) {
  revsph::use_short_openmp_spinning(argv);
}

} // namespace
