#pragma once
// Memory of this process and of the machine, for summaries, benchmarks and the check that a
// case fits before anything is allocated.

#include <cstddef>
#include <string>

namespace revsph {

std::size_t peak_resident_bytes();

// Memory the machine can give this process now (MemAvailable of /proc/meminfo, or the physical
// memory if that is unknown).
std::size_t available_memory_bytes();

// "1.5 GB"
std::string format_bytes(double bytes);

// Gives a container's storage back (`c = {}` or clear() keep a vector's capacity).
template <class Container>
void free_storage(Container& container) {
  Container().swap(container);
}

} // namespace revsph
