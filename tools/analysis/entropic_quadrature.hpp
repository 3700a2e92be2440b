#pragma once
// The quadrature test of paper 4 (Pavelka, Klika, Kincl 2024, §3.4, Fig. 2, eqs. 29-31): how
// well sum_a V_a f(x_a) over the particles in [0,1]^2 integrates f, for the mass/entropic particle
// volume (eqs. 23-24 with m = S = 1: V_a = 1 / sum_b W_ab) and the implicit one (eq. 26: W V = 1,
// solved over all particles).
//
// Particles: core's hexagonal lattice (core/particle_blocks.hpp), mapped affinely onto `columns`
// columns and `rows` rows per unit length, rows the even number nearest to 2 columns / sqrt(3).
// The lattice is hexagonal to within 1 / (2 rows) in its aspect ratio, and it tiles [0,1]^2
// exactly: rows lie half a row period inside the boundary, and even and odd rows a quarter and
// three quarters of a column period, so that the boundary cuts no particle's share unevenly (a
// true hexagonal lattice leaves a misfit of up to half a row period, an O(dr) error of its own).
// Then N = columns rows particles lie in [0,1]^2, and dr = 1 / sqrt(N) (31) is the mean spacing.
// Kernel: the Wendland quintic with support radius h = 3 dr. Dummy particles continue the lattice
// in a band at least band_width h + one period wide around the square: they take part in the
// kernel sums and in W, but not in the quadrature sum ("dummy particles ... to prevent large error
// near boundary"). The mass volume does not depend on the band once it is wider than h; the
// implicit volume does: W V = 1 has a boundary layer at the band's outer edge, which reaches into
// the square for narrow bands (for bands of 1, 2, 4, 6 h the implicit error at N = 39 804 differs
// from the mass one by -2.5 %, -0.7 %, -0.02 %, -1e-4 % of it).

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace revsph::analysis {

// Eq. (30) and the exact integrals over [0,1]^2.
struct QuadratureFunction {
  std::string_view name;
  double (*f)(double x, double y);
  double exact;
};
const std::array<QuadratureFunction, 3>& quadrature_functions();

enum class QuadratureVolume { mass, implicit };
std::string_view name_of(QuadratureVolume volume);

struct QuadratureResult {
  int columns = 0;
  int rows = 0;
  std::size_t particles = 0; // N, in [0,1]^2
  std::size_t dummies = 0;
  double dr = 0.0;
  // quadrature[volume][function]: sum_a V_a f(x_a) over the N particles, in quadrature_functions()
  // order; volume 0 mass, 1 implicit.
  std::array<std::array<double, 3>, 2> quadrature{};
  // sum_a V_a over the N particles: the quadrature of f = 1. On a lattice sum_b W_ab misses
  // 1 / (area per particle) by a bias fixed by h / dr (aliasing of the kernel: +0.54 % here, for
  // h = 2.79 nearest-neighbour spacings), so volume_sum - 1 tends to a constant, not to zero, and
  // so does every relative error (the paper's note on the truncation error's optimum, §3.2).
  std::array<double, 2> volume_sum{};
  int solver_iterations = 0; // conjugate gradients of W V = 1
  double solver_residual = 0.0;

  double relative_error(QuadratureVolume volume, int function) const;
};

// One lattice with `columns` >= 2 columns (N ~ 1.15 columns^2). Throws std::runtime_error if the
// implicit volume's solve does not converge.
QuadratureResult entropic_quadrature(int columns, double band_width = 1.0);

// The column count whose N = columns rows is nearest to `particles`.
int columns_for(double particles);

} // namespace revsph::analysis
