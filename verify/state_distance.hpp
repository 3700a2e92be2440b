#pragma once
// How far one state lies from another, variable by variable: what `revsph verify` reports when
// a state does not come back bit for bit (a case with irreversible terms, or float arithmetic).
//
// For each declared variable (particle set + field name):
//   - in physical units: per particle the Euclidean norm of the difference over its components
//     (|Δv| for a velocity, the Frobenius norm for a matrix), then the largest and the RMS over
//     the particles; also the RMS norm of the first state's values, as a yardstick;
//   - in units of the last place: per raw value as in state_compare.hpp (the raw integer
//     difference in fixed point; |difference| / the scale's unit, rounded up, for double state,
//     so the two arithmetics share one yardstick), then the largest and the RMS over all values.
// A bitwise comparison (state_compare.hpp) says whether the states are equal; this says by how
// much they are not.

#include "core/state_snapshot.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace revsph {

struct VariableDistance {
  std::string particle_set;
  std::string variable;
  std::string unit;
  bool evolved = true;
  std::size_t particles = 0;
  std::size_t differing_values = 0; // raw values (components × particles) that differ
  std::size_t total_values = 0;
  double max_difference = 0.0; // physical: largest per-particle norm of the difference
  double rms_difference = 0.0; // physical: RMS over particles of that norm
  double reference_rms = 0.0;  // physical: RMS over particles of the norm of the first state
  std::size_t worst_particle = 0;
  std::uint64_t max_units_in_last_place = 0;
  double rms_units_in_last_place = 0.0;

  bool identical() const { return differing_values == 0; }
  std::string name() const { return particle_set + "." + variable; }
};

struct StateDistance {
  std::vector<VariableDistance> variables; // every variable, in declaration order

  bool identical() const;
  // The variables that differ.
  std::vector<const VariableDistance*> differing() const;
  // One line per differing variable: "material.velocity: max 3.2e-04 m/s, RMS 1.1e-04 m/s (RMS
  // value 0.31 m/s); 12000 of 12000 values differ, largest 2.1e+15 units in the last place, RMS
  // 7.4e+14".
  std::vector<std::string> table() const;
};

// Throws std::invalid_argument if the states do not have the same layout (require_same_layout).
StateDistance state_distance(const StateSnapshot& from, const StateSnapshot& to);

} // namespace revsph
