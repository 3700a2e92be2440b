#pragma once
// Uniform numbers from a 64-bit Mersenne twister that are the same with every standard library
// (std::uniform_real_distribution is not specified bit for bit): seeded initial states then
// give the same golden hashes everywhere.

#include <random>

namespace revsph {

// Uniform in [0, 1).
inline double unit_uniform(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

// Uniform in [-1, 1).
inline double symmetric_uniform(std::mt19937_64& generator) {
  return 2.0 * unit_uniform(generator) - 1.0;
}

} // namespace revsph
