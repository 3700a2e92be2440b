#pragma once
// The entropy-wave benchmark of paper 5 (Tsuzuki 2021, sec. V.2, Figs. 7-8, Appendix A): the
// wave equation d^2 S / dt^2 = c^2 lap S (42) on the unit square with S = 0 on its four sides
// (43)-(44), started from the mode (m, n) = (4, 3) at rest, so that (45)-(47)
//   S_a(x, y, t) = cos(lambda t) sin(4 pi x) sin(3 pi y),   lambda = c pi sqrt(4^2 + 3^2) = 5 c pi.
// Time: the second-order central difference S^{n+1} = 2 S^n - S^{n-1} + dt^2 c^2 L S^n; space: L
// one of three Laplacians on the same particles, so that only the spatial error differs.
//
// Particles: per_side^2 on the square lattice ((i + 1/2) l, (j + 1/2) l), l = 1 / per_side, each
// shifted by dl in a random direction. The paper's volume fluctuation rate
// dD = ((l + dl)^2 - l^2) / l^2 x 100 (sec. V.2) is the input: dl = l (sqrt(1 + dD / 100) - 1)
// (dD = 0.5 % is dl = 0.0025 l). The boundary S = 0 is the odd mirror image of the particles
// across each side (and the even double image across each corner) within the kernel's reach:
// ghosts that carry -S (+S at the corners) of their source, folded into the operator's
// coefficients, so that every operator sees an antisymmetric continuation and S = 0 on the sides.
//
// Measured (400^2, dt = 0.1 l / c, seed 1; docs/figures/two_fluid_entropy_wave.csv): at c = 135
// E_r is set by the mode's phase error at t_end, which L's dispersion makes 0.0106 rad for sph (its
// wave 1.7e-4 slow at support 3 l), 2.2e-3 for fd, 0.25 rad for brookshaw: E_r = 0.213, 0.044,
// 4.4 %. The displacements add a shift of that phase, second order in dl, and a part outside the
// mode, first order (0.0034 dD %): E_r = 0.2125 + 0.0015 dD^2.3 %. At c = 20, lambda t_end = 3 pi
// puts t_end on an extremum of S_a, where a phase error enters E_r only at second order, and
// E_r = 0.0028 dD^1.0 % (3e-5 % at dD = 0).

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace revsph::analysis {

enum class WaveLaplacian {
  sph,       // App. A, eqs. (A3)-(A4), (A7)-(A9): the MPS-normalised form the paper uses
  brookshaw, // eq. (14) = (A1) with its factor 2 restored and V_j = 1 / sum_k W_jk
  fd,        // the 5-point finite difference on the unperturbed lattice
};
std::string_view name_of(WaveLaplacian method);
// Throws std::invalid_argument for a name other than sph, brookshaw, fd.
WaveLaplacian wave_laplacian_named(std::string_view name);

struct EntropyWaveOptions {
  WaveLaplacian method = WaveLaplacian::sph;
  double speed = 135.0;                  // c [m/s]: the paper's 135 and 20
  double fluctuation_percent = 0.0;      // dD; must be 0 for fd, which has no particle positions
  int per_side = 400;                    // N_px = N_py
  double support_over_l = 3.0;           // the Wendland quintic's support radius / l: the paper
                                         // names no kernel; 3 l as paper 1 and paper 4 (sec. 3.4)
  std::uint64_t seed = 1;                // of the displacement directions
  double t_end = 0.03;                   // [s]
  double dt_factor = 0.1;                // dt = dt_factor l / c, rounded down to hit t_end
  int probe_every = 10;                  // steps between the probe's samples
  std::array<double, 2> probe{0.3, 0.4}; // the probe: the particle of the lattice cell
                                         // (i l..(i+1) l, j l..(j+1) l) holding this point
};

// The particles in lattice order (index j per_side + i for lattice node (i, j)).
struct WaveParticles {
  int per_side = 0;
  double spacing = 0.0;      // l
  double displacement = 0.0; // dl
  double support_over_l = 3.0;
  std::vector<std::array<double, 2>> position;
};

// dl for a volume fluctuation rate dD in percent.
double displacement_for(double fluctuation_percent, double spacing);

// Throws std::invalid_argument if per_side is too small for the kernel's reach, the support is
// outside [1.5, 6] l, or dD is negative or so large that a particle could leave the square
// (dl >= l / 2).
WaveParticles wave_particles(int per_side, double fluctuation_percent, std::uint64_t seed,
                             double support_over_l = 3.0);

// L phi over the particles, the sides' odd images included (a check of the operator: for a
// quadratic phi its exact value away from the sides).
std::vector<double> apply_wave_laplacian(const WaveParticles& particles, WaveLaplacian method,
                                         std::span<const double> phi);

struct EntropyWaveResult {
  double spacing = 0.0;
  double displacement = 0.0; // dl (0 for fd)
  double dt = 0.0;
  long steps = 0;
  std::size_t nonzeros = 0; // of L, ghosts folded in
  // The paper's E_r at t_end (see entropy_wave) and the largest particle term of its mean.
  double mean_error_percent = 0.0;
  double max_error_percent = 0.0;
  // The same mean with the paper's printed denominator |S_a + A| (zero where S_a = -A: large
  // wherever t_end puts a trough near a particle).
  double literal_error_percent = 0.0;
  // E_r splits into a phase error of the mode and a part outside the mode: a = sum_i S_i f_i /
  // sum_i f_i^2, f = sin(4 pi x) sin(3 pi y), the mode's least-squares amplitude at t_end (exact:
  // cos(lambda t_end)), and E_r's formula applied to S - a f. The first is mostly L's dispersion
  // on the lattice (the displacements shift it at second order in dl), the second the response to
  // L's pointwise error, which is first order in dl (sum_j P_ij r_ji no longer vanishes).
  double mode_amplitude = 0.0;
  double off_mode_error_percent = 0.0;
  std::array<double, 2> probe_position{}; // of the probe particle, (i + 1/2, j + 1/2) l + dl e
  std::vector<double> probe_time;
  std::vector<double> probe_value;
  std::vector<double> probe_exact;
};

// One run. E_r is the mean over the particles of |S_i - S_a(x_i, t_end)| / (|S_a| + A) x 100,
// A = 1 the amplitude. The paper (sec. V.2) prints |S_a + A| in the denominator, which is zero
// wherever S_a = -1 and contradicts its own "added to avoid division by zero"; both are reported
// (literal_error_percent: as printed), since which one the paper computed is not known.
EntropyWaveResult entropy_wave(const EntropyWaveOptions& options);

} // namespace revsph::analysis
