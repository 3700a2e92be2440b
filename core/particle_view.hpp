#pragma once
// A physical per-particle quantity for people (density, pressure, energy per particle, …):
// written to snapshots for ParaView and Python, never read back into a simulation. The exact
// state is the StateSnapshot; views of it and derived quantities are doubles.

#include <functional>
#include <string>
#include <vector>

namespace revsph {

struct ParticleView {
  std::string particle_set;
  std::string name;
  std::string unit;
  int components = 1;
  std::vector<double> values; // component-major, like StateField
};

// Views are produced one at a time and handed to a sink (the snapshot writer), so that only one
// of them is in memory at once: at a million particles each is tens of megabytes.
using ViewSink = std::function<void(ParticleView&&)>;

} // namespace revsph
