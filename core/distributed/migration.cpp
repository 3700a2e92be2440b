#include "core/distributed/migration.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace revsph::distributed {

Migration::Migration(std::span<const int> owners, std::span<const std::uint64_t> global_indices)
    : sent_per_process_(static_cast<std::size_t>(process_count()), 0) {
  if (owners.size() != global_indices.size()) {
    throw std::invalid_argument("Migration: owners and global indices differ in length");
  }
  std::int64_t leaving = 0;
  for (const int owner : owners) {
    if (owner < 0 || owner >= process_count()) {
      throw std::invalid_argument("Migration: an owner outside the processes");
    }
    ++sent_per_process_[static_cast<std::size_t>(owner)];
    leaving += owner != process_rank() ? 1 : 0;
  }
  moved_count_ = sum_over_processes(leaving);
  // A counting sort by owner keeps this process's order within each destination.
  std::vector<std::size_t> next(sent_per_process_.size(), 0);
  std::exclusive_scan(sent_per_process_.begin(), sent_per_process_.end(), next.begin(),
                      std::size_t{0});
  sent_order_.resize(owners.size());
  for (std::size_t i = 0; i < owners.size(); ++i) {
    sent_order_[next[static_cast<std::size_t>(owners[i])]++] = static_cast<std::uint32_t>(i);
  }
  // The indices travel first; the arrival order sorts what came by index.
  const std::vector<std::uint64_t> arrived =
      exchange_rows(global_indices, 1, std::span<const std::uint32_t>(sent_order_),
                    std::span<const std::size_t>(sent_per_process_));
  arrival_order_.resize(arrived.size());
  std::iota(arrival_order_.begin(), arrival_order_.end(), std::size_t{0});
  std::sort(arrival_order_.begin(), arrival_order_.end(),
            [&arrived](std::size_t a, std::size_t b) { return arrived[a] < arrived[b]; });
  indices_after_.resize(arrived.size());
  for (std::size_t n = 0; n < arrival_order_.size(); ++n) {
    indices_after_[n] = arrived[arrival_order_[n]];
  }
}

} // namespace revsph::distributed
