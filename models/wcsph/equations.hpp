#pragma once
// Pointwise physics of symplectic WCSPH (Kincl & Pavelka, Comput. Phys. Commun. 284 (2023)
// 108593, "paper 1"). Pure functions of doubles; the neighbour loops are in forces.hpp.

#include "core/wall_potential.hpp"
#include "fixedpoint/deterministic_math.hpp"
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
         dmath::pow(1.0 + 7.0 * pressure / (sound_speed * sound_speed * rest_density), 1.0 / 7.0);
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

// The conservative wall of eq. (7): core/wall_potential.hpp (shared with the entropic model).
using revsph::WallPotential;

} // namespace revsph::wcsph
