#pragma once
// The state of an entropic SPH simulation (paper 4: Pavelka, Klika, Kincl 2024), declared once
// (core/particle_sets.hpp). Fixed point only: the kick adds exact pair impulses to the momenta.
//
// What is integrated is what the paper's symplectic form integrates (§2.4, §4.1-4.5): positions
// and momenta. Density, entropy density and volume are recomputed from the positions every step.
// The particle entropy S is even under time reversal and constant in the reversible part; only
// dissipation changes it (§5).

#include "core/common_fields.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"
#include "core/units.hpp"

#include <cstdint>
#include <tuple>

namespace revsph::entropic {

using Field = StateField<std::int64_t>;

// The gas: positions and momenta M = m v evolve (eq. 11); the particle entropy S (extensive, eq.
// 21) and the mass are constants of the reversible motion, except that the hyperbolic heat
// conduction (§5.5) exchanges S with the entropy-flux variable w (odd, eq. 66b; zero and
// untouched without it).
template <int D>
struct Gas {
  static constexpr SetInfo set{.name = "gas", .motion = Motion::moving};
  Field position{position_field<D>()};
  Field momentum{
      {.name = "momentum", .unit = momentum_unit<D>, .parity = Parity::odd, .components = D}};
  Field entropy{{.name = "entropy", .unit = entropy_unit<D>}};
  Field mass{mass_field<D>()};
  // w: its energy c_w V |w|^2 (Fig. 13) makes its unit the square root of a pressure.
  Field entropy_flux{
      {.name = "entropy_flux", .unit = "Pa^(1/2)", .parity = Parity::odd, .components = D}};
  auto fields() { return std::tie(position, momentum, entropy, mass, entropy_flux); }
};

// Wall particles of the conservative wall (paper 1 §3.3, eq. 7): fixed, only their positions.
template <int D>
struct Wall {
  static constexpr SetInfo set{.name = "wall", .motion = Motion::fixed};
  Field position{position_field<D>(false)};
  auto fields() { return std::tie(position); }
};

// Dummy particles (as paper 1 App. A): fixed, they take part in the kernel sums and the pair
// forces like gas particles (the paper's "dummy particles outside", §3.4), with their own mass
// and entropy, so that the sums near a wall are not cut. They do not move, and the dissipation
// leaves them out (adiabatic; free-slip unless physics.wall_slip = "no_slip").
template <int D>
struct Dummy {
  static constexpr SetInfo set{.name = "dummy", .motion = Motion::fixed};
  Field position{position_field<D>(false)};
  Field entropy{{.name = "entropy", .unit = entropy_unit<D>, .evolved = false}};
  Field mass{mass_field<D>()};
  auto fields() { return std::tie(position, entropy, mass); }
};

// Thermal wall particles (a heater or a cooler): dummy particles held at their own temperature
// that also conduct heat to and from the gas (§5.1 conduction with T_b fixed). Their entropy,
// the initial gas's, gives their pressure in the kernel sums, as for a dummy; the held
// temperature is what the conduction sees.
template <int D>
struct Thermal {
  static constexpr SetInfo set{.name = "thermal", .motion = Motion::fixed};
  Field position{position_field<D>(false)};
  Field entropy{{.name = "entropy", .unit = entropy_unit<D>, .evolved = false}};
  Field mass{mass_field<D>()};
  Field temperature{{.name = "temperature", .unit = "K", .evolved = false, .positive = true}};
  auto fields() { return std::tie(position, entropy, mass, temperature); }
};

template <int D>
struct State {
  Gas<D> gas;
  Wall<D> wall;
  Dummy<D> dummy;
  Thermal<D> thermal;

  State() { declare_state(*this); }
  auto sets() { return std::tie(gas, wall, dummy, thermal); }
};

} // namespace revsph::entropic
