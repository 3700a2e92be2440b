#pragma once
// One per-particle array that the processes hold in pieces, read in the run's canonical
// (global-index) order by one process, a chunk at a time (docs/design/distributed.md, piece 8):
// what a state hash or a snapshot needs to see the same bytes as a one-process run, without any
// process ever holding the whole array.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace revsph::distributed {

// `indices`: this process's particles' global indices, ascending; `values`: one value each.
// `total`: the number of particles over every process. Calls `consumer` on process 0 with the
// values of indices [0, chunk), [chunk, 2 chunk), ... in order, covering [0, total) (collective;
// the other processes' consumer is never called). Throws std::invalid_argument if the indices do
// not cover [0, total) exactly once.
void stream_in_index_order(std::span<const std::uint64_t> indices,
                           std::span<const std::int64_t> values, std::uint64_t total,
                           std::size_t chunk,
                           const std::function<void(std::span<const std::int64_t>)>& consumer);

// Process 0's text on every process (a hash computed there, say).
std::string broadcast_from_first(const std::string& text);

} // namespace revsph::distributed
