#pragma once
// Particles moving to the process that owns their new position (docs/design/distributed.md,
// piece 6): after each drift (the few that crossed a region's border) and after a rebalance
// (many). The plan is made once from every particle's new owner and its global index (its place in
// the run's canonical order); each field's rows then move along it, and every process ends with
// its particles in global-index order, whatever order they arrived in: the order a
// one-process run keeps, so snapshots and hashes can be written by global index.

#include "core/distributed/processes.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
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
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t row = width * sizeof(T);
    std::vector<std::byte> send(sent_order_.size() * row);
    for (std::size_t n = 0; n < sent_order_.size(); ++n) {
      std::memcpy(send.data() + n * row, values.data() + sent_order_[n] * width, row);
    }
    std::vector<std::size_t> bytes(sent_per_process_.size());
    for (std::size_t p = 0; p < bytes.size(); ++p) {
      bytes[p] = sent_per_process_[p] * row;
    }
    std::vector<std::size_t> received_bytes;
    const std::vector<std::byte> received = exchange_bytes(send, bytes, received_bytes);
    std::vector<T> moved(received.size() / sizeof(T));
    for (std::size_t n = 0; n < arrival_order_.size(); ++n) {
      std::memcpy(moved.data() + n * width, received.data() + arrival_order_[n] * row, row);
    }
    return moved;
  }

  // This process's particles after the move, and their global indices (ascending).
  std::size_t count_after() const { return arrival_order_.size(); }
  const std::vector<std::uint64_t>& global_indices_after() const { return indices_after_; }
  // Particles that change process (summed over every process: the same on each).
  std::int64_t moved_count() const { return moved_count_; }

private:
  std::vector<std::size_t> sent_order_;       // this process's particles grouped by new owner
  std::vector<std::size_t> sent_per_process_; // one count per process (this one included)
  std::vector<std::size_t> arrival_order_;    // received row of each particle in index order
  std::vector<std::uint64_t> indices_after_;
  std::int64_t moved_count_ = 0;
};

} // namespace revsph::distributed
