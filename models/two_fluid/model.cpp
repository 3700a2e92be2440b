#include "models/two_fluid/model.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/verlet.hpp"
#include "models/two_fluid/helium_ii.hpp"
#include "models/two_fluid/rigid_walls.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace revsph::two_fluid {

template <int D, class Arith>
Model<D, Arith>::Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state)
    : Parts(std::move(parameters), std::move(info), std::move(state)),
      kernel_(parameters_.support_radius),
      layout_(parameters_.domain, parameters_.support_radius * parameters_.cell_size_factor,
              carrier_sets(state_.superfluid, state_.normal, state_.wall)),
      number_density_sums_(SummedQuantity{"number_density", parameters_.density_scale}),
      impulse_sums_(components_of<D>("momentum", parameters_.momentum_scale)),
      counted_impulse_sums_(components_of<2 * D>("momentum", parameters_.momentum_scale)),
      normal_weight_sums_(SummedQuantity{"normal_weight", parameters_.density_scale}),
      dissipation_sums_([this] {
        std::array<SummedQuantity, D + 1> q{};
        for (int k = 0; k < D; ++k) {
          q[k] = {"momentum", parameters_.momentum_scale};
        }
        q[D] = {"wall_work", parameters_.energy_scale};
        return q;
      }()) {}

template <int D, class Arith>
std::span<const Substep<Model<D, Arith>>> Model<D, Arith>::palindrome() {
  return kick_drift_kick<Model>();
}

template <int D, class Arith>
std::span<const IrreversibleOperator<Model<D, Arith>>> Model<D, Arith>::irreversible_operators() {
  static constexpr IrreversibleOperator<Model> operators[] = {
      {"dissipate", &Model::dissipate, &Model::dissipation_acts}};
  return operators;
}

namespace {

// ratio^exponent; an integral exponent (the Tait default 7) by multiplication, which is exact in
// its order of operations and several times cheaper than pow.
double tait_power(double ratio, double exponent) {
  const int integral = static_cast<int>(exponent);
  return integral == exponent ? dmath::integer_power(ratio, integral) : dmath::pow(ratio, exponent);
}

} // namespace

template <int D, class Arith>
double Model<D, Arith>::pressure(double density, double rest) const {
  const Parameters<D>& p = parameters_;
  const double b = rest * p.sound_speed * p.sound_speed / p.tait_exponent;
  return b * (tait_power(density / rest, p.tait_exponent) - 1.0) + p.background_pressure;
}

template <int D, class Arith>
double Model<D, Arith>::internal_energy(double density, double rest) const {
  // e = B / (rho_k (gamma - 1)) ((rho / rho_k)^(gamma - 1) - 1) + (B - p_b)(1 / rho - 1 / rho_k):
  // de/drho = (B (rho / rho_k)^gamma - B + p_b) / rho^2 = p / rho^2.
  const Parameters<D>& p = parameters_;
  const double gamma = p.tait_exponent;
  const double b = rest * p.sound_speed * p.sound_speed / gamma;
  const double power = gamma == 1.0
                           ? dmath::log(density / rest)
                           : (tait_power(density / rest, gamma - 1.0) - 1.0) / (gamma - 1.0);
  return b / rest * power + (b - p.background_pressure) * (1.0 / density - 1.0 / rest);
}

template <int D, class Arith>
void Model<D, Arith>::update_constants() {
  if (constants_valid_) {
    return;
  }
  mass_ =
      CarrierField<Arith>{&state_.superfluid.mass, &state_.normal.mass, &state_.wall.mass}.reals();
  temperature_ = CarrierField<Arith>{&state_.superfluid.temperature, &state_.normal.temperature,
                                     &state_.wall.temperature}
                     .reals();
  spin_ =
      CarrierField<Arith>{&state_.superfluid.spin, &state_.normal.spin, &state_.wall.spin}.reals();
  constants_valid_ = true;
}

template <int D, class Arith>
double Model<D, Arith>::theta_factor(std::size_t carrier) const {
  const Thermomechanical& t = parameters_.thermomechanical;
  const std::size_t set = layout_.set_of_carrier(carrier) % layout_.sets().size();
  const bool superfluid = set == layout_.index_of(state_.superfluid);
  if (!(t.entropy_scale > 0.0) || !(superfluid || set == layout_.index_of(state_.normal))) {
    return 0.0;
  }
  const double kind =
      superfluid ? 1.0 : -parameters_.superfluid_density / parameters_.normal_density;
  return kind * t.entropy_scale * phonon_roton_entropy(temperature_[carrier], t.first_sound_speed) /
         t.reference_density;
}

template <int D, class Arith>
void Model<D, Arith>::update_density() {
  if (density_valid_) {
    return;
  }
  update_constants();
  ImpulseInputs& in = inputs_;
  layout_.build(carrier_position(), parameters_.support_radius, Gathered<double>{mass_, &in.mass},
                Gathered<double>{temperature_, &slot_temperature_},
                Gathered<double>{spin_, &in.spin},
                Gathered{[&](std::size_t c) { return parameters_.rest_density(is_superfluid(c)); },
                         &slot_rest_density_},
                Gathered{[&](std::size_t c) { return theta_factor(c); }, &slot_theta_factor_});
  in.moves = layout_.in(state_.superfluid, state_.normal);
  in.viscous = layout_.in(state_.normal, state_.wall);
  dissipation_inputs_.superfluid = layout_.in(state_.superfluid);
  dissipation_inputs_.wall = layout_.in(state_.wall);
  const std::size_t slots = layout_.slot_count();
  for (std::vector<double>* v :
       {&in.volume, &in.density, &in.pressure, &in.temperature_term, &in.thermomechanical}) {
    v->resize(slots);
  }
  FaultRecorder faults;
  const auto inputs_of_slot = [&](std::uint32_t s) {
    const double n = number_density_sums_.value(0, s);
    if (!(n > 0.0)) {
      layout_.record_fault(faults, s, "density", "number density not positive");
      return;
    }
    const double rho = in.mass[s] * n; // eq. (36)
    in.volume[s] = 1.0 / n;
    in.density[s] = rho;
    in.pressure[s] = pressure(rho, slot_rest_density_[s]);
    in.temperature_term[s] = slot_temperature_[s] / (rho * rho);
    in.thermomechanical[s] = rho * slot_theta_factor_[s]; // theta' of eqs. (28, 31)
  };
  sum_pairs<Arith>(layout_, NumberDensityTerm<D>{kernel_}, number_density_sums_, {},
                   inputs_of_slot);
  faults.throw_if_any();
  // A phase's share of the volume (README, "Interpenetrating phases"): V rho / rho_k for the
  // fluid, V for the walls (wholly normal); V itself with separate phases.
  in.phase_volume.resize(slots);
  for (std::size_t s = 0; s < slots; ++s) {
    in.phase_volume[s] = in.volume[s] * phase_factor_of(dissipation_inputs_.superfluid(s),
                                                        dissipation_inputs_.wall(s));
  }
  density_valid_ = true;
  impulses_valid_ = false;
}

template <int D, class Arith>
void Model<D, Arith>::update_impulses(double tau) {
  update_density();
  if (impulses_valid_ && impulse_tau_ == tau) {
    return;
  }
  const Parameters<D>& p = parameters_;
  const bool thermomechanical = p.thermomechanical.entropy_scale > 0.0;
  const auto term = [&]<bool Counted>(std::bool_constant<Counted>) {
    return ImpulseTerm<D, Counted>{kernel_,
                                   inputs_,
                                   p.pressure_form,
                                   p.rotational_viscosity,
                                   p.gravity,
                                   tau,
                                   thermomechanical,
                                   spin_on(),
                                   p.thermomechanical.difference_form,
                                   slot_temperature_,
                                   rigid_walls_on()};
  };
  if (counts_force_work()) {
    sum_pairs<Arith>(layout_, term(std::true_type{}), counted_impulse_sums_);
  } else {
    sum_pairs<Arith>(layout_, term(std::false_type{}), impulse_sums_);
  }
  impulse_tau_ = tau;
  impulses_valid_ = true;
}

template <int D, class Arith>
template <class Sums>
void Model<D, Arith>::add_impulses(const Sums& sums) {
  // p += the exact total of the particle's rounded pair impulses, no rounding of its own: a
  // reversed kick subtracts bit for bit what this one added.
  FaultRecorder faults;
  for_each_moving([&](auto& kind, std::size_t set) {
    add_pair_totals<Arith>(kind.momentum, sums, 0, layout_.slots_of_set(set), faults);
  });
  faults.throw_if_any();
  if (rigid_walls_on()) {
    wall_work_ += rigid_wall_work(sums);
  }
  if (!counts_force_work()) {
    return;
  }
  // The work of the non-gradient impulses (components D..2D-1).
  force_work_ += work_of_impulses(sums, D);
}

template <int D, class Arith>
template <class Sums>
RunTotal Model<D, Arith>::rigid_wall_work(const Sums& sums) const {
  // A turning wall moves the internal energy sum m e(rho), which depends on its position, by
  // -F_w . dx_w, F_w the gradient (pressure) force on it: that is the work it does on the fluid.
  // Each kick of tau adds -J_w . v_w with J_w = F_w tau (the non-gradient spin share, components
  // D..2D-1 where counted, left out: its work on the fluid is force_work's), so the two kicks of a
  // step make the trapezoid rule over the step, second order as the integrator.
  const std::span<const std::uint32_t> slots = layout_.slots_of(state_.wall);
  const auto& v_scale = state_.wall.velocity.info().scale;
  ExactDoubleSum work;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      double impulse = sums.value(k, slots[i]);
      if constexpr (std::is_same_v<Sums, PairSums<Arith, 2 * D>>) {
        impulse -= sums.value(D + k, slots[i]);
      }
      work.add(-impulse * Arith::real(state_.wall.velocity.at(k, i), v_scale));
    }
  }
  return global_total(work);
}

template <int D, class Arith>
void Model<D, Arith>::kick(double dt) {
  update_impulses(dt);
  if (counts_force_work()) {
    add_impulses(counted_impulse_sums_);
  } else {
    add_impulses(impulse_sums_);
  }
}

template <int D, class Arith>
void Model<D, Arith>::drift(double dt) {
  update_constants();
  FaultRecorder faults;
  for_each_moving([&](auto& kind, std::size_t set) {
    drift_by_momentum<Arith>(kind.position, kind.momentum,
                             layout_.part_of_set(std::span<const double>(mass_), set), dt, faults);
  });
  faults.throw_if_any();
  // Rigid walls turn by dt Omega (rigid_walls.hpp), exactly reversible like the fluid's drift.
  if (rigid_walls_on()) {
    turn_rigid_walls<Arith>(state_.wall.position, state_.wall.velocity, parameters_.rigid_walls, dt,
                            faults);
  }

  density_valid_ = false;
  impulses_valid_ = false;
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::two_fluid
