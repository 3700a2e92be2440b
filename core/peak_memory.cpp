#include "core/peak_memory.hpp"

#include <sys/resource.h>

namespace revsph {

std::size_t peak_resident_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024; // Linux reports kilobytes
}

} // namespace revsph
