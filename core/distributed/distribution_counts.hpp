#pragma once
// How a distributed run's particles are spread over the processes, for summary.json's
// "distribution" record and the partition measurements (docs/design/distributed.md): this
// process's counts, which the caller combines over the processes.

#include <cstdint>

namespace revsph::distributed {

struct DistributionCounts {
  std::uint64_t own_particles = 0;    // every set's own rows
  std::uint64_t ghosts = 0;           // copies of other processes' particles held here
  std::uint64_t copies_sent = 0;      // of own particles, to other processes, per ghost refresh
  std::uint64_t ghost_lists_made = 0; // at setup, after migrations and after rebalances
  std::uint64_t rebalances = 0;       // regions cut again because the work had drifted apart
  std::uint64_t rebalances_by_measured_time = 0; // of them, decided on measured computing times
  double work = 0.0;                             // the partition's estimate of this process's work
};

} // namespace revsph::distributed
