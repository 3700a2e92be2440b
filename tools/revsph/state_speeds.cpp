#include "tools/revsph/state_speeds.hpp"

#include "core/distributed/records_of_every_process.hpp"
#include "core/global_totals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace revsph::cli {

namespace {

// The set's velocities: its velocity field, or its momentum over its mass (entropic SPH, the
// two-fluid model); nullptr if it has neither (or no mass).
const FieldSnapshot* velocity_or_momentum(const StateSnapshot& state, const std::string& set,
                                          bool& is_momentum) {
  if (state.find(set, "mass") == nullptr) {
    return nullptr;
  }
  is_momentum = false;
  if (const FieldSnapshot* velocity = state.find(set, "velocity")) {
    return velocity;
  }
  is_momentum = true;
  return state.find(set, "momentum");
}

} // namespace

ParticleSpeeds particle_speeds(const StateSnapshot& state, const std::string& particle_set) {
  bool is_momentum = false;
  const FieldSnapshot* motion = velocity_or_momentum(state, particle_set, is_momentum);
  const FieldSnapshot* mass = state.find(particle_set, "mass");
  if (motion == nullptr) {
    throw std::invalid_argument("particle set '" + particle_set +
                                "' has no mass with a velocity or momentum field (choose one "
                                "with --particle-set)");
  }
  const std::uint64_t particles = whole_count(state, *motion);
  if (particles == 0) {
    throw std::invalid_argument("particle set '" + particle_set + "' is empty");
  }
  ParticleSpeeds result;
  result.dimension = motion->info.components;
  result.speeds.resize(motion->count);
  result.in_pieces = !state.pieces.empty();
  ExactDoubleSum kinetic_energy;
  ExactDoubleSum total_mass;
  for (std::size_t particle = 0; particle < motion->count; ++particle) {
    const double m = mass->real(0, particle);
    double square = 0.0;
    for (int component = 0; component < motion->info.components; ++component) {
      const double v =
          is_momentum ? motion->real(component, particle) / m : motion->real(component, particle);
      square += v * v;
    }
    if (!std::isfinite(square) || !std::isfinite(m) || m <= 0.0) {
      throw std::invalid_argument(particle_set + " particle " + std::to_string(particle) +
                                  ": velocity or mass is not finite (or the mass is not "
                                  "positive)");
    }
    result.speeds[particle] = std::sqrt(square);
    kinetic_energy.add(0.5 * m * square);
    total_mass.add(m);
  }
  // Exact sums: the same totals whoever holds which particles.
  result.kinetic_energy = result.in_pieces ? global_total(kinetic_energy) : kinetic_energy.value();
  result.mean_mass = (result.in_pieces ? global_total(total_mass) : total_mass.value()) /
                     static_cast<double>(particles);
  return result;
}

double largest_own_speed(const StateSnapshot& state, const std::vector<std::string>& moving) {
  double largest = 0.0;
  for (const std::string& set : moving) {
    bool is_momentum = false;
    const FieldSnapshot* motion = velocity_or_momentum(state, set, is_momentum);
    if (motion == nullptr) {
      continue;
    }
    const FieldSnapshot& mass = *state.find(set, "mass");
    for (std::size_t particle = 0; particle < motion->count; ++particle) {
      double square = 0.0;
      for (int component = 0; component < motion->info.components; ++component) {
        const double v = is_momentum ? motion->real(component, particle) / mass.real(0, particle)
                                     : motion->real(component, particle);
        square += v * v;
      }
      largest = std::isfinite(square) ? std::max(largest, std::sqrt(square))
                                      : std::numeric_limits<double>::infinity();
    }
  }
  return largest;
}

std::optional<std::string> moving_particle_set(const StateSnapshot& state) {
  auto has_speeds = [&](const std::string& set) {
    bool is_momentum = false;
    const FieldSnapshot* motion = velocity_or_momentum(state, set, is_momentum);
    return motion != nullptr && whole_count(state, *motion) > 0;
  };
  for (const char* preferred : {"fluid", "material"}) {
    if (has_speeds(preferred)) {
      return preferred;
    }
  }
  for (const FieldSnapshot& field : state.fields) {
    if (has_speeds(field.info.particle_set)) {
      return field.info.particle_set;
    }
  }
  return std::nullopt;
}

namespace {

// A sample's histogram on the shared bins [0, max_speed] (max_speed 0: every speed is 0). The
// processes of a distributed run bin their own speeds, and the counts are summed: bin counts are
// integers, so the histogram and its entropy are the whole set's, for any decomposition.
analysis::SpeedHistogram histogram_of(const ParticleSpeeds& sample, int bins, double max_speed) {
  const std::optional<double> shared = max_speed > 0.0 ? std::optional(max_speed) : std::nullopt;
  if (!sample.in_pieces) {
    return analysis::speed_histogram(sample.speeds, bins, shared);
  }
  static constexpr double at_rest = 0.0;
  const bool none = sample.speeds.empty(); // this process holds none of the set
  analysis::SpeedHistogram histogram = analysis::speed_histogram(
      none ? std::span<const double>(&at_rest, 1) : std::span<const double>(sample.speeds), bins,
      shared);
  if (none) {
    std::fill(histogram.counts.begin(), histogram.counts.end(), 0);
    histogram.samples = 0;
    histogram.above_max = 0;
  }
  std::vector<std::int64_t> counts(histogram.counts.begin(), histogram.counts.end());
  counts.push_back(static_cast<std::int64_t>(histogram.samples));
  counts.push_back(static_cast<std::int64_t>(histogram.above_max));
  const std::vector<std::int64_t> total = distributed::combined_in_rank_order(
      std::span<const std::int64_t>(counts),
      [](std::int64_t& sum, std::int64_t more) { sum += more; });
  const std::size_t bin_count = histogram.counts.size();
  for (std::size_t i = 0; i < bin_count; ++i) {
    histogram.counts[i] = static_cast<std::size_t>(total[i]);
  }
  histogram.samples = static_cast<std::size_t>(total[bin_count]);
  histogram.above_max = static_cast<std::size_t>(total[bin_count + 1]);
  // As analysis::speed_histogram normalises (the same expression: the same bits).
  std::fill(histogram.density.begin(), histogram.density.end(), 0.0);
  if (!histogram.degenerate()) {
    const double normalisation = static_cast<double>(histogram.samples) * histogram.bin_width;
    for (std::size_t i = 0; i < bin_count; ++i) {
      histogram.density[i] = static_cast<double>(histogram.counts[i]) / normalisation;
    }
  }
  return histogram;
}

} // namespace

std::vector<SpeedEntropy> shared_bin_entropies(const std::vector<const ParticleSpeeds*>& samples,
                                               int bins) {
  double max_speed = 0.0;
  bool in_pieces = false;
  for (const ParticleSpeeds* sample : samples) {
    for (const double speed : sample->speeds) {
      max_speed = std::max(max_speed, speed);
    }
    in_pieces = in_pieces || sample->in_pieces;
  }
  if (in_pieces) {
    max_speed = global_max(max_speed);
  }
  std::vector<SpeedEntropy> result;
  for (const ParticleSpeeds* sample : samples) {
    SpeedEntropy entry;
    entry.histogram = histogram_of(*sample, bins, max_speed);
    entry.entropy = analysis::reduced_entropy(entry.histogram, sample->dimension);
    result.push_back(std::move(entry));
  }
  return result;
}

} // namespace revsph::cli
