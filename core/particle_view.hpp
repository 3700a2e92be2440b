#pragma once
// A physical per-particle quantity for people (density, pressure, energy per particle, …):
// written to snapshots for ParaView and Python, never read back into a simulation. The exact
// state is the StateSnapshot; views of it and derived quantities are doubles.

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

} // namespace revsph
