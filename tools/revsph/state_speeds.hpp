#pragma once
// The particle speeds of one particle set of a state, and the reduced Boltzmann entropy of their
// histogram (tools/analysis/boltzmann_entropy.hpp): shared by `revsph entropy`, which reads them
// from snapshot files, and `revsph verify`, which takes them from the states of its experiment.

#include "core/state_snapshot.hpp"
#include "tools/analysis/boltzmann_entropy.hpp"

#include <optional>
#include <string>
#include <vector>

namespace revsph::cli {

struct ParticleSpeeds {
  int dimension = 2;
  std::vector<double> speeds;
  double kinetic_energy = 0.0; // Σ m v² / 2 (per unit depth in 2D)
  double mean_mass = 0.0;
  // The speeds are this process's particles' of a state held in pieces (a distributed run):
  // histograms of them are summed over the processes.
  bool in_pieces = false;
};

// The speeds from the set's velocity field, or from its momentum over its mass where it has no
// velocity (entropic SPH, the two-fluid model). For a state held in pieces, this process's
// particles' speeds, and the kinetic energy and mean mass of the whole set (collective). Throws std::invalid_argument if the set has no
// mass with a velocity or momentum field, is empty, or holds a non-finite velocity or a mass that
// is not positive (the message names the set and particle).
ParticleSpeeds particle_speeds(const StateSnapshot& state, const std::string& particle_set);

// The largest speed of this process's particles of the sets `moving` (those with a velocity, or
// a momentum and a mass); infinity if one is not finite, 0 without any. Not collective: a
// distributed run takes the largest over the processes.
double largest_own_speed(const StateSnapshot& state, const std::vector<std::string>& moving);

// The set whose speeds describe the flow: "fluid" (WCSPH, superfluid) or "material" (SHTC) if the
// state has it with speeds (above), else the first set that has them (entropic SPH's gas, the
// two-fluid model's superfluid); nullopt if none does.
std::optional<std::string> moving_particle_set(const StateSnapshot& state);

struct SpeedEntropy {
  double entropy = 0.0; // S_D of eq. 17, as analysis::reduced_entropy
  analysis::SpeedHistogram histogram;
};

// The reduced entropies of several speed samples on common bins [0, the largest speed of all]
// (the histogram entropy depends on the bin width, so only entropies on shared bins compare).
std::vector<SpeedEntropy> shared_bin_entropies(const std::vector<const ParticleSpeeds*>& samples,
                                               int bins = analysis::default_speed_bins);

} // namespace revsph::cli
