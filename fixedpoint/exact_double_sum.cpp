#include "fixedpoint/exact_double_sum.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace revsph::fixedpoint {

namespace {

// The smallest subnormal is 2^-1074: every finite double is term = units 2^-1074.
constexpr int unit_exponent = -1074;

} // namespace

void ExactDoubleSum::add(double term) {
  if (!std::isfinite(term)) {
    finite_ = false;
    return;
  }
  if (term == 0.0) {
    return;
  }
  int exponent = 0;
  const double fraction =
      std::frexp(term, &exponent); // term = fraction 2^exponent, |f| in [0.5, 1)
  // mantissa 2^(exponent - 53) with a 53-bit integer mantissa (exact).
  const auto mantissa = static_cast<std::int64_t>(std::ldexp(fraction, 53));
  const int shift = exponent - 53 - unit_exponent;
  Wide units = mantissa;
  if (shift >= 0) {
    units <<= shift;
  } else {
    units >>= -shift; // a subnormal: its mantissa's low bits are zeros, so this is exact
  }
  total_ += units;
}

void ExactDoubleSum::add(const ExactDoubleSum& other) {
  total_ += other.total_;
  finite_ = finite_ && other.finite_;
}

double ExactDoubleSum::value() const {
  if (!finite_) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (total_ == 0) {
    return 0.0;
  }
  // Round |total| to 53 significant bits, to nearest with ties to even: the bit below the kept
  // ones decides, and any bit under it (sticky) breaks a tie upward. (Boost's conversion to a
  // 53-bit cpp_bin_float drops the sticky bits: 1 + 2^-53 + 2^-200 came out as 1.)
  const double sign = total_ < 0 ? -1.0 : 1.0;
  const Wide magnitude = boost::multiprecision::abs(total_);
  const auto top_bit = static_cast<int>(boost::multiprecision::msb(magnitude));
  if (top_bit <= 52) {
    // At most 53 bits: exact as a double, and times 2^-1074 exact too (subnormal or not).
    return sign * std::ldexp(magnitude.convert_to<double>(), unit_exponent);
  }
  const int dropped = top_bit - 52;
  auto kept = static_cast<std::uint64_t>(magnitude >> dropped);
  const bool half = boost::multiprecision::bit_test(magnitude, static_cast<unsigned>(dropped - 1));
  const bool sticky = static_cast<int>(boost::multiprecision::lsb(magnitude)) < dropped - 1;
  if (half && (sticky || (kept & 1U) != 0)) {
    ++kept; // 2^53 at most: still exact as a double
  }
  // At least 2^52 2^(1 - 1074): a normal double, so the scaling is exact (or overflows to inf).
  return sign * std::ldexp(static_cast<double>(kept), dropped + unit_exponent);
}

} // namespace revsph::fixedpoint
