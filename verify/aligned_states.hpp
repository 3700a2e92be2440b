#pragma once
// Two states of one run lined up row for row, for a comparison (state_compare.hpp,
// state_distance.hpp): as they are when both hold the whole state; in index blocks
// (core/distributed/index_blocks.hpp) when either is held in pieces by the processes of a
// distributed run, so that each process compares the same particles of both and the processes'
// findings, combined in rank order, are those of the whole state in index order.

#include "core/state_snapshot.hpp"

#include <cstdint>
#include <optional>

namespace revsph {

class AlignedStates {
public:
  // Collective when either state has pieces. Throws std::invalid_argument
  // (require_same_layout's message) if the layouts differ, counted over every process: checked
  // before any exchange, so every process throws alike.
  AlignedStates(const StateSnapshot& expected, const StateSnapshot& actual);

  const StateSnapshot& expected() const { return expected_blocks_ ? *expected_blocks_ : expected_; }
  const StateSnapshot& actual() const { return actual_blocks_ ? *actual_blocks_ : actual_; }
  // Whether the rows are in pieces: the findings must then be combined over the processes.
  bool in_pieces() const { return expected_blocks_.has_value(); }
  // The global index of row 0 of `field` (one of expected()'s) on this process.
  std::uint64_t first_index(const FieldSnapshot& field) const;

private:
  const StateSnapshot& expected_;
  const StateSnapshot& actual_;
  std::optional<StateSnapshot> expected_blocks_;
  std::optional<StateSnapshot> actual_blocks_;
};

} // namespace revsph
