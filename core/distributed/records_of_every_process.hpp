#pragma once
// Every process's records on every process, in rank order (docs/design/distributed.md): for
// findings that each process makes about its own rows (a comparison of its block of two states,
// say) and that every process then combines in the same order, so all of them reach the same
// result, whatever the decomposition.

#include "core/distributed/processes.hpp"

#include <cstddef>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace revsph::distributed {

// `mine` (the same number of records on every process) from each process, process 0's first
// (collective).
template <class Record>
std::vector<Record> records_of_every_process(std::span<const Record> mine) {
  static_assert(std::is_trivially_copyable_v<Record>);
  const auto processes = static_cast<std::size_t>(process_count());
  const std::span<const std::byte> bytes = std::as_bytes(mine);
  std::vector<std::byte> send;
  send.reserve(bytes.size() * processes);
  for (std::size_t p = 0; p < processes; ++p) {
    send.insert(send.end(), bytes.begin(), bytes.end());
  }
  const std::vector<std::size_t> send_bytes(processes, bytes.size());
  std::vector<std::size_t> received_bytes;
  const std::vector<std::byte> received = exchange_bytes(send, send_bytes, received_bytes);
  if (received.size() != bytes.size() * processes) {
    throw std::logic_error("records_of_every_process: the processes sent different numbers of "
                           "records");
  }
  std::vector<Record> records(mine.size() * processes);
  std::memcpy(records.data(), received.data(), received.size());
  return records;
}

// Every process's `mine` combined record by record in rank order: combined[i] starts as
// process 0's record i and then(combined[i], record) takes each later process's in turn
// (collective; every process gets the same result).
template <class Record, class Then>
std::vector<Record> combined_in_rank_order(std::span<const Record> mine, const Then& then) {
  const std::vector<Record> all = records_of_every_process(mine);
  std::vector<Record> combined(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(mine.size()));
  for (std::size_t n = mine.size(); n < all.size(); ++n) {
    then(combined[n % mine.size()], all[n]);
  }
  return combined;
}

} // namespace revsph::distributed
