#pragma once
// One exact sum per particle, at one scale, for pair loops that add each pair term to both
// particles of the pair. Same arithmetic as ExactSum (each term rounded once to the scale, 128-bit
// integer totals), so the totals do not depend on the order of the terms.

#include "fixedpoint/exact_sum.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace revsph::fixedpoint {

class ExactSums {
public:
  explicit ExactSums(const Scale& scale) : scale_(scale) {}

  // n sums, all zero and valid.
  void reset(std::size_t n) {
    totals_.assign(n, 0);
    valid_.assign(n, 1);
  }
  std::size_t size() const { return totals_.size(); }

  void add(std::size_t i, double term) {
    std::int64_t raw = 0;
    if (try_to_fixed(term, scale_, raw)) {
      totals_[i] += raw;
    } else {
      valid_[i] = 0;
    }
  }
  void add_raw(std::size_t i, std::int64_t raw) { totals_[i] += raw; }
  // Adds a single accumulator's total (same scale) to sum i.
  void add_sum(std::size_t i, const ExactSum& sum) {
    totals_[i] += sum.total();
    valid_[i] &= static_cast<std::uint8_t>(sum.valid());
  }

  bool try_value(std::size_t i, double& value) const {
    const int128 total = totals_[i];
    if (!valid_[i] || total > INT64_MAX || total < INT64_MIN) {
      return false;
    }
    value = to_real(static_cast<std::int64_t>(total), scale_);
    return true;
  }

  const Scale& scale() const { return scale_; }

private:
  Scale scale_;
  std::vector<int128> totals_;
  std::vector<std::uint8_t> valid_;
};

} // namespace revsph::fixedpoint
