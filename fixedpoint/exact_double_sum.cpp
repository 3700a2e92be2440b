#include "fixedpoint/exact_double_sum.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace revsph::fixedpoint {

namespace {

// The smallest subnormal is 2^-1074: every finite double is term = units 2^-1074.
constexpr int unit_exponent = -1074;

__extension__ using uint128 = unsigned __int128;

} // namespace

void ExactDoubleSum::add(double term) {
  // IEEE 754 binary64: a normal double with biased exponent e and fraction f is
  // (2^52 + f) 2^(e - 1075) = (2^52 + f) 2^(e - 1) units of 2^-1074; a subnormal (e = 0) is
  // f units.
  const auto bits = std::bit_cast<std::uint64_t>(term);
  const auto biased_exponent = static_cast<int>((bits >> 52) & 0x7FFU);
  if (biased_exponent == 0x7FF) {
    finite_ = false;
    return;
  }
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  int shift = 0;
  if (biased_exponent != 0) {
    mantissa |= std::uint64_t{1} << 52;
    shift = biased_exponent - 1;
  }
  const bool negative = (bits >> 63) != 0;
  const uint128 placed = static_cast<uint128>(mantissa) << (shift % chunk_bits);
  const int first = shift / chunk_bits; // at most 63: the three chunks fit in 70
  for (int c = 0; c < 3; ++c) {
    const auto piece = static_cast<std::int64_t>(
        static_cast<std::uint64_t>(placed >> (chunk_bits * c)) & 0xFFFFFFFFU);
    chunks_[static_cast<std::size_t>(first + c)] += negative ? -piece : piece;
  }
  if (++pending_ == terms_before_folding) {
    fold();
  }
}

void ExactDoubleSum::fold() {
  for (int c = chunk_count - 1; c >= 0; --c) {
    std::int64_t& chunk = chunks_[static_cast<std::size_t>(c)];
    if (chunk != 0) {
      folded_ += Wide(chunk) << (chunk_bits * c);
      chunk = 0;
    }
  }
  pending_ = 0;
}

ExactDoubleSum::Wide ExactDoubleSum::units() const {
  ExactDoubleSum copy = *this;
  copy.fold();
  return copy.folded_;
}

ExactDoubleSum::Image ExactDoubleSum::image() const {
  const Wide total = units();
  Image image{};
  // Least significant byte first; the magnitude has at most 2 240 bits, so it fills at most the
  // 280 bytes before the sign.
  boost::multiprecision::export_bits(boost::multiprecision::abs(total), image.begin(), 8,
                                     /*msv_first=*/false);
  image[image_size - 2] = total < 0 ? 1 : 0;
  image[image_size - 1] = finite_ ? 1 : 0;
  return image;
}

ExactDoubleSum ExactDoubleSum::from_image(const Image& image) {
  Wide magnitude = 0;
  boost::multiprecision::import_bits(magnitude, image.begin(), image.end() - 2, 8,
                                     /*msv_first=*/false);
  return from_units(image[image_size - 2] != 0 ? Wide(-magnitude) : magnitude,
                    image[image_size - 1] != 0);
}

void ExactDoubleSum::add(const ExactDoubleSum& other) {
  folded_ += other.units();
  finite_ = finite_ && other.finite_;
}

double ExactDoubleSum::value() const {
  if (!finite_) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const Wide total = units();
  if (total == 0) {
    return 0.0;
  }
  // Round |total| to 53 significant bits, to nearest with ties to even: the bit below the kept
  // ones decides, and any bit under it (sticky) breaks a tie upward. (Boost's conversion to a
  // 53-bit cpp_bin_float drops the sticky bits: 1 + 2^-53 + 2^-200 came out as 1.)
  const double sign = total < 0 ? -1.0 : 1.0;
  const Wide magnitude = boost::multiprecision::abs(total);
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
