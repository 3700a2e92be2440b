#pragma once
// Rows of per-particle values sent to other processes (docs/design/distributed.md): the one
// packing behind the ghost exchange (ghost_plan.hpp) and the migration (migration.hpp). A row
// is `width` values of one particle (values[i * width + j]).

#include "core/distributed/processes.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace revsph::distributed {

// Sends `rows` (already packed, `width` values each), the first rows_per_process[0] of them to
// process 0, the next to process 1, ...; returns the rows this process receives, in the senders'
// rank order and each sender's order (collective). `rows_from_process`, when given (one entry
// per process), is how many rows each sends to this one, which spares exchanging the counts.
template <class T>
std::vector<T> exchange_packed_rows(std::span<const T> rows, std::size_t width,
                                    std::span<const std::size_t> rows_per_process,
                                    std::span<const std::size_t> rows_from_process = {}) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::size_t row = width * sizeof(T);
  const auto bytes_of = [row](std::span<const std::size_t> counts) {
    std::vector<std::size_t> bytes(counts.size());
    for (std::size_t p = 0; p < bytes.size(); ++p) {
      bytes[p] = counts[p] * row;
    }
    return bytes;
  };
  const std::vector<std::size_t> bytes = bytes_of(rows_per_process);
  std::vector<std::size_t> received_bytes;
  const std::vector<std::byte> received =
      rows_from_process.empty()
          ? exchange_bytes(std::as_bytes(rows), bytes, received_bytes)
          : exchange_bytes(std::as_bytes(rows), bytes,
                           std::span<const std::size_t>(bytes_of(rows_from_process)));
  std::vector<T> arrived(received.size() / sizeof(T));
  std::memcpy(arrived.data(), received.data(), received.size());
  return arrived;
}

// The same for rows order[0], order[1], ... of `values`.
template <class T>
std::vector<T> exchange_rows(std::span<const T> values, std::size_t width,
                             std::span<const std::uint32_t> order,
                             std::span<const std::size_t> rows_per_process,
                             std::span<const std::size_t> rows_from_process = {}) {
  std::vector<T> packed(order.size() * width);
  for (std::size_t n = 0; n < order.size(); ++n) {
    std::copy_n(values.data() + std::size_t{order[n]} * width, width, packed.data() + n * width);
  }
  return exchange_packed_rows(std::span<const T>(packed), width, rows_per_process,
                              rows_from_process);
}

} // namespace revsph::distributed
