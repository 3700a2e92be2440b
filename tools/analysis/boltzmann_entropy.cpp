#include "tools/analysis/boltzmann_entropy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace revsph::analysis {

namespace {

constexpr double quiet_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

void require_dimension(int dimension) {
  if (dimension != 2 && dimension != 3) {
    throw std::invalid_argument("Boltzmann entropy: dimension must be 2 or 3, got " +
                                std::to_string(dimension));
  }
}

void require_non_negative(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("Boltzmann entropy: ") + what +
                                " must be finite and >= 0, got " + std::to_string(value));
  }
}

void require_positive(double value, const char* what) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string("Boltzmann entropy: ") + what +
                                " must be finite and > 0, got " + std::to_string(value));
  }
}

// ln c_D, the normalisation of f / v^(D−1) at θ = 1: c_2 = 1, c_3 = √(2/π).
double log_normalisation(int dimension) {
  return dimension == 2 ? 0.0 : 0.5 * std::log(2.0 / std::numbers::pi);
}

// Least-squares distance between the histogram and the Maxwell–Boltzmann distribution at
// θ = exp(log_theta). The model is averaged over each bin (through the CDF) rather than taken at
// the centre, so that coarse bins are compared like with like and the fit carries no
// discretisation bias.
double fit_residual(const SpeedHistogram& histogram, int dimension, double log_theta) {
  const double theta = std::exp(log_theta);
  double residual = 0.0;
  double lower_cdf = 0.0;
  for (int i = 0; i < histogram.bins(); ++i) {
    const auto bin = static_cast<std::size_t>(i);
    const double upper_cdf = maxwell_boltzmann_cdf(histogram.edges[bin + 1], theta, dimension);
    const double model = (upper_cdf - lower_cdf) / histogram.bin_width;
    const double difference = histogram.density[bin] - model;
    residual += difference * difference;
    lower_cdf = upper_cdf;
  }
  return residual;
}

} // namespace

SpeedHistogram speed_histogram(std::span<const double> speeds, int bins,
                               std::optional<double> max_speed) {
  if (bins < 1) {
    throw std::invalid_argument("speed histogram: the number of bins must be >= 1, got " +
                                std::to_string(bins));
  }
  if (speeds.empty()) {
    throw std::invalid_argument("speed histogram: no speeds");
  }
  double largest = 0.0;
  for (const double speed : speeds) {
    require_non_negative(speed, "a speed");
    largest = std::max(largest, speed);
  }
  if (max_speed) {
    require_positive(*max_speed, "the maximum speed of the histogram");
  }

  SpeedHistogram histogram;
  histogram.max_speed = max_speed.value_or(largest);
  histogram.bin_width = histogram.max_speed / bins;
  histogram.samples = speeds.size();
  const auto bin_count = static_cast<std::size_t>(bins);
  histogram.edges.resize(bin_count + 1);
  histogram.centres.resize(bin_count);
  histogram.counts.assign(bin_count, 0);
  histogram.density.assign(bin_count, 0.0);
  // Edges as v_max · i / bins, not i · Δv, so that the last edge is v_max exactly.
  for (std::size_t i = 0; i <= bin_count; ++i) {
    histogram.edges[i] = histogram.max_speed * static_cast<double>(i) / bins;
  }
  for (std::size_t i = 0; i < bin_count; ++i) {
    histogram.centres[i] = 0.5 * (histogram.edges[i] + histogram.edges[i + 1]);
  }
  if (histogram.degenerate()) {
    histogram.counts[0] = speeds.size();
    return histogram;
  }

  for (const double speed : speeds) {
    if (speed > histogram.max_speed) {
      ++histogram.above_max;
      continue;
    }
    // The closed last bin keeps v_max itself (which floor would put one bin too far).
    const auto bin = std::min(static_cast<std::size_t>(speed / histogram.bin_width), bin_count - 1);
    ++histogram.counts[bin];
  }
  const double normalisation = static_cast<double>(speeds.size()) * histogram.bin_width;
  for (std::size_t i = 0; i < bin_count; ++i) {
    histogram.density[i] = static_cast<double>(histogram.counts[i]) / normalisation;
  }
  return histogram;
}

double maxwell_boltzmann_density(double speed, double theta, int dimension) {
  require_dimension(dimension);
  require_non_negative(speed, "the speed");
  require_positive(theta, "theta");
  const double boltzmann_factor = std::exp(-speed * speed / (2.0 * theta));
  if (dimension == 2) {
    return speed / theta * boltzmann_factor; // eq. (19), corrected
  }
  return 4.0 * std::numbers::pi * std::pow(2.0 * std::numbers::pi * theta, -1.5) * speed * speed *
         boltzmann_factor;
}

double maxwell_boltzmann_cdf(double speed, double theta, int dimension) {
  require_dimension(dimension);
  require_non_negative(speed, "the speed");
  require_positive(theta, "theta");
  const double half_square = speed * speed / (2.0 * theta);
  if (dimension == 2) {
    return -std::expm1(-half_square);
  }
  const double x = std::sqrt(half_square);
  const double cdf = std::erf(x) - 2.0 / std::sqrt(std::numbers::pi) * x * std::exp(-half_square);
  return std::max(cdf, 0.0); // the difference can round below 0 for tiny x
}

double reduced_entropy(const SpeedHistogram& histogram, int dimension) {
  require_dimension(dimension);
  if (histogram.degenerate()) {
    return -infinity;
  }
  if (histogram.binned() == 0) {
    return quiet_nan;
  }
  // Eq. (17) by the midpoint rule. In the first bin the Maxwell–Boltzmann density grows like
  // f'(0) v (2D); its bin average is f'(0) Δv/2 = f'(0) c_1, so f_1 / c_1 = f'(0) exactly and the
  // first bin needs no special treatment (centres are never 0). Integrating ln v exactly over a
  // piecewise-constant f instead would be wrong precisely there (by P_1 (1 − ln 2)). In 3D,
  // f ≈ a v² gives f_1 / c_1² = 4a/3: an error P_1 ln(4/3), with P_1 ≈ a Δv³/3 < 1e-5 for 100
  // bins over a thermal sample.
  const double samples = static_cast<double>(histogram.samples);
  double entropy = 0.0;
  for (std::size_t i = 0; i < histogram.counts.size(); ++i) {
    if (histogram.counts[i] == 0) {
      continue; // P ln P → 0
    }
    const double probability = static_cast<double>(histogram.counts[i]) / samples;
    const double log_weight = (dimension - 1) * std::log(histogram.centres[i]);
    entropy -= probability * (std::log(histogram.density[i]) - log_weight);
  }
  return entropy;
}

double fit_theta(const SpeedHistogram& histogram, int dimension) {
  require_dimension(dimension);
  if (histogram.degenerate()) {
    return 0.0;
  }
  if (histogram.binned() == 0) {
    return quiet_nan;
  }
  // Bracket: the histogram's own second moment gives θ up to the shape of the distribution; a
  // far from equilibrium histogram (e.g. most particles at rest and a fast few) can fit a θ
  // orders of magnitude away from it, hence the wide bracket, scanned on a grid in ln θ so that
  // the golden-section refinement starts next to the global minimum, not a local one.
  double second_moment = 0.0;
  double binned = 0.0;
  for (std::size_t i = 0; i < histogram.counts.size(); ++i) {
    const auto count = static_cast<double>(histogram.counts[i]);
    second_moment += count * histogram.centres[i] * histogram.centres[i];
    binned += count;
  }
  const double log_theta_moment = std::log(second_moment / binned / dimension);
  constexpr double log_bracket_half_width = 4.0 * std::numbers::ln10; // θ_moment · 10^(±4)
  constexpr int grid_intervals = 160;
  const double grid_step = 2.0 * log_bracket_half_width / grid_intervals;
  const double grid_start = log_theta_moment - log_bracket_half_width;
  int best = 0;
  double best_residual = infinity;
  for (int k = 0; k <= grid_intervals; ++k) {
    const double residual = fit_residual(histogram, dimension, grid_start + k * grid_step);
    if (residual < best_residual) {
      best_residual = residual;
      best = k;
    }
  }

  // Golden-section search on [u_(k−1), u_(k+1)] around the best grid point u_k.
  double low = grid_start + std::max(best - 1, 0) * grid_step;
  double high = grid_start + std::min(best + 1, grid_intervals) * grid_step;
  const double inverse_golden = (std::sqrt(5.0) - 1.0) / 2.0;
  double left = high - inverse_golden * (high - low);
  double right = low + inverse_golden * (high - low);
  double left_residual = fit_residual(histogram, dimension, left);
  double right_residual = fit_residual(histogram, dimension, right);
  while (high - low > 1e-10) {
    if (left_residual < right_residual) {
      high = right;
      right = left;
      right_residual = left_residual;
      left = high - inverse_golden * (high - low);
      left_residual = fit_residual(histogram, dimension, left);
    } else {
      low = left;
      left = right;
      left_residual = right_residual;
      right = low + inverse_golden * (high - low);
      right_residual = fit_residual(histogram, dimension, right);
    }
  }
  return std::exp(0.5 * (low + high));
}

double moment_theta(std::span<const double> speeds, int dimension) {
  require_dimension(dimension);
  if (speeds.empty()) {
    throw std::invalid_argument("Boltzmann entropy: no speeds for the moment estimate of theta");
  }
  double sum_of_squares = 0.0;
  for (const double speed : speeds) {
    require_non_negative(speed, "a speed");
    sum_of_squares += speed * speed;
  }
  return sum_of_squares / static_cast<double>(speeds.size()) / dimension;
}

double theta_from_energy(double kinetic_energy, double particles, double mass, int dimension) {
  require_dimension(dimension);
  require_non_negative(kinetic_energy, "the kinetic energy");
  require_positive(particles, "the number of particles");
  require_positive(mass, "the particle mass");
  return 2.0 * kinetic_energy / (dimension * particles * mass); // E = (D/2) N m θ
}

double equilibrium_entropy(double theta, int dimension) {
  require_dimension(dimension);
  if (std::isnan(theta)) {
    return quiet_nan; // an undefined fit stays undefined (fit_theta documents when)
  }
  require_non_negative(theta, "theta");
  // Eq. (20) for D = 2; D/2 + (D/2) ln θ − ln c_D in general (header).
  const double half_dimension = 0.5 * dimension;
  return half_dimension + half_dimension * std::log(theta) - log_normalisation(dimension);
}

double equilibrium_entropy_from_energy(double kinetic_energy, double particles, double mass,
                                       int dimension) {
  // Eq. (21) for D = 2: eq. (20) at θ = 2E / (D N m).
  return equilibrium_entropy(theta_from_energy(kinetic_energy, particles, mass, dimension),
                             dimension);
}

} // namespace revsph::analysis
