#pragma once
// Which rows of a particle set one process holds in a distributed run
// (docs/design/distributed.md): what a hash, a snapshot or a comparison of the whole state needs
// to put the pieces back in the run's canonical order.

#include <cstdint>
#include <string>
#include <vector>

namespace revsph {

// One particle set's rows on this process: their global indices (ascending) and the set's
// particle count over every process.
struct SetRows {
  std::string set;
  std::vector<std::uint64_t> indices;
  std::uint64_t total = 0;
};

} // namespace revsph
