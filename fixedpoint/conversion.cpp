#include "fixedpoint/conversion.hpp"
#include "fixedpoint/fixed_vector.hpp"

#include <cfenv>
#include <cmath>
#include <sstream>

namespace revsph::fixedpoint {

Scale Scale::covering(double max_magnitude, int fraction_bits) {
  if (!(max_magnitude > 0.0) || !std::isfinite(max_magnitude)) {
    throw std::invalid_argument("Scale::covering: the magnitude must be positive and finite");
  }
  // 2^e >= max_magnitude, then fraction_bits more bits of resolution below it.
  const int magnitude_exponent = std::ilogb(max_magnitude) + 1;
  return Scale(magnitude_exponent - fraction_bits);
}

std::string describe(const Scale& scale) {
  std::ostringstream out;
  out << "2^" << scale.exponent() << " (" << scale.unit() << ")";
  return out.str();
}

std::int64_t to_fixed(double value, const Scale& scale, const std::string& quantity) {
  std::int64_t raw = 0;
  if (!try_to_fixed(value, scale, raw)) {
    std::ostringstream message;
    message << quantity << ": value " << value << " does not fit in 64-bit fixed point at scale "
            << describe(scale) << " (range +-" << scale.max_magnitude() << ")";
    throw OverflowError(message.str());
  }
  return raw;
}

std::int64_t add_checked(std::int64_t a, std::int64_t b, const std::string& quantity) {
  std::int64_t sum = 0;
  if (!try_add(a, b, sum)) {
    throw OverflowError(quantity + ": fixed-point addition overflows int64");
  }
  return sum;
}

void require_round_to_nearest() {
  if (std::fegetround() != FE_TONEAREST) {
    throw std::runtime_error("the floating-point rounding mode is not round-to-nearest; "
                             "fixed-point conversions would not be odd-symmetric");
  }
}

FixedScalar operator+(const FixedScalar& x, const FixedScalar& d) {
  if (!(x.scale == d.scale)) {
    throw std::invalid_argument("fixed-point addition of values at different scales");
  }
  return {add_checked(x.raw, d.raw, "fixed-point sum"), x.scale};
}

FixedScalar operator-(const FixedScalar& x) {
  std::int64_t negated = 0;
  if (!try_negate(x.raw, negated)) {
    throw OverflowError("fixed-point negation of INT64_MIN");
  }
  return {negated, x.scale};
}

FixedScalar operator-(const FixedScalar& x, const FixedScalar& d) {
  return x + (-d);
}

} // namespace revsph::fixedpoint
