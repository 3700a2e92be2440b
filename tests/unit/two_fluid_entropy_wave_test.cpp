// Paper 5's entropy-wave benchmark (sec. V.2, App. A) on small lattices
// (tools/analysis/two_fluid_entropy_wave.hpp): the operators are exact for a quadratic away from
// the sides on the unperturbed lattice, and the wave's error falls with the spacing.

#include "tools/analysis/two_fluid_entropy_wave.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace revsph::analysis;

// phi = x^2 + 2 y^2: lap phi = 6 wherever the kernel does not reach a side (the odd images there
// continue phi antisymmetrically, which is not phi).
TEST(TwoFluidEntropyWave, OperatorsAreExactForAQuadraticOnTheLattice) {
  const WaveParticles particles = wave_particles(40, 0.0, 1);
  std::vector<double> phi;
  for (const auto& x : particles.position) {
    phi.push_back(x[0] * x[0] + 2.0 * x[1] * x[1]);
  }
  for (const WaveLaplacian method : {WaveLaplacian::sph, WaveLaplacian::fd}) {
    const std::vector<double> lap = apply_wave_laplacian(particles, method, phi);
    double worst = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) {
      const auto& x = particles.position[i];
      const double margin = 5.0 * particles.spacing; // beyond the support 3 l
      if (x[0] > margin && x[0] < 1.0 - margin && x[1] > margin && x[1] < 1.0 - margin) {
        worst = std::max(worst, std::abs(lap[i] - 6.0));
      }
    }
    EXPECT_LT(worst, 1e-8) << name_of(method);
  }
}

// Without displacements the App. A operator's error is its dispersion on the lattice, second
// order in l: E_r over a fixed time falls about fourfold from 50 to 100 particles per side.
TEST(TwoFluidEntropyWave, ErrorFallsWithTheSpacingAtSecondOrder) {
  auto error_with = [](int per_side) {
    EntropyWaveOptions options;
    options.per_side = per_side;
    options.t_end = 0.01;
    return entropy_wave(options).mean_error_percent;
  };
  const double coarse = error_with(50);
  const double fine = error_with(100);
  std::printf("E_r at 50 and 100 per side: %.4e %%, %.4e %%, ratio %.2f\n", coarse, fine,
              coarse / fine);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.0);
}

} // namespace
