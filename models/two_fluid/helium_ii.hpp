#pragma once
// Helium II as paper 5 (Tsuzuki 2021) describes it: the entropy of the phonon-roton model
// (eqs. 19-24, 41) and the decay of the vortex line density (eq. 9) behind the mutual friction
// (eq. 8). SI units throughout; the paper's constants are printed in CGS (README, "slips").

#include "fixedpoint/deterministic_math.hpp"

#include <cmath>
#include <numbers>

namespace revsph::two_fluid {

inline constexpr double boltzmann = 1.380649e-23;         // J/K
inline constexpr double reduced_planck = 1.054571817e-34; // J s
// Landau's roton parameters as the paper gives them (sec. II.4, its refs [33, 34]):
inline constexpr double roton_effective_mass = 1.72e-27; // mu: 1.72e-24 g
inline constexpr double roton_momentum = 2.1e-24;        // p0: 2.1e-19 g cm/s (printed g cm^-1)
inline constexpr double roton_gap = 8.9;                 // Delta / k_B in K

// Eq. (21): S = dP/dT of the phonon and roton pressures (19), an entropy per volume (J/(K m^3)),
// with c the first sound speed. As printed: its roton term is half of Landau's leading term
// k_B N_r Delta / T (N_r the roton density), and the 3/2 k_B N_r the paper drops is left out
// too (README).
inline double phonon_roton_entropy(double temperature, double first_sound_speed) {
  const double kt = boltzmann * temperature;
  const double phonon = 2.0 * std::numbers::pi * std::numbers::pi * boltzmann *
                        dmath::integer_power(kt / (reduced_planck * first_sound_speed), 3) / 45.0;
  const double roton = dmath::pow(boltzmann / (2.0 * std::numbers::pi), 1.5) *
                       std::sqrt(roton_effective_mass) * roton_momentum * roton_momentum *
                       roton_gap * dmath::exp(-roton_gap / temperature) /
                       (dmath::integer_power(reduced_planck, 3) * std::sqrt(temperature));
  return phonon + roton;
}

// The mutual friction's coefficient C_L = (2/3) rho_s alpha kappa L(t) of eqs. (8, 29), with
// Vinen's decay 1 / L(t) = 1 / L0 + beta_v t (eq. 9).
struct MutualFriction {
  double superfluid_density = 0.0;   // rho_s, kg/m^3
  double alpha = 0.0;                // the friction coefficient, 1
  double circulation_quantum = 0.0;  // kappa, m^2/s
  double initial_line_density = 0.0; // L0, 1/m^2
  double vinen_beta = 0.0;           // beta_v, m^2/s
  // mutual_friction.wall_line_density = "initial": against the wall particles the friction keeps
  // C_L(0) (L = L0) for the whole run, while the fluid-fluid friction follows Vinen's L(t)
  // (README, "Wall grip").
  bool wall_at_initial_line_density = false;

  bool active() const { return alpha > 0.0 && initial_line_density > 0.0; }
  double line_density(double time) const {
    return 1.0 / (1.0 / initial_line_density + vinen_beta * time);
  }
  // Per volume and per unit of relative velocity: F_sn = C_L v_sn (eq. 8), kg/(m^3 s).
  double coefficient(double time) const {
    return 2.0 / 3.0 * superfluid_density * alpha * circulation_quantum * line_density(time);
  }
  // C_L of a superfluid particle's pairs with the wall particles.
  double wall_coefficient(double time) const {
    return coefficient(wall_at_initial_line_density ? 0.0 : time);
  }
};

} // namespace revsph::two_fluid
