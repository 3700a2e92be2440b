#pragma once
// The superfluid helium-4 model of paper 3 (Kincl, Schmoranzer, Pavelka, Phys. Fluids 35 (2023)
// 047124): one particle with two velocities, the reversible part of eq. (19), bitwise reversible
// through two copies of (v, v_s, s) (state.hpp; README "The reversible step"):
//   drift(dt/2) [dissipate(dt/2)] copy_one(dt/2) copy_two(dt) copy_one(dt/2) [dissipate(dt/2)]
//   drift(dt/2)
// drift:    x += tau (v + v') / 2                      (mean of the two copies' velocities)
// copy_one: (v, v_s, s) += tau f(x, v', v_s', s')      (eq. 19 evaluated on copy 2)
// copy_two: (v', v_s', s') += tau f(x, v, v_s, s)      (eq. 19 evaluated on copy 1)
// Each is a shear (its increment does not depend on the group it changes), so each is undone by
// subtracting the same increment, and the palindrome is bitwise reversible under
// (v, v_s, v', v_s') -> -(...). dissipate (viscosity, heat conduction: dissipation_terms.hpp)
// is the irreversible part, placed by the core (step.splitting; the brackets: "strang", at the
// sites the palindrome marks) and left out without it; it gives both copies the same increments.

#include "core/model_api.hpp"
#include "models/superfluid/pair_terms.hpp"
#include "models/superfluid/parameters.hpp"
#include "models/superfluid/state.hpp"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace revsph::superfluid {

template <int D, class Arith>
class Model : public ModelParts<Parameters<D>, State<D, typename Arith::Raw>> {
  using Parts = ModelParts<Parameters<D>, State<D, typename Arith::Raw>>;
  using Parts::info_;
  using Parts::parameters_;
  using Parts::state_;

public:
  using Raw = typename Arith::Raw;

  Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state);

  // Eq. (24): C_a = rho0 - sum_b m_b w_ab for every fluid then dummy particle (rho(0) = rho0).
  void initialise_density_constants();

  static std::span<const Substep<Model>> palindrome();
  // Viscosity and heat conduction, placed by step.splitting (strang: after the half drifts).
  static std::span<const IrreversibleOperator<Model>> irreversible_operators();

  // Eq. (15) summed over the fluid, on the mean of the two copies.
  EnergyBudget energy();
  void derived_views(const ViewSink& sink);
  // The largest differences between the copies and the total entropies sum m s of each copy;
  // with the second-sound wave of eq. (26), its error against eq. (25) at `time` (RMS over the
  // particles of (s - s_exact) / (A s0): eq. 27 before its maximum over time) and the mean
  // entropy of the particle nearest to (L/4, L/4) with eq. (25) there (Fig. 6).
  std::vector<EnergyTerm> diagnostics(double time);
  // The wall exchange and the heater's input so far, carried by snapshots into restarted runs
  // (core/simulation.hpp, HasEnergyAccounts).
  static auto energy_accounts() {
    return std::array{EnergyAccount<Model>{"wall_exchange", &Model::exchanged_energy_},
                      EnergyAccount<Model>{"heater_input", &Model::heater_energy_}};
  }
  void invalidate_derived() {
    density_valid_ = false;
    constants_valid_ = false;
  }

  void drift(double dt);
  // Viscosity and heat conduction over dt from the mean of the copies (irreversible): the same
  // velocity and entropy increments to both copies, the heat turned into entropy so that the
  // energy (15) is kept.
  void dissipate(double dt);
  // The fountain's sources, after every step (outside the palindrome; irreversible): the
  // superleak's exact relaxation of v_n, its energy kept as heat; the heater's power as heat.
  static std::span<const StepHook<Model>> step_hooks();
  void relax_superleak(std::int64_t step);
  void heat(std::int64_t step);
  // Adds dt * f(copy `from`) to copy `to` (0: the fields without suffix, 1: the *_copy ones).
  void update_copy(int to, double dt);

private:
  void update_copy_one(double dt) { update_copy(0, dt); }
  void update_copy_two(double dt) { update_copy(1, dt); }
  static std::string dissipation_acts(const Model& model);
  static std::string superleak_acts(const Model& model);
  static std::string heater_acts(const Model& model);
  // Adds the same entropy increment ds (rounded up to the scale) to both copies of particle i;
  // false on overflow.
  bool add_entropy(std::size_t i, double ds);
  // Which side of the superleak's mid-plane each slot lies on (+1, -1; 0 outside its width).
  void fill_superleak_sides();

  struct Copy {
    StateField<Raw>* velocity;
    StateField<Raw>* superflow_velocity;
    StateField<Raw>* entropy;
    StateField<Raw>* wall_superflow_velocity;
  };
  Copy copy(int which);
  std::size_t fluid_count() const { return state_.fluid.position.count(); }
  CarrierField<Arith> carrier_position() const {
    return {&state_.fluid.position, &state_.dummy.position, &state_.wall.position};
  }
  void update_constants();
  void update_density();
  // Entropy increment that adds `heat` to a particle's energy (15) at fixed v, v_s, rho.
  double entropy_for_heat(double s, double relative_squared, double mass, double heat) const;
  // The rate inputs from copy `from` (or the mean of both, from = -1) at the current positions.
  void fill_rate_inputs(int from);
  void sum_increments(int from, double tau);
  // Absorbing walls: the energy (15) their pair terms gave the fluid in the increments just
  // summed (to first order in tau), added to exchanged_energy_ at the weight the mean of the
  // copies receives.
  void count_wall_work(double tau);
  // The mean of the copies, per fluid particle in canonical order.
  struct MeanState {
    std::array<std::vector<double>, D> velocity, superflow_velocity;
    std::vector<double> entropy;
  };
  MeanState mean_state() const;

  WendlandQuintic<D> kernel_;

  bool constants_valid_ = false;
  std::vector<double> mass_;
  std::vector<Raw> density_constant_;
  bool density_valid_ = false;
  // sum_b w(x_a - x_b) over a full square lattice of spacing dr (b = a included): a unit-mass
  // particle's kernel sum inside the liquid at the start.
  double lattice_kernel_sum_ = 0.0;
  SlotLayout<D> layout_;
  // The slots that interact as fluid: the fluid's, and the absorbing walls' (pair_terms.hpp).
  SlotInSet interacting() const {
    return parameters_.absorbing_walls ? layout_.in(state_.fluid, state_.wall)
                                       : layout_.in(state_.fluid);
  }
  std::vector<double> slot_mass_;
  std::vector<Raw> slot_density_constant_;
  // Energy the walls gave the fluid in dissipation sub-steps since the run began (lid work, heat
  // from or to a cooler): the energy budget's wall_exchange term is minus this.
  RunTotal exchanged_energy_;
  RunTotal heater_energy_; // the heater's input since the run began
  std::vector<std::int8_t> slot_side_;
  PairSums<Arith, 1> density_sums_;
  HalfPairList fluid_pairs_; // the layout's pairs with a fluid particle on one side at least
  HalfPairList wall_pairs_;  // fluid-wall pairs, with absorbing walls only
  RateInputs<D> inputs_;
  PairSums<Arith, 2 * D + 1> increment_sums_; // at the scales of v, v_s and s
  PairSums<Arith, D + 1> dissipation_sums_;   // velocity increments and heat
  PairSums<Arith, 1> wall_work_sums_;         // energy absorbing walls give each fluid particle
  // Whether the case has walls, from the whole state at setup (in a distributed run a process's
  // own share may hold none: what the passes do must not depend on it).
  bool has_walls_;
};

extern template class Model<2, FixedArithmetic>;
extern template class Model<3, FixedArithmetic>;
extern template class Model<2, FloatArithmetic>;
extern template class Model<3, FloatArithmetic>;

} // namespace revsph::superfluid
