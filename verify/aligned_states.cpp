#include "verify/aligned_states.hpp"

#include "core/distributed/index_blocks.hpp"
#include "core/distributed/processes.hpp"

#include <stdexcept>
#include <string>

namespace revsph {

namespace {

// The field's layout with its particles counted over every process.
FieldSnapshot whole_layout(const StateSnapshot& state, const FieldSnapshot& field) {
  return FieldSnapshot{field.info, field.kind, whole_count(state, field), {}, {}};
}

} // namespace

AlignedStates::AlignedStates(const StateSnapshot& expected, const StateSnapshot& actual)
    : expected_(expected), actual_(actual) {
  if (expected.fields.size() != actual.fields.size()) {
    throw std::invalid_argument("the states have different numbers of variables (" +
                                std::to_string(expected.fields.size()) + " and " +
                                std::to_string(actual.fields.size()) + ")");
  }
  for (std::size_t f = 0; f < expected.fields.size(); ++f) {
    require_same_layout(whole_layout(expected, expected.fields[f]),
                        whole_layout(actual, actual.fields[f]));
  }
  if (!expected.pieces.empty() || !actual.pieces.empty()) {
    expected_blocks_ = distributed::in_index_blocks(expected);
    actual_blocks_ = distributed::in_index_blocks(actual);
  }
}

std::uint64_t AlignedStates::first_index(const FieldSnapshot& field) const {
  if (!in_pieces()) {
    return 0;
  }
  const SetRows* rows = expected_blocks_->rows_of(field.info.particle_set);
  return rows == nullptr ? 0
                         : distributed::index_block_start(rows->total, distributed::process_rank());
}

} // namespace revsph
