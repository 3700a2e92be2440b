#pragma once
// A wall made of fixed particles that repel moving ones with a conservative, Lennard-Jones-like
// force (paper 1 §3.3, eq. 7); used by every model whose walls are wall particles.

#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace revsph {

// The conservative Lennard-Jones-like wall, paper 1 §3.3 eq. (7):
//   s = (r_wall^2 + eps^2) / (r^2 + eps^2) for r < r_wall, else 1;
//   energy of a pair E_wall (s^2 / 4 - s / 2 + 1 / 4) = E_wall (s - 1)^2 / 4;
//   force on the fluid particle b from wall particle a:
//   F = -dH/dx_b = E_wall (s^2 - s) / (r^2 + eps^2) (x_b - x_a).
// E_wall is proportional to the particle mass (Table 1: E_wall = 10 m g l_wch), so both are
// written per unit mass of the fluid particle: energy_per_mass = E_wall / m.
struct WallPotential {
  double radius_squared_plus_epsilon_squared; // r_wall^2 + eps^2
  double epsilon_squared;
  double energy_per_mass;

  double s(double r_squared) const {
    const double value = radius_squared_plus_epsilon_squared / (r_squared + epsilon_squared);
    return value > 1.0 ? value : 1.0;
  }
  // Acceleration of the fluid particle divided by (x_fluid - x_wall).
  double acceleration_over_distance(double r_squared) const {
    const double s_value = s(r_squared);
    return energy_per_mass * (s_value * s_value - s_value) / (r_squared + epsilon_squared);
  }
  double energy_per_fluid_mass(double r_squared) const {
    const double excess = s(r_squared) - 1.0;
    return 0.25 * energy_per_mass * excess * excess;
  }
};

// Eq. (7): the wall energy of each moving particle, E_wall (s - 1)^2 / 4 per wall particle within
// reach, as the one-sided pair term of a sum over wall particles (core/fixed_targets.hpp; a
// diagnostic, summed in doubles in ascending wall order). `receiving` is the set the walls act
// on (SlotLayout::in).
template <int D>
struct WallEnergyTerm {
  static constexpr int width = 1;
  std::span<const double> mass;
  SlotInSet receiving;
  WallPotential wall;

  bool receives(std::uint32_t s) const { return receiving(s); }
  void cross_pair(const PairGeometry<D>& p, std::array<double, 1>& to_a) const {
    to_a[0] = mass[p.a] * wall.energy_per_fluid_mass(p.r_squared);
  }
};

} // namespace revsph
