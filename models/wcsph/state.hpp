#pragma once
// The state of a WCSPH simulation, declared once: every field with its particle set, unit,
// parity under time reversal and (set at setup) fixed-point scale.

#include "core/state_field.hpp"

namespace revsph::wcsph {

template <int D, class Raw>
struct State {
  // Evolved: positions and velocities of the fluid particles (eqs. 1b, 1c).
  StateField<Raw> position{{"fluid", "position", "m", Parity::even, D, {}, true}};
  StateField<Raw> velocity{{"fluid", "velocity", "m/s", Parity::odd, D, {}, true}};
  // Constant: particle masses (per unit depth in 2D) and the density integration constants
  // C_a = rho0 - rho_a(t = 0) of eq. (5).
  StateField<Raw> mass{{"fluid", "mass", D == 2 ? "kg/m" : "kg", Parity::even, 1, {}, false}};
  StateField<Raw> density_constant{
      {"fluid", "density_constant", "kg/m^3", Parity::even, 1, {}, false}};
  // Constant: wall particles (§3.3) are fixed and carry only their positions.
  StateField<Raw> wall_position{{"wall", "position", "m", Parity::even, D, {}, false}};
  // Constant: dummy particles (App. A) are fixed walls that take part in the density and the
  // pressure force like fluid particles, with their own masses and integration constants.
  StateField<Raw> dummy_position{{"dummy", "position", "m", Parity::even, D, {}, false}};
  StateField<Raw> dummy_mass{{"dummy", "mass", D == 2 ? "kg/m" : "kg", Parity::even, 1, {}, false}};
  StateField<Raw> dummy_density_constant{
      {"dummy", "density_constant", "kg/m^3", Parity::even, 1, {}, false}};

  template <class Visit>
  void for_each_field(Visit&& visit) {
    visit(position);
    visit(velocity);
    visit(mass);
    visit(density_constant);
    visit(wall_position);
    visit(dummy_position);
    visit(dummy_mass);
    visit(dummy_density_constant);
  }
};

} // namespace revsph::wcsph
