#pragma once
// Parameters of a two-fluid case (paper 5), read from its case file. Every key read is declared
// in case_keys() (revsph cases --keys two_fluid, docs/case-keys.md). Paper 5 leaves most numbers
// out: each case file gives its values with their sources (README, "Parameters").

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/geometry.hpp"
#include "core/particle_discretisation.hpp"
#include "core/step_splitting.hpp"
#include "fixedpoint/deterministic_math.hpp"
#include "fixedpoint/scale.hpp"
#include "models/two_fluid/helium_ii.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace revsph::two_fluid {

// The pressure force: eqs. (37-38) (Hu & Adams), eq. (26) (standard), or the gradient of the
// internal energy (variational; README).
enum class PressureForm { hu_adams, standard, variational };

// The thermomechanical force (27-28): sigma = entropy_scale * S(T) / reference_density, S of
// eq. (21) with the first sound speed; normal particles take it times -rho_s / rho_n.
struct Thermomechanical {
  double entropy_scale = 0.0;     // C_e of eq. (41); 0: no thermomechanical force
  double first_sound_speed = 0.0; // c of eq. (21), m/s
  double reference_density = 0.0; // turns S (per volume) into sigma (per mass), kg/m^3
  // Eq. (27)'s symmetric form, or sigma_a sum_b V_b (T_b - T_a) grad W (zero for a uniform T).
  bool difference_form = false;
};

// A curved interface (sec. V.1): the particles of superfluid and normal blocks are superfluid
// above y = height - amplitude sin(2 pi x / wavelength) and normal below it.
struct Interface {
  bool given = false;
  double height = 0.0;
  double amplitude = 0.0;
  double wavelength = 0.0;
  // false: kinds split by the curve on the unmoved lattice; true: split at y = height, then every
  // fluid particle moved by the linear mode's displacement (displacement()).
  bool displaced = false;

  bool superfluid_at(double x, double y) const {
    return y > (displaced
                    ? height
                    : height - amplitude * dmath::sin(2.0 * std::numbers::pi * x / wavelength));
  }
  // The incompressible displacement (x, y) of the interface's linear mode at a point of the flat
  // state: the interface y = height moves to height - amplitude sin(k x), and the displacement
  // decays as e^(-k |y - height|) on both sides (div = 0 on each; it slips along the interface).
  std::array<double, 2> displacement(double x, double y) const {
    const double k = 2.0 * std::numbers::pi / wavelength;
    const double decay = amplitude * dmath::exp(-k * std::abs(y - height));
    return {(y > height ? 1.0 : -1.0) * decay * dmath::cos(k * x), -decay * dmath::sin(k * x)};
  }
};

// Sec. IV.1's stabilising pair terms for r < d (dissipation_terms.hpp, ContactInputs).
struct Contact {
  bool collision = false;
  double restitution = 0.2; // e: not given by the paper (README)
  bool riemann = false;
  double limiter = 3.0; // eta of Zhang, Hu & Adams (2017)
  bool any() const { return collision || riemann; }
};

// Wall blocks with `wall_motion = "rigid"` (README, "Wall grip"): per wall particle, in the wall
// set's order, the rate |Omega| of its block (0: frozen, the default) and the block's centre. The
// drift turns such a particle's position and velocity about the centre by dt Omega.
struct RigidWalls {
  std::vector<double> rate;                  // 1/s, >= 0; the sense is the velocity's (odd)
  std::vector<std::array<double, 2>> centre; // m (2D only)
  bool any() const {
    return std::any_of(rate.begin(), rate.end(), [](double r) { return r > 0.0; });
  }
};

template <int D>
struct Parameters : ParticleDiscretisation { // dr, support_radius, dt, cell_size_factor
  double superfluid_density = 0.0; // rho_s: the superfluid particles' Tait reference and mass
  double normal_density = 0.0;     // rho_n: the normal (and wall) particles'
  // physics.phases = "interpenetrating": every particle, walls included, carries the mixture's
  // density rho_s + rho_n, and the phases' partial densities come from the particle counts
  // (README, "Interpenetrating phases"); "separate" (the default): a particle carries its kind's.
  bool interpenetrating = false;
  double sound_speed = 0.0; // c of the Tait equation (numerical, not given by the paper)
  double tait_exponent = 7.0;
  double background_pressure = 0.0; // added to every Tait pressure (Pa)
  double temperature = 0.0;         // T0: every particle's temperature (sec. IV.4), K
  double gravity = 0.0;             // g along minus the last axis, m/s^2
  double gravity_reference_height = 0.0;
  // Where viscosity, friction and contacts go (step.splitting, core/step_splitting.hpp).
  Splitting splitting = Splitting::strang;
  PressureForm pressure_form = PressureForm::hu_adams;
  Thermomechanical thermomechanical;
  double rotational_viscosity = 0.0; // eta_r of eq. (39): the spin term 2 eta_r curl omega (40)
  double spin = 0.0;                 // omega of every fluid particle, C_omega v_max / (0.5 dr)
  // Irreversible terms.
  double normal_viscosity = 0.0;  // eta_bar = eta_n of eqs. (34, 39), Pa s
  bool central_viscosity = false; // physics.viscosity_form = "central" (README)
  // physics.separate_phase_viscosity = "undiluted": with separate phases the normal-normal pairs'
  // viscous coefficient is multiplied by N / N_n (README, "Wall grip"), so that the normal
  // particles of a random mixture diffuse momentum at nu = (eta_bar + eta_r) / rho_n.
  bool undiluted_viscosity = false;
  MutualFriction mutual_friction;
  Contact contact;
  Interface interface;
  RigidWalls rigid_walls;         // filled by the setup from the wall blocks
  double random_velocity = 0.0;   // each velocity component uniform in [-value, value] at start
  bool hydrostatic_start = false; // masses of the hydrostatic column (hydrostatic_start.hpp)
  std::uint64_t seed = 1;
  // [discretisation]
  Box<D> domain;
  // [fixed_point]
  fixedpoint::Scale position_scale;
  fixedpoint::Scale momentum_scale;
  fixedpoint::Scale density_scale; // the number-density sums (sum W, 1/m^D)
  fixedpoint::Scale energy_scale;  // the dissipation's energy accounts, summed over pairs

  // The Tait reference density, and the particle mass over its lattice volume, of a kind.
  double rest_density(bool superfluid) const {
    if (interpenetrating) {
      return superfluid_density + normal_density;
    }
    return superfluid ? superfluid_density : normal_density;
  }
};

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file);

const KeyTable& case_keys();

} // namespace revsph::two_fluid
