#include "core/determinism_probe.hpp"

namespace revsph {

double multiply_add_unfused(double a, double b, double c) {
  return a * b + c;
}

} // namespace revsph
