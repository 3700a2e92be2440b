#pragma once
// Compiled with the same flags as the physics, so that a test can detect whether the compiler
// contracts a*b + c into a fused multiply-add (which would change results between builds).

namespace revsph {

double multiply_add_unfused(double a, double b, double c);

} // namespace revsph
