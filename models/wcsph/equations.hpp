#pragma once
// Pointwise physics of symplectic WCSPH (Kincl & Pavelka, Comput. Phys. Commun. 284 (2023)
// 108593, "paper 1"). Pure functions of doubles; the neighbour loops are in forces.hpp.

#include <cmath>

namespace revsph::wcsph {

// Tait equation of state, paper 1 eq. (2): p = c^2 rho0 / 7 [(rho / rho0)^7 - 1].
// The seventh power is written as multiplications (std::pow is not exact; design note §6).
inline double tait_pressure(double density, double rest_density, double sound_speed) {
  const double ratio = density / rest_density;
  const double ratio3 = ratio * ratio * ratio;
  return sound_speed * sound_speed * rest_density / 7.0 * (ratio3 * ratio3 * ratio - 1.0);
}

// The inverse of eq. (2): the density at which the Tait pressure is p. Used only to set up
// initial states (std::pow is fine outside the time step).
inline double tait_density(double pressure, double rest_density, double sound_speed) {
  return rest_density *
         std::pow(1.0 + 7.0 * pressure / (sound_speed * sound_speed * rest_density), 1.0 / 7.0);
}

// Compressional energy per unit mass, paper 1 below eq. (3):
//   eps = c^2 / 42 [(rho / rho0)^6 + 6 rho0 / rho],  d eps / d rho = p / rho^2.
// (The paper prints d eps = p / rho d rho; p / rho^2 is what makes eq. (3) conserved.)
inline double compressional_energy_per_mass(double density, double rest_density,
                                            double sound_speed) {
  const double ratio = density / rest_density;
  const double ratio3 = ratio * ratio * ratio;
  return sound_speed * sound_speed / 42.0 * (ratio3 * ratio3 + 6.0 / ratio);
}

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

} // namespace revsph::wcsph
