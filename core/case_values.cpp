#include "core/case_values.hpp"

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

std::string format_scientific(double value, int digits) {
  std::ostringstream text;
  text.precision(digits);
  text << std::scientific << value;
  return text.str();
}

} // namespace revsph
