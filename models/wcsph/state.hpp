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

  template <class Visit>
  void for_each_field(Visit&& visit) {
    visit(position);
    visit(velocity);
    visit(mass);
    visit(density_constant);
    visit(wall_position);
  }
};

} // namespace revsph::wcsph
