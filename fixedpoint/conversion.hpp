#pragma once
// Exact, odd-symmetric conversions between doubles and 64-bit fixed-point integers.
//
// Rounding is to nearest with ties to even (the FPU default, one `cvtsd2si` instruction). It is
// odd-symmetric, to_fixed(-y) == -to_fixed(y), because IEEE negation is exact and ties-to-even
// treats +q and -q alike; floor or an arithmetic right shift would not be (design note §1, §2).
// Every conversion checks its range; NaN and infinity fail the same check.

#include "fixedpoint/scale.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace revsph::fixedpoint {

// Thrown by the throwing conversions; hot loops use the try_ forms and report through their caller.
class OverflowError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

inline constexpr double two_to_the_63 = 9223372036854775808.0;

// raw = round(value / unit); false if the result would not fit in int64 or value is not finite.
// Requires the FPU rounding mode to be round-to-nearest (checked by require_round_to_nearest()).
inline bool try_to_fixed(double value, const Scale& scale, std::int64_t& raw) {
  const double quotient = value * scale.inverse_unit(); // exact: multiplication by 2^-exponent
  if (!(std::fabs(quotient) < two_to_the_63)) {
    return false;
  }
  raw = std::llrint(quotient);
  return true;
}

// raw = ceil(value / unit), for an increment that rounding must never make smaller (the entropy
// a dissipative step adds: rounded up, the total entropy never falls by rounding); false if it
// would reach 2^62 in magnitude (room left for the sums it joins) or value is not finite.
inline bool try_round_up_to_fixed(double value, const Scale& scale, std::int64_t& raw) {
  const double units = std::ceil(value * scale.inverse_unit());
  if (!(std::fabs(units) < 0x1p62)) {
    return false;
  }
  raw = static_cast<std::int64_t>(units);
  return true;
}

inline double to_real(std::int64_t raw, const Scale& scale) {
  return static_cast<double>(raw) * scale.unit();
}

// a + b, false on signed overflow (never wraps).
inline bool try_add(std::int64_t a, std::int64_t b, std::int64_t& sum) {
  return !__builtin_add_overflow(a, b, &sum);
}

// -a, false for the one value whose negation does not fit (INT64_MIN).
inline bool try_negate(std::int64_t a, std::int64_t& negated) {
  return !__builtin_sub_overflow(std::int64_t{0}, a, &negated);
}

// Throwing forms for code outside hot loops; `quantity` names what was converted in the message.
std::int64_t to_fixed(double value, const Scale& scale, const std::string& quantity);
std::int64_t add_checked(std::int64_t a, std::int64_t b, const std::string& quantity);

// Throws if the FPU is not in round-to-nearest mode (llrint would then not be odd-symmetric).
void require_round_to_nearest();

} // namespace revsph::fixedpoint
