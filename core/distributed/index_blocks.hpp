#pragma once
// A state held in pieces rearranged by global index (docs/design/distributed.md): process p holds
// the particles [start(p), start(p + 1)) of every set, in index order. Two snapshots of one run
// captured in different decompositions (before and after particles migrated) line up row for row
// once both are in index blocks, so each process compares its block and the processes combine
// their findings in rank order, which is index order: what `revsph verify` needs.

#include "core/state_snapshot.hpp"

#include <cstdint>

namespace revsph::distributed {

// The first global index of `process`'s block of a set of `total` particles (blocks of nearly
// equal size; start(process_count()) = total).
std::uint64_t index_block_start(std::uint64_t total, int process);

// `snapshot` with every process holding its block of every set; pieces say which (collective).
// A snapshot without pieces (each process holds the whole state) is cut without communication.
StateSnapshot in_index_blocks(const StateSnapshot& snapshot);

} // namespace revsph::distributed
