#pragma once
// The state of a WCSPH simulation, declared once (core/particle_sets.hpp): three particle sets,
// every field with its unit, parity under time reversal and the quantity whose fixed-point scale
// it is stored in (chosen at setup: set_scales).

#include "core/common_fields.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"
#include "core/units.hpp"

#include <tuple>

namespace revsph::wcsph {

// The fluid: positions and velocities evolve (eqs. 1b, 1c); masses (per unit depth in 2D) and the
// density integration constants C_a = rho0 - rho_a(t = 0) of eq. (5) are constants.
template <int D, class Raw>
struct Fluid {
  static constexpr SetInfo set{.name = "fluid", .motion = Motion::moving};
  StateField<Raw> position{position_field<D>()};
  StateField<Raw> velocity{
      {.name = "velocity", .unit = "m/s", .parity = Parity::odd, .components = D}};
  StateField<Raw> mass{mass_field<D>()};
  StateField<Raw> density_constant{density_constant_field()};
  auto fields() { return std::tie(position, velocity, mass, density_constant); }
};

// Wall particles (§3.3): fixed, they carry only their positions.
template <int D, class Raw>
struct Wall {
  static constexpr SetInfo set{.name = "wall", .motion = Motion::fixed};
  StateField<Raw> position{position_field<D>(false)};
  auto fields() { return std::tie(position); }
};

// Dummy particles (App. A): fixed walls that take part in the density and the pressure force like
// fluid particles, with their own masses and integration constants.
template <int D, class Raw>
using Dummy = DummyParticles<D, Raw>; // core/common_fields.hpp

template <int D, class Raw>
struct State {
  Fluid<D, Raw> fluid;
  Wall<D, Raw> wall;
  Dummy<D, Raw> dummy;

  State() { declare_state(*this); }
  auto sets() { return std::tie(fluid, wall, dummy); }
};

} // namespace revsph::wcsph
