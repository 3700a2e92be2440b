#include "core/arithmetic.hpp"

namespace revsph {

std::string_view to_string(Arithmetic arithmetic) {
  return arithmetic == Arithmetic::fixed ? "fixed" : "float";
}

} // namespace revsph
