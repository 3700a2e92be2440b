#pragma once
// A fixed-point scale: a quantity's physical value is raw * 2^exponent.
//
// Scales are powers of two so that converting between the raw integer and a double is a pure
// exponent shift: exact whenever |raw| < 2^53 (design note exact-reversibility.md §1).

#include <cmath>
#include <string>

namespace revsph::fixedpoint {

class Scale {
public:
  constexpr Scale() = default;
  explicit Scale(int exponent)
      : exponent_(exponent), unit_(std::ldexp(1.0, exponent)),
        inverse_unit_(std::ldexp(1.0, -exponent)) {}

  // The smallest power-of-two scale whose raw range covers |value| <= max_magnitude with
  // `fraction_bits` bits of resolution below it: e.g. positions in a 4 m box with 52 bits.
  static Scale covering(double max_magnitude, int fraction_bits);

  int exponent() const { return exponent_; }
  // The physical value of one raw unit (one "unit in the last place").
  double unit() const { return unit_; }
  double inverse_unit() const { return inverse_unit_; }
  // The largest physical magnitude a raw int64 can hold at this scale.
  double max_magnitude() const { return std::ldexp(1.0, 63 + exponent_); }

  friend bool operator==(const Scale& a, const Scale& b) { return a.exponent_ == b.exponent_; }

private:
  int exponent_ = 0;
  double unit_ = 1.0;
  double inverse_unit_ = 1.0;
};

std::string describe(const Scale& scale);

} // namespace revsph::fixedpoint
