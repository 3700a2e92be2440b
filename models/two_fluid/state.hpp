#pragma once
// The state of a two-fluid simulation (paper 5), declared once (core/particle_sets.hpp): the
// superfluid and the normal particles move; the walls are frozen normal particles. A particle
// keeps its kind (sec. IV.4), so the kind is the particle set.

#include "core/common_fields.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"
#include "core/units.hpp"

#include <tuple>

namespace revsph::two_fluid {

// The spin omega of eq. (40): a rate about z in 2D, a vector in 3D.
template <int D>
inline constexpr int spin_components = D == 2 ? 1 : 3;

// A moving kind: position and momentum evolve; mass, temperature (kept at its initial value,
// sec. IV.4) and spin (only initialised by the paper: held fixed, and even under time reversal,
// README) are constants of the particle. Momentum, not velocity: the kinds' masses differ, and a
// pair impulse then changes p_a and p_b by the same rounded integer (total momentum exact).
template <int D, class Raw, const char* Name>
struct MovingKind {
  static constexpr SetInfo set{.name = Name, .motion = Motion::moving};
  StateField<Raw> position{position_field<D>()};
  StateField<Raw> momentum{{.name = "momentum",
                            .unit = D == 2 ? "kg/s" : "kg m/s",
                            .parity = Parity::odd,
                            .components = D}};
  StateField<Raw> mass{mass_field<D>()};
  StateField<Raw> temperature{{.name = "temperature", .unit = "K", .evolved = false}};
  StateField<Raw> spin{
      {.name = "spin", .unit = "1/s", .components = spin_components<D>, .evolved = false}};
  auto fields() { return std::tie(position, momentum, mass, temperature, spin); }
};

inline constexpr char superfluid_name[] = "superfluid";
inline constexpr char normal_name[] = "normal";

// Walls: frozen normal particles (several layers, sec. V.1), in the density and every pair
// force like a normal particle at the wall's temperature, with a velocity (a lid, a turning
// vessel) that only the irreversible terms see (no-slip). A block with wall_motion = "rigid"
// turns instead: the drift turns its positions and velocities exactly (rigid_walls.hpp), though
// the fields stay declared as not evolved (so the state, and every case's hash, is unchanged).
template <int D, class Raw>
struct Wall {
  static constexpr SetInfo set{.name = "wall", .motion = Motion::fixed};
  StateField<Raw> position{position_field<D>(false)};
  StateField<Raw> velocity{prescribed_velocity_field<D>()};
  StateField<Raw> mass{mass_field<D>()};
  StateField<Raw> temperature{{.name = "temperature", .unit = "K", .evolved = false}};
  StateField<Raw> spin{
      {.name = "spin", .unit = "1/s", .components = spin_components<D>, .evolved = false}};
  auto fields() { return std::tie(position, velocity, mass, temperature, spin); }
};

template <int D, class Raw>
struct State {
  MovingKind<D, Raw, superfluid_name> superfluid;
  MovingKind<D, Raw, normal_name> normal;
  Wall<D, Raw> wall;

  State() { declare_state(*this); }
  auto sets() { return std::tie(superfluid, normal, wall); }
};

} // namespace revsph::two_fluid
