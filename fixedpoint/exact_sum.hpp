#pragma once
// Exact, order-independent accumulation of many fixed-point terms (design note §3).
//
// Each term is rounded to the accumulator's scale once; the integer total is then the same for
// any order of the terms, any thread count and any neighbour-search layout. The total is kept in
// 128 bits, so it cannot overflow for fewer than 2^64 terms; only the final value must fit in
// int64, which result() checks.

#include "fixedpoint/conversion.hpp"

#include <cstdint>

namespace revsph::fixedpoint {

__extension__ using int128 = __int128;

class ExactSum {
public:
  explicit ExactSum(const Scale& scale) : scale_(scale) {}

  // Adds round(term / unit). A term out of range or not finite poisons the sum.
  void add(double term) {
    std::int64_t raw = 0;
    if (try_to_fixed(term, scale_, raw)) {
      total_ += raw;
    } else {
      valid_ = false;
    }
  }
  // Adds a value that is already a raw integer at this scale.
  void add_raw(std::int64_t raw) { total_ += raw; }

  // The total as a raw int64; false if a term or the total was out of range.
  bool try_raw(std::int64_t& raw) const {
    if (!valid_ || total_ > INT64_MAX || total_ < INT64_MIN) {
      return false;
    }
    raw = static_cast<std::int64_t>(total_);
    return true;
  }
  // The total as a double (rounded deterministically if |total| >= 2^53).
  bool try_value(double& value) const {
    std::int64_t raw = 0;
    if (!try_raw(raw)) {
      return false;
    }
    value = to_real(raw, scale_);
    return true;
  }

  const Scale& scale() const { return scale_; }

private:
  Scale scale_;
  int128 total_ = 0;
  bool valid_ = true;
};

} // namespace revsph::fixedpoint
