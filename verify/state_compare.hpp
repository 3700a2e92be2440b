#pragma once
// Bit-for-bit comparison of two states of the same layout, with a report a person can act on:
// the first differing particle and variable, and per variable how many values differ and by
// how many units in the last place. The last place is the variable's fixed-point unit
// (2^exponent of its scale) in both arithmetics: the raw difference in fixed point, and
// |difference| / unit rounded up for double state (FloPA), so the two are on one yardstick.
// (Counting representable doubles instead would call 0 -> 1e-11 four quintillion ULPs.)

#include "core/state_snapshot.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace revsph {

struct ValueLocation {
  std::string particle_set;
  std::string variable;
  std::size_t particle = 0;
  int component = 0;
  std::int64_t expected = 0; // raw bits
  std::int64_t actual = 0;
  double expected_value = 0.0; // physical values
  double actual_value = 0.0;
  std::string unit;
};

struct VariableDifference {
  std::string particle_set;
  std::string variable;
  std::size_t differing_values = 0;
  std::size_t total_values = 0;
  std::uint64_t max_units_in_last_place = 0;
  double max_abs_difference = 0.0; // in the variable's unit
  std::string unit;
  ValueLocation worst;
};

struct StateComparison {
  bool identical = true;
  std::size_t compared_values = 0;
  std::optional<ValueLocation> first_difference;
  std::vector<VariableDifference> differences; // only variables that differ
  std::string layout_error;                    // non-empty if the states cannot be compared

  // One line: "bitwise identical (…)" or what differs.
  std::string verdict() const;
  // The per-variable table, one line each.
  std::vector<std::string> details() const;
};

StateComparison compare_states(const StateSnapshot& expected, const StateSnapshot& actual);

// Distance between two raw values of a field in units of its last place (see above).
std::uint64_t units_in_last_place(const FieldSnapshot& field, std::int64_t a, std::int64_t b);

} // namespace revsph
