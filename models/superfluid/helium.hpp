#pragma once
// The linearised helium-4 of paper 3 (Kincl, Schmoranzer, Pavelka 2023) sec. II.C: everything
// the model needs from the energy (15) per unit mass,
//   e = v^2 / 2 + (chi_s / chi_n) (v - v_s)^2 / 2 + u1^2 (ln(rho / rho0) + rho0 / rho - 1)
//       + T0 (s - s0) + T0 (s - s0)^2 / (2 C),
// with chi_n = chi_n0 + chi' (s - s0), chi_s = 1 - chi_n (eq. 8). Its derivatives (eq. 9):
//   p = rho^2 de/drho = u1^2 (rho - rho0)                                   (eq. 12)
//   T = de/ds = T0 (1 + (s - s0) / C) - chi' |v_ns|^2 / 2                   (derived, below)
// The flow part of T: d(chi_s / chi_n)/ds = -chi' / chi_n^2, so the counterflow term of (15)
// contributes -chi' (v - v_s)^2 / (2 chi_n^2) = -chi' |v_ns|^2 / 2. Eq. (13) is its value at rest;
// without the flow part the discrete equations (19) do not conserve energy (Appendix B, Prop. 1
// takes the test function T = de/ds; scheme_check.py measures both).

#include "fixedpoint/deterministic_math.hpp"

#include <cmath>

namespace revsph::superfluid {

struct Helium {
  double rest_density = 0.0;          // rho0 (kg/m^3)
  double first_sound_speed = 0.0;     // u1 (m/s)
  double reference_temperature = 0.0; // T0 (K)
  double reference_entropy = 0.0;     // s0 (J/(kg K))
  double normal_fraction = 0.0;       // chi_n0
  double normal_fraction_slope = 0.0; // chi' (kg K/J)
  double heat_capacity = 0.0;         // C (J/(kg K))

  // Eq. (8).
  double chi_n(double s) const {
    return normal_fraction + normal_fraction_slope * (s - reference_entropy);
  }
  // Eq. (12).
  double pressure(double rho) const {
    return first_sound_speed * first_sound_speed * (rho - rest_density);
  }
  // A boundary particle's (dummy or wall) pressure and energy: eq. (12) and the compressional
  // term of (15) where it is compressed, zero where it is not. A boundary particle's density
  // constant is that of a particle inside the liquid (Model::initialise_density_constants), so
  // a dry one is under-dense; with eq. (12) as it stands it would pull the liquid toward it (up
  // the capillary's dry walls). e stays continuous with de/drho = 0 at rho0, so the forces are
  // still the gradient of the energy.
  double boundary_pressure(double rho) const { return rho > rest_density ? pressure(rho) : 0.0; }
  double boundary_compressional_energy(double rho) const {
    return rho > rest_density ? compressional_energy(rho) : 0.0;
  }
  // de/ds of eq. (15); counterflow_squared = |v_ns|^2.
  double temperature(double s, double counterflow_squared) const {
    return reference_temperature * (1.0 + (s - reference_entropy) / heat_capacity) -
           0.5 * normal_fraction_slope * counterflow_squared;
  }
  // Eq. (14): the second sound speed of the linearised model.
  double second_sound_speed() const {
    const double n = normal_fraction;
    return std::sqrt((1.0 - n) * reference_temperature * reference_entropy * reference_entropy /
                     (n * heat_capacity));
  }
  // The terms of eq. (15) per unit mass.
  double compressional_energy(double rho) const {
    return first_sound_speed * first_sound_speed *
           (dmath::log(rho / rest_density) + rest_density / rho - 1.0);
  }
  double thermal_energy(double s) const {
    const double ds = s - reference_entropy;
    return reference_temperature * ds + reference_temperature / (2.0 * heat_capacity) * ds * ds;
  }
  // (chi_s / chi_n) |v - v_s|^2 / 2, with relative = v - v_s.
  double counterflow_energy(double s, double relative_squared) const {
    const double n = chi_n(s);
    return 0.5 * (1.0 - n) / n * relative_squared;
  }
};

} // namespace revsph::superfluid
