#pragma once
// The two arithmetics a model runs in, as policies: the same equations are written once and
// instantiated for each.
//
// FixedArithmetic (FixPA): state in 64-bit fixed point, neighbour sums exact in integers; this is
// what makes the step bitwise reversible. FloatArithmetic (FloPA, paper 1 §4): state in double,
// sums in double in neighbour-list order; same equations, not reversible, kept for comparison.

#include "fixedpoint/conversion.hpp"
#include "fixedpoint/exact_sum.hpp"
#include "fixedpoint/exact_sums.hpp"

#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

namespace revsph {

enum class Arithmetic { fixed, floating };

std::string_view to_string(Arithmetic arithmetic);

struct FixedArithmetic {
  using Raw = std::int64_t;
  using Sum = fixedpoint::ExactSum;
  using Sums = fixedpoint::ExactSums; // one Sum per particle
  static constexpr Arithmetic kind = Arithmetic::fixed;

  static double real(Raw raw, const fixedpoint::Scale& scale) {
    return fixedpoint::to_real(raw, scale);
  }
  static bool try_from_real(double value, const fixedpoint::Scale& scale, Raw& raw) {
    return fixedpoint::try_to_fixed(value, scale, raw);
  }
  // raw += round(increment / unit): exactly undone by an increment of -increment.
  static bool try_increment(Raw& raw, double increment, const fixedpoint::Scale& scale) {
    std::int64_t delta = 0;
    std::int64_t sum = 0;
    if (!fixedpoint::try_to_fixed(increment, scale, delta) ||
        !fixedpoint::try_add(raw, delta, sum)) {
      return false;
    }
    raw = sum;
    return true;
  }
  static bool try_negate(Raw& raw) { return fixedpoint::try_negate(raw, raw); }
};

struct FloatArithmetic {
  using Raw = double;
  static constexpr Arithmetic kind = Arithmetic::floating;

  // Plain double accumulation in the order the terms come (neighbour-list order).
  class Sum {
  public:
    explicit Sum(const fixedpoint::Scale&) {}
    void add(double term) { total_ += term; }
    void add_raw(double raw) { total_ += raw; }
    bool try_value(double& value) const {
      value = total_;
      return std::isfinite(total_);
    }

    double total() const { return total_; }

  private:
    double total_ = 0.0;
  };

  // One Sum per particle; terms are added in the order they come (pair_list.hpp fixes it).
  class Sums {
  public:
    explicit Sums(const fixedpoint::Scale& scale) : scale_(scale) {}
    const fixedpoint::Scale& scale() const { return scale_; }
    void reset(std::size_t n) {
      totals_.resize(n);
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        totals_[i] = 0.0;
      }
    }
    void add(std::size_t i, double term) {
      totals_[i] += term;
    }
    void add_raw(std::size_t i, double raw) {
      totals_[i] += raw;
    }
    void add_sum(std::size_t i, const Sum& sum) {
      totals_[i] += sum.total();
    }
    bool try_value(std::size_t i, double& value) const {
      value = totals_[i];
      return std::isfinite(value);
    }

  private:
    fixedpoint::Scale scale_; // unused by the arithmetic; kept for the same interface
    std::vector<double> totals_;
  };

  static double real(Raw raw, const fixedpoint::Scale&) {
    return raw;
  }
  static bool try_from_real(double value, const fixedpoint::Scale&, Raw& raw) {
    raw = value;
    return std::isfinite(value);
  }
  static bool try_increment(Raw& raw, double increment, const fixedpoint::Scale&) {
    raw += increment;
    return std::isfinite(raw);
  }
  static bool try_negate(Raw& raw) {
    raw = -raw;
    return true;
  }
};

} // namespace revsph
