#pragma once
// State fields that several models declare alike (the same name, unit, parity and scale), and the
// dummy-particle set of paper 1 App. A that wcsph and superfluid share: written once here, so that
// a state table lists only what is its own.

#include "core/particle_sets.hpp"
#include "core/state_field.hpp"
#include "core/units.hpp"

#include <string>
#include <tuple>
#include <utility>

namespace revsph {

// A position of D components (m); `evolved` false for particles held in place.
template <int D>
VariableInfo position_field(bool evolved = true) {
  return {.name = "position", .unit = "m", .components = D, .evolved = evolved};
}

// A particle's mass, fixed at setup (kg per m^(3-D)).
template <int D>
VariableInfo mass_field() {
  return {.name = "mass", .unit = mass_unit<D>, .evolved = false, .positive = true};
}

// Paper 1 eq. (5)'s integration constant C_a, fixed at setup, in the density's scale.
inline VariableInfo density_constant_field() {
  return {.name = "density_constant", .unit = "kg/m^3", .evolved = false, .scaled_as = "density"};
}

// A wall's prescribed velocity: odd (time reversal reverses a lid), not evolved.
template <int D>
VariableInfo prescribed_velocity_field() {
  return {
      .name = "velocity", .unit = "m/s", .parity = Parity::odd, .components = D, .evolved = false};
}

// Dummy particles: held in place, in the density and the pressure force like fluid particles,
// with their own masses and integration constants (paper 1 App. A; paper 3 sec. III.C).
template <int D, class Raw>
struct DummyParticles {
  static constexpr SetInfo set{.name = "dummy", .motion = Motion::fixed};
  StateField<Raw> position{position_field<D>(false)};
  StateField<Raw> mass{mass_field<D>()};
  StateField<Raw> density_constant{density_constant_field()};
  auto fields() { return std::tie(position, mass, density_constant); }
};

} // namespace revsph
