// Prints the GOMP_SPINCOUNT this program's main sees: the core chooses it before main
// (core/openmp_waiting.hpp); tests/unit/openmp_waiting_test.cpp checks that it does. Calls
// nothing of the core itself: linking it must be enough.

#include <cstdio>
#include <cstdlib>

int main() {
  const char* spin_count = std::getenv("GOMP_SPINCOUNT");
  std::printf("%s\n", spin_count != nullptr ? spin_count : "unset");
  return 0;
}
