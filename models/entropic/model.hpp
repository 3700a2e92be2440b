#pragma once
// Entropic SPH (paper 4: Pavelka, Klika, Kincl 2024) in fixed point, the reversible part:
//   kick(dt/2)  M_a += sum_b round(dt/2 f_ab) + round(dt/2 (wall and gravity forces on a))
//   drift(dt)   x_a += round(dt M_a / m_a)
//   kick(dt/2)
// with f_ab = -Phi_ab W'_ab e_ab the pair force of the chosen particle volume (pair_terms.hpp).
// Each pair impulse is rounded once and added to a and, negated, to b: the total momentum of
// the gas changes only by what walls and gravity give, bit for bit. The kick depends on the
// positions and the (even) entropies only, so the palindrome is bitwise reversible (design note
// §2, §4). Density, entropy density and volume are recomputed from the positions every step
// (the paper's symplectic form, §2.4).

#include "core/fixed_targets.hpp"
#include "core/model_api.hpp"
#include "core/pair_system.hpp"
#include "fixedpoint/deterministic_math.hpp"
#include "models/entropic/parameters.hpp"
#include "models/entropic/state.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace revsph::entropic {

// The magnitude the wall-mirror sum sum_b W_ab T_b must cover (model.cpp): 4 times the hotter of
// the hottest thermal wall and the initial gas temperature, over dr^D. Setup checks it is finite.
template <int D>
double wall_temperature_sum_magnitude(double hottest_wall, double initial_gas_temperature,
                                      double dr) {
  return 4.0 * std::max(hottest_wall, initial_gas_temperature) * dmath::integer_power(dr, -D);
}

template <int D>
class Model : public ModelParts<Parameters<D>, State<D>> {
  using Parts = ModelParts<Parameters<D>, State<D>>;
  using Parts::info_;
  using Parts::parameters_;
  using Parts::state_;

public:
  // `state` holds positions, momenta, entropies, masses and wall positions with their scales.
  Model(Parameters<D> parameters, SimulationInfo info, State<D> state);

  static std::span<const Substep<Model>> palindrome();
  // The dissipation (§5.1-5.2) and the flux relaxation (eq. 69), placed by the case's
  // step.splitting (core/step_splitting.hpp).
  static std::span<const IrreversibleOperator<Model>> irreversible_operators();

  // Kinetic, internal (sum_a V_a eps(rho_a, s_a), eq. 20), wall (eq. 7 of paper 1) and
  // gravitational energy.
  EnergyBudget energy();
  // Density, entropy density, volume, pressure, temperature and velocity per gas particle.
  void derived_views(const ViewSink& sink);
  // Total momentum of the gas, per axis (exact in integers up to walls and gravity).
  std::vector<EnergyTerm> diagnostics();
  void invalidate_derived() {
    constants_valid_ = false;
    geometry_valid_ = false;
    layout_current_ = false;
  }

  void kick(double dt);
  void drift(double dt);
  // Heat conduction and viscosity over tau (§5.1-5.2): the viscous impulses change the momenta
  // (pair by pair, exactly antisymmetric), and each particle's entropy grows by the heat it
  // receives, conduction and the kinetic energy the viscosity removed, at fixed density: the
  // total energy is kept up to rounding. Irreversible.
  void dissipate(double tau);
  // The hyperbolic heat conduction (§5.5, hyperbolic_heat.cpp): the reversible exchange of
  // eq. (68) as two shears, w from (S, x) and S from (w, x), and the relaxation of eq. (69),
  // which turns the energy of w into heat (irreversible, energy kept up to rounding).
  void exchange_flux(double dt);
  void exchange_entropy(double dt);
  void relax_flux(double dt);

  // Per gas particle, canonical order, at the current positions (for tests and outputs).
  struct Thermodynamics {
    std::vector<double> density, entropy_density, volume, pressure, temperature, specific_energy;
  };
  Thermodynamics thermodynamics();

private:
  void kick_substep(double dt) {
    if (parameters_.particles_move) {
      kick(dt);
    }
  }
  void drift_substep(double dt) {
    if (parameters_.particles_move) {
      drift(dt);
    }
  }
  void flux_substep(double dt);
  void entropy_exchange_substep(double dt);
  // What the operators do in this case ("" where they do not act).
  static std::string relaxation_description(const Model& model);
  static std::string dissipation_description(const Model& model);
  // The gas's part of a per-carrier array.
  std::span<const double> of_gas(const std::vector<double>& by_carrier) const {
    return layout_.part_of(std::span<const double>(by_carrier), state_.gas);
  }
  // Each carrier's held temperature (a thermal wall's, own or ghost; 0 for the rest), for
  // Gathered (read while the layout builds, after it took the sets' new sizes).
  auto held_temperature() const {
    return [this](std::size_t carrier) {
      const SetParticle particle = layout_.particle_of(carrier);
      const auto& held = state_.thermal.temperature;
      return particle.set != layout_.index_of(state_.thermal)
                 ? 0.0
                 : fixedpoint::to_real(held.at(0, particle.index), held.info().scale);
    };
  }
  std::size_t gas_count() const { return state_.gas.position.count(); }
  void update_constants();
  // Layout, kernel sums, volumes and the per-slot thermodynamics of the current positions.
  void update_geometry();
  // Slot s's volume, densities, thermodynamic state and pair-force coefficients from its kernel
  // sums (the chosen particle volume, §3.2 and §4); false if they are not physical.
  bool update_slot(std::uint32_t s);
  // The implicit volume (eqs. 26, 43-45): the gas's V from W V = 1 (dummies at their lattice
  // volume), then every slot's thermodynamics, then y from W y = p, by conjugate gradients
  // (canonical order: the same bits for any cell size).
  void update_implicit_volume();
  // The exact impulse sums of a kick over dt (cached: the two half kicks around a step boundary
  // see the same positions).
  void update_impulses(double dt);

  WendlandQuintic<D> kernel_;

  bool constants_valid_ = false;
  std::vector<double> mass_;    // carriers (gas, then dummies), canonical order
  std::vector<double> entropy_; // carriers, canonical order
  bool geometry_valid_ = false;
  // The cells and pairs were built at the current positions: the dissipation and the entropy
  // exchange change entropies only, and then the layout stands (a rebuild from the same positions
  // gives the same layout, so the results do not depend on this shortcut).
  bool layout_current_ = false;
  SlotLayout<D> layout_; // carriers: the gas, the dummy and the thermal particles
  std::vector<double> slot_held_temperature_;
  FixedTargets<D> walls_;
  std::vector<double> slot_mass_, slot_entropy_;
  PairSums<FixedArithmetic, 1> density_sums_; // sum_b m_b W_ab (eq. 32a): the mass volume
  PairSums<FixedArithmetic, 3> kernel_sums_;  // sum m W, sum S W, sum W: the other volumes
  // Per slot: density, entropy density, volume, the thermodynamic state, and the coefficients
  // of the volume's pair force Phi_ab = alpha_a beta_b + alpha_b beta_a (+ gamma_a delta_b +
  // gamma_b delta_a for the mixed volume), pair_terms.hpp.
  std::vector<double> density_, entropy_density_, volume_, pressure_, temperature_,
      specific_energy_;
  std::vector<double> alpha_, beta_, gamma_, delta_;
  // Scratch of the dissipation.
  CoordinateArrays<D> slot_velocity_, slot_heat_flux_;
  PairSums<FixedArithmetic, D> heat_flux_sums_;
  PairSums<FixedArithmetic, D + 1> dissipation_sums_;
  std::vector<double> conduction_temperature_; // by slot: T of the gas, mirrored T of the walls
  // The scales of the wall mirror sums.
  static std::array<SummedQuantity, D + 2> wall_mirror_quantities(const Parameters<D>& parameters,
                                                                  const State<D>& state);
  PairSums<FixedArithmetic, D + 2> wall_mirror_sums_; // sum W T, sum W v, sum W from the gas
  // The heat the thermal walls took in since the run (or restart) began, in total, as the entropy
  // they gained (sum Q / T_w), and split into what walls hotter than the initial gas gave out and
  // colder ones took in (for Nusselt numbers).
  RunTotal wall_heat_, wall_entropy_, hot_wall_heat_out_, cold_wall_heat_in_;
  PairSystem implicit_system_; // implicit volume: W_ab over all carriers, the gas's rows solved
  std::vector<double> implicit_volume_;   // carriers
  std::vector<double> implicit_pressure_; // the gas
  std::vector<double> implicit_y_;        // carriers: the gas's entries solved, the rest 0
  // The hyperbolic heat conduction: w per slot, the w and S exchanges of a sub-step.
  CoordinateArrays<D> slot_flux_;
  PairSums<FixedArithmetic, D> flux_sums_;
  PairSums<FixedArithmetic, 1> entropy_exchange_sums_;
  double impulse_dt_ = 0.0;
  bool impulses_valid_ = false;
  PairSums<FixedArithmetic, D> impulse_sums_;
  // Whether the case has thermal walls, from the whole state at setup (in a distributed run a
  // process's own share may hold none: what the passes do must not depend on it).
  bool has_thermal_walls_;
};

extern template class Model<1>;
extern template class Model<2>;
extern template class Model<3>;

} // namespace revsph::entropic
