#pragma once
// Peak resident memory of this process, for summaries and benchmarks.

#include <cstddef>

namespace revsph {

std::size_t peak_resident_bytes();

} // namespace revsph
