#pragma once
// Parameters of an entropic SPH case (paper 4), read from its case file. Every key read is
// declared in case_keys() (revsph cases --keys entropic, docs/case-keys.md).

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/geometry.hpp"
#include "core/particle_discretisation.hpp"
#include "core/step_splitting.hpp"
#include "fixedpoint/scale.hpp"
#include "models/entropic/equation_of_state.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <variant>

namespace revsph::entropic {

using GasLaw = std::variant<IdealGas, StiffenedGas>;
// The names of physics.equation_of_state's values.
enum class GasLawName { ideal_gas, stiffened_gas };

// The particle volumes of §3.2 and §4 (eqs. 23-28).
enum class ParticleVolume { mass, entropic, direct, implicit, mixed };

// The discretisation of Fourier's heat conduction: the paper's two passes, q = lambda G(1/T) then
// its divergence (eqs. 54-56), or one pass over pairs (dissipation_terms.hpp), whose wider-stencil
// error at a wall held at a temperature is smaller (README).
enum class HeatConduction { two_pass, pairwise };

template <int D>
struct Parameters : ParticleDiscretisation { // dr, support_radius, dt, cell_size_factor
  // [physics]
  GasLaw gas_law = IdealGas{}; // App. C: ideal gas (88-89) or stiffened gas (90-92)
  ParticleVolume volume = ParticleVolume::mass;
  double gravity = 0.0;                  // g (m/s^2), along -axis D-1
  double gravity_reference_height = 0.0; // height of zero gravitational potential (m)
  // physics.buoyancy = "boussinesq": gravity acts as the body force m g (T - T0) / T0 upwards
  // instead of m g downwards (a diagnostic: buoyancy without the compressible gas's density
  // differences; no potential, so the energy budget does not close). "density": m g downwards.
  bool boussinesq = false;
  // Dissipation (§5.1-5.2): shear viscosity mu of eq. (60) and the Fourier conductivity
  // lambda(T) = lambda_F T^2 of eq. (51); 0: off.
  double viscosity = 0.0;
  double heat_conductivity = 0.0; // lambda_F
  HeatConduction conduction = HeatConduction::two_pass;
  // Where the dissipation and the flux relaxation go (step.splitting, core/step_splitting.hpp):
  // strang, half updates at the step's ends; midpoint, one update between two half drifts (both
  // kicks of a step boundary see the same state: one force pass and one update per step instead
  // of two of each, one more neighbour search); lie, one update after the step (the paper's
  // first-order explicit update, kept for comparison).
  Splitting splitting = Splitting::strang;
  // Whether the viscosity acts between the gas and the dummy and thermal particles (at rest):
  // no-slip walls. Otherwise the walls are free-slip.
  bool no_slip_walls = false;
  bool dissipative() const { return viscosity > 0.0 || heat_conductivity > 0.0; }
  // Particles held at their places (physics.particles_move = false): the kick and the drift do
  // nothing. The hyperbolic heat conduction of §5.5 is derived for particles at rest.
  bool particles_move = true;
  // [hyperbolic_heat] (§5.5): the energy c_w sum_a V_a |w_a|^2 of the entropy-flux variable
  // (Fig. 13: c_w = 0.05; 0: off) and the relaxation time tau of eq. (69) (infinite: none).
  double flux_energy_coefficient = 0.0;
  double relaxation_time = std::numeric_limits<double>::infinity();
  bool hyperbolic() const { return flux_energy_coefficient > 0.0; }
  bool relaxing() const { return hyperbolic() && std::isfinite(relaxation_time); }
  // [initial]: the gas at rest, uniform
  double initial_density = 0.0;  // rho (kg/m^3): the particle masses are rho dr^D
  double initial_pressure = 0.0; // p (Pa): with rho, the specific entropy S / m of every particle
  // dT/dx (K/m): T = T0 + gradient . (x - centre of the gas) at the initial density, T0 the
  // temperature of (density, pressure).
  std::array<double, D> initial_temperature_gradient{};
  // A (K): one convection roll's worth of temperature on top, A cos(pi xi_1) sin(pi xi_D) with
  // xi the position scaled to [0, 1] across the gas (a seed for Rayleigh-Benard convection).
  double initial_temperature_perturbation = 0.0;
  // The gas (and its dummy and thermal particles) in hydrostatic equilibrium under gravity,
  // density and pressure holding at the gas's centre height (the authors' RaBe.jl start).
  bool initial_hydrostatic = false;
  // [discretisation]
  // [wall]: the conservative wall of paper 1 eq. (7)
  WallSettings wall;
  Box<D> domain;
  // [fixed_point]
  fixedpoint::Scale position_scale;
  fixedpoint::Scale momentum_scale;     // momenta, and the pair impulses of the kick
  fixedpoint::Scale entropy_scale;      // particle entropies S
  fixedpoint::Scale density_scale;      // the density sums (sum m W)
  fixedpoint::Scale entropy_flux_scale; // w of the hyperbolic heat conduction

  WallPotential wall_potential() const { return wall.potential(); }
  double heat_capacity() const {
    return std::visit([](const auto& law) { return law.heat_capacity; }, gas_law);
  }
  // The sound speed of the initial state (m/s), the scale of the time step and of the momenta.
  double initial_sound_speed() const;
  // The specific entropy S / m of the initial state (J/(kg K)).
  double initial_specific_entropy() const;
  // T0 = T(initial density, initial specific entropy) (K).
  double initial_temperature() const;
  // The hydrostatic start (initial.hydrostatic) at height z above the gas's centre: density and
  // specific entropy, or nothing where no state of positive temperature and p + B exists.
  std::optional<std::pair<double, double>> hydrostatic_state(double z) const;
};

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file);

const KeyTable& case_keys();

} // namespace revsph::entropic
