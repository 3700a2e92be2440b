#pragma once
// Particles moving to the process that owns their new position (docs/design/distributed.md,
// piece 6): after each drift (the few that crossed a region's border) and after a rebalance
// (many). The plan is made once from every particle's new owner and its global index (its place in
// the run's canonical order); each field's rows then move along it, and every process ends with
// its particles in global-index order, whatever order they arrived in: the order a
// one-process run keeps, so snapshots and hashes can be written by global index.

#include "core/distributed/processes.hpp"
#include "core/distributed/row_exchange.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace revsph::distributed {

class Migration {
public:
  // owners[i], global_indices[i]: particle i of this process (collective).
  Migration(std::span<const int> owners, std::span<const std::uint64_t> global_indices);

  // Rows of `width` values per particle (values[i * width + j]); returns this process's rows
  // after the move, in global-index order (collective).
  template <class T>
  std::vector<T> move(std::span<const T> values, std::size_t width) const {
    const std::vector<T> arrived =
        exchange_rows(values, width, std::span<const std::uint32_t>(sent_order_),
                      std::span<const std::size_t>(sent_per_process_));
    std::vector<T> moved(arrived.size());
    for (std::size_t n = 0; n < arrival_order_.size(); ++n) {
      std::copy_n(arrived.begin() + static_cast<std::ptrdiff_t>(arrival_order_[n] * width), width,
                  moved.begin() + static_cast<std::ptrdiff_t>(n * width));
    }
    return moved;
  }

  // This process's particles after the move, and their global indices (ascending).
  std::size_t count_after() const { return arrival_order_.size(); }
  const std::vector<std::uint64_t>& global_indices_after() const { return indices_after_; }
  // Particles that change process (summed over every process: the same on each).
  std::int64_t moved_count() const { return moved_count_; }

private:
  std::vector<std::uint32_t> sent_order_;     // this process's particles grouped by new owner
  std::vector<std::size_t> sent_per_process_; // one count per process (this one included)
  std::vector<std::size_t> arrival_order_;    // received row of each particle in index order
  std::vector<std::uint64_t> indices_after_;
  std::int64_t moved_count_ = 0;
};

} // namespace revsph::distributed
