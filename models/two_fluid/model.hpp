#pragma once
// Tsuzuki's two-fluid helium II (paper 5): superfluid and normal particles with a position-only
// conservative core (number density 36, Tait pressure in three forms, thermomechanical force 27,
// spin term 40, gravity) integrated by velocity Verlet in momentum form, bitwise reversible in
// fixed point: kick(dt/2) drift(dt) kick(dt/2). The irreversible part (viscosity 34/39, mutual
// friction 29/35: dissipation_terms.hpp) is an operator the core places by step.splitting (by
// default half updates at both ends of the palindrome); the energy it takes is counted (energy
// accounts).

#include "core/model_api.hpp"
#include "models/two_fluid/dissipation_terms.hpp"
#include "models/two_fluid/pair_terms.hpp"
#include "models/two_fluid/parameters.hpp"
#include "models/two_fluid/state.hpp"

#include <array>
#include <span>
#include <vector>

namespace revsph::two_fluid {

template <int D, class Arith>
class Model : public ModelParts<Parameters<D>, State<D, typename Arith::Raw>> {
  using Parts = ModelParts<Parameters<D>, State<D, typename Arith::Raw>>;
  using Parts::info_;
  using Parts::parameters_;
  using Parts::state_;

public:
  using Raw = typename Arith::Raw;

  Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state);

  static std::span<const Substep<Model>> palindrome();
  static std::span<const IrreversibleOperator<Model>> irreversible_operators();

  // Kinetic sum |p|^2 / 2m, internal sum m e(rho) over every particle (walls included: their
  // density moves with the fluid), gravitational sum m g (y - y_ref); then the accounts, so that
  // the total stays constant: + dissipated, - the walls' work, - the work of the
  // thermomechanical and spin forces (no gradient of this energy).
  EnergyBudget energy();
  // The accounts, carried by snapshots into restarted runs (core/simulation.hpp).
  static auto energy_accounts() {
    return std::array{EnergyAccount<Model>{"dissipated", &Model::dissipated_},
                      EnergyAccount<Model>{"wall_work", &Model::wall_work_},
                      EnergyAccount<Model>{"force_work", &Model::force_work_}};
  }
  void set_time(double time) { time_ = time; }
  // Density, pressure and velocity per particle; with the spin term on (eq. 40), its force.
  void derived_views(const ViewSink& sink);
  void invalidate_derived() {
    density_valid_ = false;
    impulses_valid_ = false;
    constants_valid_ = false;
  }

  void kick(double dt);
  void drift(double dt);
  // Viscosity and mutual friction over tau (irreversible; dissipation.cpp).
  void dissipate(double tau);

private:
  static std::string dissipation_acts(const Model& model);
  // The dissipate sub-step's pair term over tau with these couplings (contacts: the collision
  // and Riemann terms as the case sets them, else off), the velocities gathered by slot.
  DissipationTerm<D> dissipation_term(double tau, double friction, double wall_friction,
                                      bool contacts);
  void spin_force_views(const ViewSink& sink);
  void viscosity_views(const ViewSink& sink);
  // A D-component view `name` of each moving set, component k of its particle i being
  // value(kind, k, i, slot, mass) (model_outputs.cpp).
  template <class Value>
  void moving_vector_views(const ViewSink& sink, const char* name, const char* unit,
                           const Value& value);
  // The thermomechanical or the spin force is on: the kick counts their work.
  bool counts_force_work() const {
    return parameters_.thermomechanical.entropy_scale > 0.0 || spin_on();
  }
  bool spin_on() const {
    return D == 2 && parameters_.rotational_viscosity > 0.0 && parameters_.spin != 0.0;
  }
  double viscosity() const {
    const Parameters<D>& p = parameters_;
    return p.normal_viscosity > 0.0 ? p.normal_viscosity + p.rotational_viscosity : 0.0;
  }
  // The factor on the normal-normal pairs' viscous coefficient (README, "Wall grip"). With
  // separate phases a random mixture's normal particles are a share phi = N_n / N of all, so the
  // Laplacian sum of eq. (34) over a normal particle's normal neighbours samples phi of its
  // volume: per normal mass rho_n V it gives phi nu_n lap v. Undiluted, those pairs' K is
  // multiplied by N / N_n = 1 / phi; the normal-wall pairs keep theirs, as the wall region is
  // wholly normal (its sum is not diluted). This is what the interpenetrating phases' volumes
  // V rho / rho_n (ratio rho / rho_n = 1 / phi by the draw) do per normal mass rho V: normal
  // pairs (1 / phi)^2 V_a V_b / (rho V) = (1 / phi) V_b / (rho_n V), wall pairs 1 / (rho_n V).
  // Still one K per pair: momentum exact, and the accounts count the applied impulses.
  double normal_pair_factor() const {
    const std::size_t normal = state_.normal.position.count();
    if (!parameters_.undiluted_viscosity || normal == 0) {
      return 1.0;
    }
    return static_cast<double>(state_.superfluid.position.count() + normal) /
           static_cast<double>(normal);
  }
  CarrierField<Arith> carrier_position() const {
    return {&state_.superfluid.position, &state_.normal.position, &state_.wall.position};
  }
  // f(kind, set) for the superfluid and the normal particles (different types).
  template <class F>
  void for_each_moving(F&& f) {
    f(state_.superfluid, layout_.index_of(state_.superfluid));
    f(state_.normal, layout_.index_of(state_.normal));
  }
  // V_k / V of a particle kind: with interpenetrating phases rho / rho_k for the fluid, whose
  // particles each carry rho = rho_s + rho_n and make up the phase k at the share rho_k / rho of
  // them; 1 for walls and with separate phases.
  double phase_factor_of(bool superfluid, bool wall) const {
    const Parameters<D>& p = parameters_;
    if (!p.interpenetrating || wall) {
      return 1.0;
    }
    const double phase = superfluid ? p.superfluid_density : p.normal_density;
    return (p.superfluid_density + p.normal_density) / phase;
  }
  // Masses, temperatures, spins and the entropy's factor, gathered once.
  void update_constants();
  // The layout, the number density and every per-slot input of the impulses.
  void update_density();
  void update_impulses(double tau);
  // Tait: p = B ((rho / rho_k)^gamma - 1) + p_b, B = rho_k c^2 / gamma, and its energy per mass
  // e with de/drho = p / rho^2, e(rho_k) = 0.
  double pressure(double density, double rest) const;
  double internal_energy(double density, double rest) const;
  // Adds the kick's impulses and, where counted, the work of the non-gradient forces and of
  // rigid walls.
  template <class Sums>
  void add_impulses(const Sums& sums);
  // Wall blocks turn rigidly (parameters.hpp, RigidWalls).
  bool rigid_walls_on() const {
    return D == 2 && parameters_.rigid_walls.rate.size() == state_.wall.position.count() &&
           parameters_.rigid_walls.any();
  }
  // The work the rigid walls did on the fluid through the kick's gradient impulses `sums`.
  template <class Sums>
  RunTotal rigid_wall_work(const Sums& sums) const;
  // After `sums`' impulses J (components 0..D-1) were added to the momenta: the sum over the
  // moving particles of w . (p_after - J / 2) / m, w the components weight..weight+D-1. With
  // w = J it is the kinetic energy J changed; summed exactly over the run (independent of the
  // threads and processes).
  template <class Sums>
  RunTotal work_of_impulses(const Sums& sums, int weight) {
    ExactDoubleSum work;
    for_each_moving([&](const auto& kind, std::size_t set) {
      const std::span<const std::uint32_t> slots = layout_.slots_of_set(set);
      const std::span<const double> mass = layout_.part_of_set(std::span<const double>(mass_), set);
      const auto& p_scale = kind.momentum.info().scale;
      for (std::size_t i = 0; i < slots.size(); ++i) {
        double particle = 0.0;
        for (int k = 0; k < D; ++k) {
          const double middle =
              Arith::real(kind.momentum.at(k, i), p_scale) - 0.5 * sums.value(k, slots[i]);
          particle += sums.value(weight + k, slots[i]) * middle;
        }
        work.add(particle / mass[i]);
      }
    });
    return global_total(work);
  }

  WendlandQuintic<D> kernel_;
  SlotLayout<D> layout_;

  bool constants_valid_ = false;
  std::vector<double> mass_, temperature_, spin_;
  // A carrier's phase, from the layout's sets (own particles and ghosts alike; valid once the
  // layout took the sets' sizes: while it builds).
  bool is_superfluid(std::size_t carrier) const {
    return layout_.set_of_carrier(carrier) % layout_.sets().size() ==
           layout_.index_of(state_.superfluid);
  }
  // Eq. (41): sigma = C_e S(T) / rho_ref; theta' / rho = sigma for the superfluid (28) and
  // -sigma rho_s / rho_n for the normal fluid (sec. IV.3); zero for the walls.
  double theta_factor(std::size_t carrier) const;
  bool density_valid_ = false;
  PairSums<Arith, 1> number_density_sums_;
  ImpulseInputs inputs_; // by slot
  std::vector<double> slot_temperature_, slot_spin_, slot_rest_density_, slot_theta_factor_;
  bool impulses_valid_ = false;
  double impulse_tau_ = 0.0;
  PairSums<Arith, D> impulse_sums_;
  PairSums<Arith, 2 * D> counted_impulse_sums_; // impulses, then the non-gradient ones alone

  // The dissipate sub-step.
  double time_ = 0.0;
  DissipationInputs dissipation_inputs_;
  PairSums<Arith, 1> normal_weight_sums_;
  PairSums<Arith, D + 1> dissipation_sums_;
  // Accounts since the run began (J, or J/m in 2D).
  RunTotal dissipated_; // by the dissipate sub-steps (viscosity, friction, contacts)
  RunTotal wall_work_;  // done by moving walls on the fluid
  RunTotal force_work_; // done by the thermomechanical and spin forces
};

extern template class Model<2, FixedArithmetic>;
extern template class Model<3, FixedArithmetic>;
extern template class Model<2, FloatArithmetic>;
extern template class Model<3, FloatArithmetic>;

} // namespace revsph::two_fluid
