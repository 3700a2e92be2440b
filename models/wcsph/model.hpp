#pragma once
// Symplectic WCSPH in fixed point (FixPA) or floating point (FloPA), paper 1 §2–4 and App. A:
// velocity Verlet kick(dt/2) drift(dt) kick(dt/2), the acceleration a deterministic function of
// the positions (closed-form density eq. 5, Tait pressure eq. 2, pressure force eq. 1b, gravity,
// conservative wall eq. 7, dummy-particle walls and the anti-clump force of App. A). Two options
// are irreversible: the active Shepard filter of App. A (a step hook, step_hooks()) and Monaghan's
// artificial viscosity (an operator the core places by step.splitting, irreversible_operators();
// viscosity_term.hpp), whose energy is counted as dissipated.

#include "core/fixed_targets.hpp"
#include "core/model_api.hpp"
#include "models/wcsph/parameters.hpp"
#include "models/wcsph/state.hpp"
#include "models/wcsph/viscosity_term.hpp"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace revsph::wcsph {

template <int D, class Arith>
class Model : public ModelParts<Parameters<D>, State<D, typename Arith::Raw>> {
  using Parts = ModelParts<Parameters<D>, State<D, typename Arith::Raw>>;
  using Parts::info_;
  using Parts::parameters_;
  using Parts::state_;

public:
  using Raw = typename Arith::Raw;

  // `state` holds positions, velocities, masses, wall and dummy positions with their scales
  // set. The density constants are set by initialise_density_constants (eq. 5), or come with a
  // state restored from a snapshot.
  Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state);

  // Eq. (5): C_a = target_a - sum_b m_b w(r_ab) for every fluid particle then every dummy
  // particle, so that rho_a(0) = target_a (rho0 at rest; the Gresho pressure's density, say).
  void initialise_density_constants(std::span<const double> target_density);

  static std::span<const Substep<Model>> palindrome();
  // Monaghan's artificial viscosity over tau, where physics.artificial_viscosity > 0
  // (artificial_viscosity.cpp).
  static std::span<const IrreversibleOperator<Model>> irreversible_operators();

  // Kinetic, gravitational, compressional and wall energy; with the artificial viscosity on, the
  // kinetic energy it took ("dissipated"), so that the total stays constant.
  EnergyBudget energy();
  // The account, carried by snapshots into restarted runs (core/simulation.hpp).
  static auto energy_accounts() {
    return std::array{EnergyAccount<Model>{"dissipated", &Model::dissipated_}};
  }
  // Density, pressure, acceleration, each energy term per fluid particle (and the filtered
  // velocity with a Shepard filter); density and pressure of the dummy particles.
  void derived_views(const ViewSink& sink);
  // With the Gresho vortex: the error norm of eq. (11) at this instant, of the velocity and of
  // its Shepard-filtered field (the paper's "passive filter").
  std::vector<EnergyTerm> diagnostics();
  void invalidate_derived() {
    derived_valid_ = false;
    constants_valid_ = false;
  }
  // The active Shepard filter every shepard_every steps (App. A; irreversible where active).
  static std::span<const StepHook<Model>> step_hooks();
  void filter_velocity(std::int64_t step);

  // Sub-steps (paper 1 §4, steps 1–3).
  void kick(double dt);
  void drift(double dt);
  // The irreversible operator: v += tau dv/dt of the artificial viscosity (viscosity_term.hpp).
  void apply_artificial_viscosity(double tau);

  // Derived quantities at the current positions, fluid particles first, then dummies.
  std::vector<double> density();
  const std::array<std::vector<double>, D>& acceleration();

private:
  static std::string shepard_filter_acts(const Model& model);
  static std::string artificial_viscosity_acts(const Model& model);
  bool viscosity_on() const { return parameters_.artificial_viscosity > 0.0; }
  // The fluid's velocities by slot, zero in the dummies' slots (after update_derived).
  void gather_slot_velocity(std::array<std::vector<double>, D>& slot_velocity) const;
  enum class EnergyOf { kinetic, gravitational, compressional, wall, dummy_compressional };
  std::size_t fluid_count() const { return state_.fluid.position.count(); }
  double fluid_position(int axis, std::size_t a) const {
    return Arith::real(state_.fluid.position.at(axis, a), state_.fluid.position.info().scale);
  }
  // The density carriers' positions (fluid, then dummies).
  CarrierField<Arith> carrier_position() const {
    return {&state_.fluid.position, &state_.dummy.position};
  }
  void update_derived();
  void update_constants();
  // One set's masses and densities in its particle order, read from the slots (after
  // update_derived).
  template <ParticleSet Set>
  auto mass_of(const Set& set) const {
    return layout_.in_set_order(std::span<const double>(slot_mass_), set);
  }
  template <ParticleSet Set>
  auto density_of(const Set& set) const {
    return layout_.in_set_order(density_sums_.values(0), set);
  }
  // Per fluid particle (per dummy for dummy_compressional).
  std::vector<double> particle_energy(EnergyOf what);
  double fluid_velocity(int axis, std::size_t a) const;
  std::array<std::vector<double>, D> real_velocity() const;
  std::array<std::vector<double>, D> filtered_velocity();

  WendlandQuintic<D> kernel_;
  std::optional<WendlandQuintic<D>> anti_clump_kernel_;

  // The wall positions, converted once.
  bool constants_valid_ = false;
  // Derived from the state, recomputed after every drift. The pair loops run over the carriers
  // in cell order (slots, core/slot_layout.hpp); the state and everything the model reports stay
  // in the canonical particle order.
  bool derived_valid_ = false;
  SlotLayout<D> layout_;  // carriers: the fluid and dummy particles
  FixedTargets<D> walls_; // the wall particles of eq. (7)
  std::vector<double> slot_mass_;
  std::vector<Raw> slot_density_constant_;
  PairSums<Arith, 1> density_sums_;
  PairSums<Arith, D> acceleration_sums_;
  std::vector<double> pressure_over_density_squared_; // slots
  std::vector<double> inverse_density_squared_;       // slots, with the anti-clump force
  // For acceleration(), filled on demand.
  std::array<std::vector<double>, D> acceleration_; // fluid, canonical order
  // The artificial viscosity: its inputs by slot, its velocity increments, and the kinetic
  // energy it took since the run began (J, or J/m in 2D).
  std::array<std::vector<double>, D> slot_velocity_;
  PairSums<Arith, D> viscosity_sums_;
  RunTotal dissipated_;
};

extern template class Model<1, FixedArithmetic>;
extern template class Model<2, FixedArithmetic>;
extern template class Model<3, FixedArithmetic>;
extern template class Model<1, FloatArithmetic>;
extern template class Model<2, FloatArithmetic>;
extern template class Model<3, FloatArithmetic>;

} // namespace revsph::wcsph
