#pragma once
// The reduced Boltzmann entropy of particle speeds (Kincl & Pavelka, Comput. Phys. Commun. 284
// (2023) 108593, §6 and Appendix B), in 2D and 3D.
//
// Temperatures are written as θ = k_B T / m (m²/s²), the combination the paper uses throughout,
// so no Boltzmann constant appears. f is the speed density of the particles (∫ f dv = 1), the
// paper's f_MB before equilibrium.
//
// 3D analogue of Appendix B. For an isotropic one-particle distribution the momentum-space element
// is 2π p dp in 2D and 4π p² dp in 3D. Repeating eqs. (13)–(17) with 4π m³ v² in place of
// 2π m² v, the part of S_Boltzmann / (k_B N) that varies with f is
//     S_D = −∫ f ln(f / v^(D−1)) dv                        (eq. 17 for D = 2)
// The MaxEnt equilibrium (18) gives the Maxwell–Boltzmann speed densities
//     2D: f(v) = (v/θ) exp(−v²/(2θ))                       (eq. 19, misprint corrected)
//     3D: f(v) = 4π (2πθ)^(−3/2) v² exp(−v²/(2θ))
// i.e. ln(f / v^(D−1)) = ln c_D − (D/2) ln θ − v²/(2θ) with c_2 = 1, c_3 = √(2/π). With
// <v²> = Dθ:
//     S_D,eq(θ) = D/2 + (D/2) ln θ − ln c_D
//       2D: 1 + ln θ                                       (eq. 20)
//       3D: 3/2 + (3/2) ln θ + (1/2) ln(π/2)
// and with the kinetic energy E = (D/2) N m θ (m the particle mass):
//       2D: 1 + ln(E/(N m))                                (eq. 21)
//       3D: 3/2 + (3/2) ln(2E/(3 N m)) + (1/2) ln(π/2)
// For any f with <v²> = Dθ, S_D,eq(θ) − S_D = ∫ f ln(f/f_MB) dv ≥ 0 (Gibbs' inequality): at a
// given kinetic energy the Maxwell–Boltzmann distribution has the largest reduced entropy, which
// is the direction the second law predicts the entropy of an isolated system to move in.
//
// All functions take the dimension D ∈ {2, 3} and throw std::invalid_argument for anything else,
// and for negative or non-finite speeds, energies or masses.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace revsph::analysis {

// The authors' histograms have 100 bins.
inline constexpr int default_speed_bins = 100;

// Uniform bins on [0, v_max]; bin i is [edges[i], edges[i+1]), the last bin also holds v_max.
struct SpeedHistogram {
  double max_speed = 0.0;      // v_max
  double bin_width = 0.0;      // Δv = v_max / bins; 0 only if v_max = 0 (degenerate)
  std::vector<double> edges;   // bins + 1 values, edges[0] = 0, edges[bins] = v_max
  std::vector<double> centres; // bins values, (edges[i] + edges[i+1]) / 2, never 0
  std::vector<std::size_t> counts;
  // f_i = n_i / (N Δv) with N = samples, so Σ f_i Δv = 1 unless speeds lie above v_max.
  // All zero for a degenerate histogram (the density of "every speed is 0" is a delta).
  std::vector<double> density;
  std::size_t samples = 0;   // N: every speed given, binned or not
  std::size_t above_max = 0; // speeds > v_max (possible only with an explicit v_max): not binned

  int bins() const { return static_cast<int>(counts.size()); }
  std::size_t binned() const { return samples - above_max; }
  // Every speed is 0 and no positive v_max was given: there are no bins to resolve.
  bool degenerate() const { return bin_width == 0.0; }
};

// Histogram of `speeds` (≥ 0, finite; at least one). `max_speed` (> 0) defaults to the largest
// speed; an explicit one lets several histograms share their bins.
SpeedHistogram speed_histogram(std::span<const double> speeds, int bins = default_speed_bins,
                               std::optional<double> max_speed = std::nullopt);

// Maxwell–Boltzmann speed density at temperature θ (eq. 19 corrected; 3D analogue above).
double maxwell_boltzmann_density(double speed, double theta, int dimension);
// Its cumulative distribution: the probability of a speed ≤ `speed`.
double maxwell_boltzmann_cdf(double speed, double theta, int dimension);

// Reduced Boltzmann entropy S_D = −∫ f ln(f / v^(D−1)) dv (eq. 17) of the histogram, by the
// midpoint rule on the bins: −Σ P_i ln(f_i / c_i^(D−1)), P_i = n_i / N, c_i the bin centre, empty
// bins contributing 0 (P ln P → 0). −∞ for a degenerate histogram (all speeds 0: a delta at v = 0
// is the limit S → −∞); NaN if no speed is binned (all above v_max), which the caller must report.
double reduced_entropy(const SpeedHistogram& histogram, int dimension);

// θ of the Maxwell–Boltzmann distribution closest to the histogram in least squares on the
// density values (eq. 19 fitted as in Fig. 6). 0 for a degenerate histogram; NaN if no speed is
// binned.
double fit_theta(const SpeedHistogram& histogram, int dimension);

// θ = <v²> / D, the estimate from the second moment (and the maximum-likelihood one for an
// exactly Maxwellian sample).
double moment_theta(std::span<const double> speeds, int dimension);

// θ of the equilibrium with kinetic energy E among `particles` particles of mass `mass`:
// E = (D/2) N m θ.
double theta_from_energy(double kinetic_energy, double particles, double mass, int dimension);

// S_D,eq(θ) (eq. 20 and its 3D analogue); −∞ for θ = 0.
double equilibrium_entropy(double theta, int dimension);
// S_D,eq(E) (eq. 21 and its 3D analogue); −∞ for E = 0.
double equilibrium_entropy_from_energy(double kinetic_energy, double particles, double mass,
                                       int dimension);

} // namespace revsph::analysis
