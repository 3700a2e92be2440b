#pragma once
// Rows of per-particle values sent to other processes (docs/design/distributed.md): the one
// packing behind the ghost exchange (ghost_plan.hpp) and the migration (migration.hpp). A row
// is `width` values of one particle (values[i * width + j]).

#include "core/distributed/processes.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace revsph::distributed {

// Sends rows order[0], order[1], ... of `values`, the first rows_per_process[0] of them to
// process 0, the next to process 1, ...; returns the rows this process receives, in the senders'
// rank order and each sender's order (collective).
template <class T>
std::vector<T> exchange_rows(std::span<const T> values, std::size_t width,
                             std::span<const std::uint32_t> order,
                             std::span<const std::size_t> rows_per_process) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::size_t row = width * sizeof(T);
  std::vector<std::byte> send(order.size() * row);
  for (std::size_t n = 0; n < order.size(); ++n) {
    std::memcpy(send.data() + n * row, values.data() + std::size_t{order[n]} * width, row);
  }
  std::vector<std::size_t> bytes(rows_per_process.size());
  for (std::size_t p = 0; p < bytes.size(); ++p) {
    bytes[p] = rows_per_process[p] * row;
  }
  std::vector<std::size_t> received_bytes;
  const std::vector<std::byte> received = exchange_bytes(send, bytes, received_bytes);
  std::vector<T> rows(received.size() / sizeof(T));
  std::memcpy(rows.data(), received.data(), received.size());
  return rows;
}

} // namespace revsph::distributed
