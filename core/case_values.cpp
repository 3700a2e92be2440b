#include "core/case_values.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace revsph {

void require_positive_finite(const CaseFile& case_file, const char* key, const char* what,
                             double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream reason;
    reason << what << " is " << value << ": it must be positive and finite";
    case_file.fail(key, reason.str());
  }
}

fixedpoint::Scale mass_scale(const CaseFile& case_file, const char* density_key,
                             std::initializer_list<std::span<const double>> masses) {
  double largest = 0.0;
  for (const std::span<const double> set : masses) {
    for (const double m : set) {
      largest = std::max(largest, m);
    }
  }
  require_positive_finite(case_file, density_key,
                          "the particle mass (density times lattice cell volume)", largest);
  return fixedpoint::Scale::covering(largest, mass_fraction_bits);
}

fixedpoint::Scale scale_or(const CaseFile& case_file, const char* key, double magnitude,
                           int fraction_bits) {
  if (case_file.has(key)) {
    const std::int64_t exponent = case_file.integer(key);
    if (exponent < -1000 || exponent > 1000) {
      case_file.fail(key, "a power-of-two exponent between -1000 and 1000");
    }
    return fixedpoint::Scale(static_cast<int>(exponent));
  }
  require_positive_finite(case_file, key,
                          "the magnitude its default scale must cover (from [physics] and "
                          "[discretisation])",
                          magnitude);
  return fixedpoint::Scale::covering(magnitude, fraction_bits);
}

fixedpoint::Scale position_scale_or(const CaseFile& case_file, double max_abs_coordinate,
                                    double dr) {
  constexpr const char* key = "fixed_point.position_exponent";
  const fixedpoint::Scale scale =
      scale_or(case_file, key, max_abs_coordinate, position_fraction_bits);
  if (!(scale.unit() <= std::ldexp(dr, -16))) {
    case_file.fail(case_file.has(key) ? key : "domain.max",
                   "positions would be stored in units of " + format_scientific(scale.unit(), 3) +
                       " m, coarser than dr / 65536 = " + format_scientific(dr / 65536.0, 3) +
                       " m: the domain is too large for dr (at most 2^36 dr from the origin)");
  }
  return scale;
}

std::string format_scientific(double value, int digits) {
  std::ostringstream text;
  text.precision(digits);
  text << std::scientific << value;
  return text.str();
}

} // namespace revsph
