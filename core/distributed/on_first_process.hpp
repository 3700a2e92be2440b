#pragma once
// Records gathered on process 0 and records sent from it to every process
// (docs/design/distributed.md): for work done once for the whole run, on one process, in the
// run's own order (a linear system solved as in a one-process run, core/pair_system.hpp), so
// that its result does not depend on the decomposition.

#include "core/distributed/processes.hpp"

#include <cstddef>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace revsph::distributed {

// Every process's `mine` on process 0, in rank order; empty on the others (collective).
template <class Record>
std::vector<Record> gathered_on_first(std::span<const Record> mine) {
  static_assert(std::is_trivially_copyable_v<Record>);
  std::vector<std::size_t> send_bytes(static_cast<std::size_t>(process_count()), 0);
  send_bytes[0] = mine.size_bytes();
  std::vector<std::size_t> received_bytes;
  const std::vector<std::byte> received =
      exchange_bytes(std::as_bytes(mine), send_bytes, received_bytes);
  std::vector<Record> records(received.size() / sizeof(Record));
  if (!records.empty()) {
    std::memcpy(records.data(), received.data(), received.size());
  }
  return records;
}

// Process 0's `records` on every process (the others' argument is ignored; collective).
template <class Record>
std::vector<Record> sent_from_first(std::span<const Record> records) {
  static_assert(std::is_trivially_copyable_v<Record>);
  const auto processes = static_cast<std::size_t>(process_count());
  const bool first = process_rank() == 0;
  std::vector<std::byte> send;
  std::vector<std::size_t> send_bytes(processes, first ? records.size_bytes() : 0);
  if (first) {
    const std::span<const std::byte> bytes = std::as_bytes(records);
    send.reserve(bytes.size() * processes);
    for (std::size_t p = 0; p < processes; ++p) {
      send.insert(send.end(), bytes.begin(), bytes.end());
    }
  }
  std::vector<std::size_t> received_bytes;
  const std::vector<std::byte> received = exchange_bytes(send, send_bytes, received_bytes);
  std::vector<Record> result(received.size() / sizeof(Record));
  if (!result.empty()) {
    std::memcpy(result.data(), received.data(), received.size());
  }
  return result;
}

} // namespace revsph::distributed
