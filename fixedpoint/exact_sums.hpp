#pragma once
// One exact sum per particle, at one scale, for pair loops that add each pair term to both
// particles of the pair. Each term is rounded once to the scale, as in ExactSum, so the totals do
// not depend on the order of the terms. The totals are 64-bit (half the memory of ExactSum's 128
// bits, which matters at a million particles) with overflow detection: a sum whose running total
// leaves int64 is invalid, even if later terms would bring it back. The callers add the terms in
// an order fixed by the geometry (core/pair_list.hpp), so that verdict is reproducible too.

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
    totals_.resize(n);
    valid_.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      totals_[i] = 0;
      valid_[i] = 1;
    }
  }

  void add(std::size_t i, double term) {
    std::int64_t raw = 0;
    if (!try_to_fixed(term, scale_, raw)) {
      valid_[i] = 0;
      return;
    }
    add_raw(i, raw);
  }
  void add_raw(std::size_t i, std::int64_t raw) {
    if (__builtin_add_overflow(totals_[i], raw, &totals_[i])) {
      valid_[i] = 0;
    }
  }
  // Adds a single accumulator's total (same scale) to sum i.
  void add_sum(std::size_t i, const ExactSum& sum) {
    std::int64_t raw = 0;
    if (!sum.try_raw(raw)) {
      valid_[i] = 0;
      return;
    }
    add_raw(i, raw);
  }

  bool try_value(std::size_t i, double& value) const {
    if (!valid_[i]) {
      return false;
    }
    value = to_real(totals_[i], scale_);
    return true;
  }

  const Scale& scale() const {
    return scale_;
  }

private:
  Scale scale_;
  std::vector<std::int64_t> totals_;
  std::vector<std::uint8_t> valid_;
};

} // namespace revsph::fixedpoint
