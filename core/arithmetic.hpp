#pragma once
// The two arithmetics a model runs in, as policies: the same equations are written once and
// instantiated for each.
//
// FixedArithmetic (FixPA): state in 64-bit fixed point, neighbour sums exact in integers; this is
// what makes the step bitwise reversible. FloatArithmetic (FloPA, paper 1 §4): state in double,
// sums in double in neighbour-list order; same equations, not reversible, kept for comparison.

#include "fixedpoint/conversion.hpp"

#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

namespace revsph {

enum class Arithmetic { fixed, floating };

std::string_view to_string(Arithmetic arithmetic);

struct FixedArithmetic {
  using Raw = std::int64_t;
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

  static double real(Raw raw, const fixedpoint::Scale&) { return raw; }
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
