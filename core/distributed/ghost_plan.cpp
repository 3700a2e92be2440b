#include "core/distributed/ghost_plan.hpp"

namespace revsph::distributed {

GhostPlan::GhostPlan(const SpatialPartition& partition, std::span<const double> positions,
                     double reach, const PeriodicBox& period)
    : sent_per_process_(static_cast<std::size_t>(process_count()), 0) {
  const auto d = static_cast<std::size_t>(partition.dimension());
  const std::size_t count = positions.size() / d;
  const int me = process_rank();
  // Destinations of each particle (with the image each gets: a particle within the reach of a
  // periodic face goes, shifted by the period, to whichever process, this one included, holds the
  // region beyond the opposite face), then the particles grouped by destination (a counting sort,
  // which keeps the particle order within each group).
  struct Destination {
    int process;
    ImageShift shift;
  };
  std::vector<std::vector<Destination>> needed_by(count);
  std::vector<int> processes;
  std::vector<ImageShift> shifts;
  std::vector<double> image(d);
  for (std::size_t i = 0; i < count; ++i) {
    const std::span<const double> point = positions.subspan(i * d, d);
    partition.processes_near(point, reach, me, processes);
    for (const int p : processes) {
      needed_by[i].push_back({p, ImageShift{}});
    }
    if (period.any()) {
      image_shifts(point.data(), static_cast<int>(d), period, reach, shifts);
      for (const ImageShift& shift : shifts) {
        for (std::size_t k = 0; k < d; ++k) {
          image[k] = point[k] + shift[k] * period.length(static_cast<int>(k));
        }
        partition.processes_near(image, reach, -1, processes);
        for (const int p : processes) {
          needed_by[i].push_back({p, shift});
        }
        has_images_ = true;
      }
    }
    for (const Destination& destination : needed_by[i]) {
      ++sent_per_process_[static_cast<std::size_t>(destination.process)];
    }
  }
  std::vector<std::size_t> next(sent_per_process_.size(), 0);
  std::size_t total = 0;
  for (std::size_t p = 0; p < next.size(); ++p) {
    next[p] = total;
    total += sent_per_process_[p];
  }
  sent_particles_.resize(total);
  sent_shifts_.resize(has_images_ ? total : 0);
  for (std::size_t i = 0; i < count; ++i) {
    for (const Destination& destination : needed_by[i]) {
      const std::size_t n = next[static_cast<std::size_t>(destination.process)]++;
      sent_particles_[n] = static_cast<std::uint32_t>(i);
      if (has_images_) {
        sent_shifts_[n] = destination.shift;
      }
    }
  }
  // The receivers learn their ghost counts from one exchange of a byte per ghost.
  const std::vector<std::byte> marks(total, std::byte{1});
  ghost_count_ = exchange_bytes(marks, sent_per_process_, ghosts_from_process_).size();
}

} // namespace revsph::distributed
