#pragma once
// Small fixed-point value types for code that handles one particle at a time (setup, tests,
// diagnostics). Bulk state lives in structure-of-arrays fields (core/state_field.hpp) at the
// same scales; these types and those fields share the conversion rules of conversion.hpp.

#include "fixedpoint/conversion.hpp"

#include <array>
#include <cstdint>
#include <string>

namespace revsph::fixedpoint {

// A scalar quantity in fixed point: the raw integer with the scale it is measured in.
struct FixedScalar {
  std::int64_t raw = 0;
  Scale scale;

  static FixedScalar from_real(double value, const Scale& scale, const std::string& quantity) {
    return {to_fixed(value, scale, quantity), scale};
  }
  double real() const { return to_real(raw, scale); }
};

// x + d with both at the same scale; throws OverflowError instead of wrapping.
FixedScalar operator+(const FixedScalar& x, const FixedScalar& d);
FixedScalar operator-(const FixedScalar& x, const FixedScalar& d);
FixedScalar operator-(const FixedScalar& x);

template <int D>
struct FixedVector {
  std::array<std::int64_t, D> raw{};
  Scale scale;

  static FixedVector from_real(const std::array<double, D>& value, const Scale& scale,
                               const std::string& quantity) {
    FixedVector result{{}, scale};
    for (int k = 0; k < D; ++k) {
      result.raw[k] = to_fixed(value[k], scale, quantity);
    }
    return result;
  }
  std::array<double, D> real() const {
    std::array<double, D> value{};
    for (int k = 0; k < D; ++k) {
      value[k] = to_real(raw[k], scale);
    }
    return value;
  }
  FixedScalar component(int k) const { return {raw[k], scale}; }
};

template <int D>
FixedVector<D> operator+(const FixedVector<D>& x, const FixedVector<D>& d) {
  FixedVector<D> sum{{}, x.scale};
  for (int k = 0; k < D; ++k) {
    sum.raw[k] = (x.component(k) + d.component(k)).raw;
  }
  return sum;
}

template <int D>
FixedVector<D> operator-(const FixedVector<D>& x, const FixedVector<D>& d) {
  FixedVector<D> difference{{}, x.scale};
  for (int k = 0; k < D; ++k) {
    difference.raw[k] = (x.component(k) - d.component(k)).raw;
  }
  return difference;
}

} // namespace revsph::fixedpoint
