#include "core/distributed/ghost_plan.hpp"

namespace revsph::distributed {

GhostPlan::GhostPlan(const SpatialPartition& partition, std::span<const double> positions,
                     double reach)
    : sent_per_process_(static_cast<std::size_t>(process_count()), 0) {
  const auto d = static_cast<std::size_t>(partition.dimension());
  const std::size_t count = positions.size() / d;
  const int me = process_rank();
  // Destinations of each particle, then the particles grouped by destination (a counting sort,
  // which keeps the particle order within each group).
  std::vector<std::vector<int>> needed_by(count);
  for (std::size_t i = 0; i < count; ++i) {
    partition.processes_near(positions.subspan(i * d, d), reach, me, needed_by[i]);
    for (const int p : needed_by[i]) {
      ++sent_per_process_[static_cast<std::size_t>(p)];
    }
  }
  std::vector<std::size_t> next(sent_per_process_.size(), 0);
  std::size_t total = 0;
  for (std::size_t p = 0; p < next.size(); ++p) {
    next[p] = total;
    total += sent_per_process_[p];
  }
  sent_particles_.resize(total);
  for (std::size_t i = 0; i < count; ++i) {
    for (const int p : needed_by[i]) {
      sent_particles_[next[static_cast<std::size_t>(p)]++] = static_cast<std::uint32_t>(i);
    }
  }
  // The receivers learn their ghost counts from one exchange of a byte per ghost.
  const std::vector<std::byte> marks(total, std::byte{1});
  ghost_count_ = exchange_bytes(marks, sent_per_process_, ghosts_from_process_).size();
}

} // namespace revsph::distributed
