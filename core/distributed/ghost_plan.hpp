#pragma once
// Which of this process's particles the other processes need as ghosts, and the exchange that
// brings them there (docs/design/distributed.md, pieces 4 and 5). A particle is needed by every
// other process whose region comes within the reach (the kernel's support) of it
// (SpatialPartition::processes_near); the plan lists them once, and each exchange then sends any
// per-particle values along the same lists: the inputs of a pair pass before it, its summed
// results (a density, say) after it, for the ghosts' slots.
//
// Ghosts arrive in a fixed order: by the sending process's rank, then in the sender's particle
// order. Results do not depend on it (pair sums are exact), only the layout does.

#include "core/distributed/processes.hpp"
#include "core/distributed/row_exchange.hpp"
#include "core/distributed/spatial_partition.hpp"
#include "core/periodic_box.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace revsph::distributed {

class GhostPlan {
public:
  GhostPlan() = default;
  // `positions`: this process's particles, point after point (partition.dimension() values
  // each, metres).
  // `period`: a periodic domain's faces (core/periodic_box.hpp); the particles within the reach
  // of one are also sent as images, their positions shifted by the period (sent_shifts).
  GhostPlan(const SpatialPartition& partition, std::span<const double> positions, double reach,
            const PeriodicBox& period = {});

  // Sends `width` values of each listed particle (values[i * width + j]: particle i's j-th) to
  // every process that needs it; returns the ghosts' values in the same layout (collective).
  template <class T>
  std::vector<T> exchange(std::span<const T> values, std::size_t width) const {
    return exchange_rows(values, width, std::span<const std::uint32_t>(sent_particles_),
                         std::span<const std::size_t>(sent_per_process_),
                         std::span<const std::size_t>(ghosts_from_process_));
  }

  // The same with each listed particle's row written by row_of(particle, T* row) straight into
  // the send buffer (values kept in another order, a pair loop's slots say).
  template <class T, class RowOf>
  std::vector<T> exchange_from(std::size_t width, const RowOf& row_of) const {
    std::vector<T> packed(sent_particles_.size() * width);
    for (std::size_t n = 0; n < sent_particles_.size(); ++n) {
      row_of(std::size_t{sent_particles_[n]}, packed.data() + n * width);
    }
    return exchange_packed_rows(std::span<const T>(packed), width,
                                std::span<const std::size_t>(sent_per_process_),
                                std::span<const std::size_t>(ghosts_from_process_));
  }

  // The same with the rows already packed in the order of sent_particles().
  template <class T>
  std::vector<T> exchange_packed(std::span<const T> packed, std::size_t width) const {
    return exchange_packed_rows(packed, width, std::span<const std::size_t>(sent_per_process_),
                                std::span<const std::size_t>(ghosts_from_process_));
  }

  // How many ghosts this process receives, and how many particle copies it sends.
  std::size_t ghost_count() const { return ghost_count_; }
  std::size_t sent_count() const { return sent_particles_.size(); }
  // The listed particles, grouped by destination (for a caller that packs rows itself).
  std::span<const std::uint32_t> sent_particles() const { return sent_particles_; }
  // The image each listed particle is sent as (its position is shifted by these periods before
  // it goes); empty where none is an image.
  std::span<const ImageShift> sent_shifts() const { return sent_shifts_; }

  // The particles' global indices in their set, own ones then the ghosts (as StateField numbers
  // them: ghost g at own count + g), for what orders rows by the whole run's numbering (a solve
  // gathered on one process, core/pair_system.hpp). Set by the distribution that made the plan.
  void set_global_indices(std::vector<std::uint64_t> own, std::vector<std::uint64_t> ghosts) {
    own_global_ = std::move(own);
    ghost_global_ = std::move(ghosts);
  }
  std::uint64_t global_index(std::size_t particle) const {
    return particle < own_global_.size() ? own_global_[particle]
                                         : ghost_global_.at(particle - own_global_.size());
  }

private:
  std::vector<std::uint64_t> own_global_, ghost_global_;
  std::vector<std::uint32_t> sent_particles_; // grouped by destination, in particle order
  std::vector<ImageShift> sent_shifts_;       // per sent particle; empty without images
  bool has_images_ = false;
  std::vector<std::size_t> sent_per_process_;    // one count per process
  std::vector<std::size_t> ghosts_from_process_; // one count per process
  std::size_t ghost_count_ = 0;
};

} // namespace revsph::distributed
