#pragma once
// Parameters of a superfluid case (paper 3), read from its case file. Every key read is declared
// in case_keys() (revsph cases --keys superfluid, docs/case-keys.md).

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/geometry.hpp"
#include "core/particle_discretisation.hpp"
#include "core/step_splitting.hpp"
#include "fixedpoint/scale.hpp"
#include "models/superfluid/helium.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace revsph::superfluid {

// Initial fields beyond rest at s0: the second-sound standing wave of eq. (26) and seeded random
// perturbations (uniform in [-amplitude, amplitude], every component of every particle).
struct InitialFields {
  double wave_amplitude = 0.0; // A of eq. (26)
  double wave_length = 0.0;    // L of eq. (26): s0 A sin(pi x / L) sin(pi y / L) [sin(pi z / L)]
  // Eq. (26) as printed (sine), or the mode of the adiabatic square, cos(pi x / L) cos(pi y / L)
  // (README: with free adiabatic edges eq. 25 is not a solution; the cosine mode is).
  bool wave_cosine = false;
  std::vector<double> uniform_velocity;    // v everywhere (the random part adds to it); empty: 0
  std::vector<double> uniform_counterflow; // v - v_s everywhere; empty: 0
  // With gravity: the height of the free surface, below which the initial density is hydrostatic,
  // rho = rho0 (1 + g (H - y) / u1^2) (p = rho0 g (H - y) by eq. 12); NaN: rho0 everywhere.
  double hydrostatic_surface = std::numeric_limits<double>::quiet_NaN();
  double random_velocity = 0.0;    // m/s, on v
  double random_counterflow = 0.0; // m/s, on v - v_s
  double random_entropy = 0.0;     // relative, on s / s0
  std::uint64_t seed = 1;
};

// The fountain's superleak (sec. III.C, eq. 30): a slab |x_k - c_k| <= half_width (k < D-1),
// |y - c_y| <= half_thickness in which the normal velocity relaxes at `rate` (the paper's 1 / tau
// times its mollifier; applied exactly, v_n -> v_n exp(-rate dt)), and across whose mid-plane no
// heat is conducted.
template <int D>
struct Superleak {
  double rate = 0.0; // 1/s; 0: no superleak
  Vec<D> centre{};
  double half_width = 0.0;
  double half_thickness = 0.0;
};

// The heater (eq. 30): power (W/m in 2D, W in 3D) spread by a Wendland kernel of the given
// support about the centre, ramped up linearly over ramp_time.
template <int D>
struct Heater {
  double power = 0.0; // 0: no heater
  Vec<D> centre{};
  double support = 0.0;
  double ramp_time = 0.0;
};

template <int D>
struct Parameters : ParticleDiscretisation { // dr, support_radius, dt, cell_size_factor
  Helium helium;
  double gravity = 0.0;                  // g (m/s^2) along minus the last axis (eq. 29)
  double gravity_reference_height = 0.0; // height of zero gravitational energy (m)
  // Where viscosity and heat conduction go (step.splitting, core/step_splitting.hpp).
  Splitting splitting = Splitting::strang;
  double viscosity = 0.0;         // mu of the normal fluid (eq. 19), >= 0
  double heat_conductivity = 0.0; // beta (eq. 5), >= 0
  bool dummy_no_slip = false;     // viscosity against the dummies (physics.dummy_slip)
  bool absorbing_walls = false;   // physics.cooler = "absorbing"
  // [discretisation]
  InitialFields initial;
  // The fountain's jet (sec. III.C): the diagnostics report the fluid volume above this height
  // (NaN: not reported); its growth rate over the capillary's width is the jet speed.
  double jet_height = std::numeric_limits<double>::quiet_NaN();
  Superleak<D> superleak;
  Heater<D> heater;
  Box<D> domain;
  // [fixed_point]
  fixedpoint::Scale position_scale;
  fixedpoint::Scale velocity_scale; // v and v_s
  fixedpoint::Scale entropy_scale;  // s
  fixedpoint::Scale density_scale;  // density sums and C_a
  fixedpoint::Scale heat_scale;     // sums of the heat a particle receives in a sub-step
};

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file);

const KeyTable& case_keys();

} // namespace revsph::superfluid
