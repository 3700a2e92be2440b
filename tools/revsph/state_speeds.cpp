#include "tools/revsph/state_speeds.hpp"

#include <algorithm>
#include <cmath>
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
  if (motion->count == 0) {
    throw std::invalid_argument("particle set '" + particle_set + "' is empty");
  }
  ParticleSpeeds result;
  result.dimension = motion->info.components;
  result.speeds.resize(motion->count);
  double total_mass = 0.0;
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
    result.kinetic_energy += 0.5 * m * square;
    total_mass += m;
  }
  result.mean_mass = total_mass / static_cast<double>(motion->count);
  return result;
}

std::optional<std::string> moving_particle_set(const StateSnapshot& state) {
  auto has_speeds = [&](const std::string& set) {
    bool is_momentum = false;
    const FieldSnapshot* motion = velocity_or_momentum(state, set, is_momentum);
    return motion != nullptr && motion->count > 0;
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

std::vector<SpeedEntropy> shared_bin_entropies(const std::vector<const ParticleSpeeds*>& samples,
                                               int bins) {
  double max_speed = 0.0;
  for (const ParticleSpeeds* sample : samples) {
    for (const double speed : sample->speeds) {
      max_speed = std::max(max_speed, speed);
    }
  }
  std::vector<SpeedEntropy> result;
  for (const ParticleSpeeds* sample : samples) {
    SpeedEntropy entry;
    entry.histogram = analysis::speed_histogram(
        sample->speeds, bins, max_speed > 0.0 ? std::optional(max_speed) : std::nullopt);
    entry.entropy = analysis::reduced_entropy(entry.histogram, sample->dimension);
    result.push_back(std::move(entry));
  }
  return result;
}

} // namespace revsph::cli
