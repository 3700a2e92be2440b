#pragma once
// The state of a superfluid simulation (paper 3), declared once (core/particle_sets.hpp).
//
// The reversible part of eq. (19) is not volume-preserving in any per-particle variables
// (README, "The reversible step"), so no exactly invertible single-level step can follow it.
// The fluid therefore carries two copies of everything that is not a position: copy 1 (velocity,
// superflow_velocity, entropy) and copy 2 (*_copy), each updated from the other by exact shears,
// the positions drifting with their mean velocity. Both copies approximate the same solution to
// second order; the outputs report their mean and their difference.

#include "core/common_fields.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"
#include "core/units.hpp"

#include <string>
#include <tuple>
#include <utility>

namespace revsph::superfluid {

// An odd velocity of D components stored in the velocity's scale: v, v_s and their copies, on the
// fluid and on the wall.
template <int D>
VariableInfo odd_velocity(std::string name) {
  return {.name = std::move(name),
          .unit = "m/s",
          .parity = Parity::odd,
          .components = D,
          .scaled_as = "velocity"};
}

template <int D, class Raw>
struct Fluid {
  static constexpr SetInfo set{.name = "fluid", .motion = Motion::moving};
  StateField<Raw> position{position_field<D>()};
  // Copy 1: coflow velocity v, superflow velocity v_s (both odd), specific entropy s (even).
  StateField<Raw> velocity{odd_velocity<D>("velocity")};
  StateField<Raw> superflow_velocity{odd_velocity<D>("superflow_velocity")};
  StateField<Raw> entropy{{.name = "entropy", .unit = "J/(kg K)"}};
  // Copy 2.
  StateField<Raw> velocity_copy{odd_velocity<D>("velocity_copy")};
  StateField<Raw> superflow_velocity_copy{odd_velocity<D>("superflow_velocity_copy")};
  StateField<Raw> entropy_copy{
      {.name = "entropy_copy", .unit = "J/(kg K)", .scaled_as = "entropy"}};
  // Constants: mass (per unit depth in 2D), C_a of eq. (24).
  StateField<Raw> mass{mass_field<D>()};
  StateField<Raw> density_constant{density_constant_field()};
  auto fields() {
    return std::tie(position, velocity, superflow_velocity, entropy, velocity_copy,
                    superflow_velocity_copy, entropy_copy, mass, density_constant);
  }
};

// Adiabatic walls (sec. III.C): static dummy particles that take part in the density and the
// pressure force only.
template <int D, class Raw>
using Dummy = DummyParticles<D, Raw>; // core/common_fields.hpp

// No-slip walls (sec. III.A-C): static particles in the density and the pressure force like
// dummies, that also drag the normal fluid toward their own velocity (zero, or a lid's) through
// the viscosity and, with heat conduction, hold the fluid at T0: the cryostat's cooler. Their
// velocity is prescribed (odd: time reversal reverses a lid). With physics.cooler = "absorbing"
// (the authors' fountain code) they also carry a free superflow velocity, in two copies like the
// fluid's, and take part in the reversible entropy flux and thermomechanical force at s = s0;
// otherwise their superflow velocity stays at its start, their own velocity.
template <int D, class Raw>
struct Wall {
  static constexpr SetInfo set{.name = "wall", .motion = Motion::fixed};
  StateField<Raw> position{position_field<D>(false)};
  StateField<Raw> velocity{prescribed_velocity_field<D>()};
  StateField<Raw> superflow_velocity{odd_velocity<D>("superflow_velocity")};
  StateField<Raw> superflow_velocity_copy{odd_velocity<D>("superflow_velocity_copy")};
  StateField<Raw> mass{mass_field<D>()};
  StateField<Raw> density_constant{density_constant_field()};
  auto fields() {
    return std::tie(position, velocity, superflow_velocity, superflow_velocity_copy, mass,
                    density_constant);
  }
};

template <int D, class Raw>
struct State {
  Fluid<D, Raw> fluid;
  Dummy<D, Raw> dummy;
  Wall<D, Raw> wall;

  State() { declare_state(*this); }
  auto sets() { return std::tie(fluid, dummy, wall); }
};

} // namespace revsph::superfluid
