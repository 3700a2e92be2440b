#include "models/entropic/model.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/carrier_field.hpp"
#include "core/case_values.hpp"
#include "core/state_snapshot.hpp"
#include "core/summation_density.hpp"
#include "core/verlet.hpp"
#include "fixedpoint/exact_sum.hpp"
#include "models/entropic/pair_terms.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace revsph::entropic {

namespace {

std::array<SummedQuantity, 1> density_quantity(const fixedpoint::Scale& scale) {
  return {SummedQuantity{"density", scale}};
}

// The scales of sum m W, sum S W and sum W: the initial density, entropy density and number
// density 1 / dr^D, each resolved with 48 bits.
template <int D>
std::array<SummedQuantity, 3> kernel_sum_quantities(const Parameters<D>& parameters) {
  const double heat_capacity = parameters.heat_capacity();
  const double entropy_density =
      parameters.initial_density *
      std::max(std::abs(parameters.initial_specific_entropy()), heat_capacity);
  return {SummedQuantity{"density", parameters.density_scale},
          SummedQuantity{"entropy_density", fixedpoint::Scale::covering(entropy_density, 48)},
          SummedQuantity{"number_density",
                         fixedpoint::Scale::covering(dmath::integer_power(parameters.dr, -D), 48)}};
}

// The hottest thermal wall (0 K without thermal walls).
template <int D>
double hottest_wall(const State<D>& state) {
  double largest = 0.0;
  for (const std::int64_t raw : state.thermal.temperature.component(0)) {
    largest = std::max(largest, fixedpoint::to_real(raw, state.thermal.temperature.info().scale));
  }
  return largest;
}

template <int D>
double initial_temperature(const Parameters<D>& parameters) {
  return parameters.initial_temperature();
}

// The heat flux q of eq. (54) reaches about lambda_F T^2 / h; resolved with 48 bits.
template <int D>
std::array<SummedQuantity, D> heat_flux_quantities(const Parameters<D>& parameters) {
  const double temperature = initial_temperature(parameters);
  // (Without conduction the sums are not run; any scale will do.)
  const double largest =
      parameters.heat_conductivity > 0.0
          ? parameters.heat_conductivity * temperature * temperature / parameters.support_radius
          : 1.0;
  std::array<SummedQuantity, D> quantities{};
  quantities.fill({"heat_flux", fixedpoint::Scale::covering(largest, 48)});
  return quantities;
}

// The viscous impulses at the momentum scale; the heat a particle receives in one update at 56
// bits below its thermal energy m c_V T: far finer than any heat a step moves.
template <int D>
std::array<SummedQuantity, D + 1> dissipation_quantities(const Parameters<D>& parameters) {
  std::array<SummedQuantity, D + 1> quantities{};
  quantities.fill({"momentum", parameters.momentum_scale});
  const double mass = parameters.initial_density * dmath::integer_power(parameters.dr, D);
  quantities[D] = {"heat",
                   fixedpoint::Scale::covering(
                       mass * parameters.heat_capacity() * initial_temperature(parameters), 56)};
  return quantities;
}

} // namespace

template <int D>
Model<D>::Model(Parameters<D> parameters, SimulationInfo info, State<D> state)
    : Parts(std::move(parameters), std::move(info), std::move(state)),
      kernel_(parameters_.support_radius),
      layout_(parameters_.domain, parameters_.support_radius * parameters_.cell_size_factor,
              carrier_sets(state_.gas, state_.dummy, state_.thermal)),
      walls_(parameters_.domain,
             std::max(parameters_.support_radius, parameters_.wall.radius) *
                 parameters_.cell_size_factor,
             state_.wall.position.count(), "wall"),
      density_sums_(density_quantity(parameters_.density_scale)),
      kernel_sums_(kernel_sum_quantities(parameters_)),
      heat_flux_sums_(heat_flux_quantities(parameters_)),
      dissipation_sums_(dissipation_quantities(parameters_)),
      wall_mirror_sums_(wall_mirror_quantities(parameters_, state_)),
      flux_sums_(components_of<D>("entropy_flux", parameters_.entropy_flux_scale)),
      entropy_exchange_sums_({SummedQuantity{"entropy", state_.gas.entropy.info().scale}}),
      impulse_sums_(components_of<D>("momentum", parameters_.momentum_scale)),
      has_thermal_walls_(state_.thermal.position.count() > 0) {}

// sum W T: 4 times the hottest wall over dr^D; sum W v: 4 times the sound speed over dr^D;
// sum W: the number density; each with 48 bits.
template <int D>
std::array<SummedQuantity, D + 2> Model<D>::wall_mirror_quantities(const Parameters<D>& parameters,
                                                                   const State<D>& state) {
  const double density = dmath::integer_power(parameters.dr, -D);
  std::array<SummedQuantity, D + 2> quantities{};
  // Without thermal walls the sums are unused: any finite scale will do.
  const double temperature_magnitude =
      state.thermal.temperature.count() == 0
          ? 4.0 * density
          : wall_temperature_sum_magnitude<D>(hottest_wall(state), parameters.initial_temperature(),
                                              parameters.dr);
  quantities[0] = {"temperature_density", fixedpoint::Scale::covering(temperature_magnitude, 48)};
  for (int k = 0; k < D; ++k) {
    quantities[1 + k] = {
        "velocity_density",
        fixedpoint::Scale::covering(4.0 * parameters.initial_sound_speed() * density, 48)};
  }
  quantities[D + 1] = {"number_density", fixedpoint::Scale::covering(density, 48)};
  return quantities;
}

template <int D>
std::span<const Substep<Model<D>>> Model<D>::palindrome() {
  // The reversible core is kick-drift-kick around the exchange of the hyperbolic heat
  // conduction (w, S, w: eq. 68). Each sub-step does nothing where its physics is off.
  static constexpr Substep<Model> sequence[] = {
      {"kick", 0.5, &Model::kick_substep},
      {"flux", 0.5, &Model::flux_substep},
      {"entropy_exchange", 0.5, &Model::entropy_exchange_substep},
      {"drift", 1.0, &Model::drift_substep},
      {"entropy_exchange", 0.5, &Model::entropy_exchange_substep},
      {"flux", 0.5, &Model::flux_substep},
      {"kick", 0.5, &Model::kick_substep},
  };
  return sequence;
}

template <int D>
std::span<const IrreversibleOperator<Model<D>>> Model<D>::irreversible_operators() {
  static constexpr IrreversibleOperator<Model> operators[] = {
      {"dissipation", &Model::dissipate, &Model::dissipation_description},
      {"relaxation", &Model::relax_flux, &Model::relaxation_description},
  };
  return operators;
}

template <int D>
void Model<D>::update_constants() {
  if (constants_valid_) {
    return;
  }
  walls_.template place_field<FixedArithmetic>(state_.wall.position);
  mass_ = CarrierField<FixedArithmetic>{&state_.gas.mass, &state_.dummy.mass, &state_.thermal.mass}
              .reals();
  constants_valid_ = true;
}

template <int D>
void Model<D>::update_geometry() {
  if (geometry_valid_) {
    return;
  }
  update_constants();
  // The dissipation changes the gas's entropies: read at every rebuild.
  entropy_ = CarrierField<FixedArithmetic>{&state_.gas.entropy, &state_.dummy.entropy,
                                           &state_.thermal.entropy}
                 .reals();
  const bool positions_unchanged = layout_current_;
  if (positions_unchanged) {
    // The positions did not change since the build: only the entropies did.
    layout_.gather(std::span<const double>(entropy_), slot_entropy_);
  } else {
    layout_.build(CarrierField<FixedArithmetic>{&state_.gas.position, &state_.dummy.position,
                                                &state_.thermal.position},
                  parameters_.support_radius, Gathered<double>{mass_, &slot_mass_},
                  Gathered<double>{entropy_, &slot_entropy_},
                  Gathered{held_temperature(), &slot_held_temperature_});
    walls_.find_near(layout_, parameters_.wall.radius);
    layout_current_ = true;
  }
  const std::size_t n = layout_.slot_count();
  for (std::vector<double>* values : {&density_, &entropy_density_, &volume_, &pressure_,
                                      &temperature_, &specific_energy_, &alpha_, &beta_}) {
    values->resize(n);
  }
  const bool mixed = parameters_.volume == ParticleVolume::mixed;
  gamma_.resize(mixed ? n : 0);
  delta_.resize(mixed ? n : 0);
  // Each slot's thermodynamics as soon as its kernel sums are final.
  FaultRecorder faults;
  const auto per_slot = [&](std::uint32_t s) {
    if (!update_slot(s)) {
      layout_.record_fault(faults, s, "density",
                           "volume, density or pressure not positive and finite");
    }
  };
  if (parameters_.volume == ParticleVolume::implicit) {
    update_implicit_volume();
  } else if (parameters_.volume == ParticleVolume::mass && positions_unchanged) {
    // sum_b m_b W_ab depends on the positions alone: the sums of the last update stand.
#pragma omp parallel for schedule(static)
    for (std::size_t s = 0; s < n; ++s) {
      per_slot(static_cast<std::uint32_t>(s));
    }
  } else if (parameters_.volume == ParticleVolume::mass) {
    sum_pairs<FixedArithmetic>(layout_,
                               SummationDensityTerm<D, FixedArithmetic>{kernel_, slot_mass_, {}},
                               density_sums_, {}, per_slot);
  } else {
    sum_pairs<FixedArithmetic>(layout_, KernelSumsTerm<D>{kernel_, slot_mass_, slot_entropy_},
                               kernel_sums_, {}, per_slot);
  }
  faults.throw_if_any();
  geometry_valid_ = true;
  impulses_valid_ = false;
}

template <int D>
bool Model<D>::update_slot(std::uint32_t s) {
  const double m = slot_mass_[s];
  const double entropy = slot_entropy_[s];
  double rho = 0.0;
  double entropy_density = 0.0;
  double volume = 0.0;
  switch (parameters_.volume) {
  case ParticleVolume::mass: // eqs. (23), (32)
    rho = density_sums_.value(0, s);
    volume = m / rho;
    entropy_density = entropy / volume;
    break;
  case ParticleVolume::entropic: // eqs. (24), (36)
    entropy_density = kernel_sums_.value(1, s);
    volume = entropy / entropy_density;
    rho = m / volume;
    break;
  case ParticleVolume::direct: // eqs. (25), (39)-(40)
    volume = 1.0 / kernel_sums_.value(2, s);
    rho = m / volume;
    entropy_density = entropy / volume;
    break;
  case ParticleVolume::mixed: // eq. (28); the energy takes the mass volume (before eq. 47)
    rho = kernel_sums_.value(0, s);
    entropy_density = kernel_sums_.value(1, s);
    volume = m / rho;
    break;
  case ParticleVolume::implicit: // eqs. (26), (43): W V = 1 solved before (update_implicit_volume)
    volume = implicit_volume_[layout_.carrier_of_slot()[s]];
    rho = m / volume;
    entropy_density = entropy / volume;
    break;
  }
  const double sigma = entropy_density / rho;
  const ThermodynamicState st = std::visit(
      [&](const auto& law) { return entropic::state(law, rho, sigma); }, parameters_.gas_law);
  density_[s] = rho;
  entropy_density_[s] = entropy_density;
  volume_[s] = volume;
  pressure_[s] = st.pressure;
  temperature_[s] = st.temperature;
  specific_energy_[s] = st.specific_energy; // V rho = m in every volume: U_a = m_a u_a
  // The pair-force coefficients, Phi_ab = alpha_a beta_b + alpha_b beta_a (+ gamma delta).
  switch (parameters_.volume) {
  case ParticleVolume::mass: // (34c)
    alpha_[s] = m * st.pressure / (rho * rho);
    beta_[s] = m;
    break;
  case ParticleVolume::entropic: // (38b)
    alpha_[s] = entropy * st.pressure / (entropy_density * entropy_density);
    beta_[s] = entropy;
    break;
  case ParticleVolume::direct: // (42c)
    alpha_[s] = st.pressure * volume * volume;
    beta_[s] = 1.0;
    break;
  case ParticleVolume::mixed: // (47c): A = dU/drho, B = dU/ds at fixed x
    alpha_[s] = m * (st.pressure - entropy_density * st.temperature) / (rho * rho);
    beta_[s] = m;
    gamma_[s] = m * st.temperature / rho;
    delta_[s] = entropy;
    break;
  case ParticleVolume::implicit: // (45b): alpha = y (W y = p), set by update_implicit_volume
    alpha_[s] = 0.0;
    beta_[s] = volume;
    break;
  }
  return rho > 0.0 && volume > 0.0 && std::isfinite(rho) && std::isfinite(alpha_[s]) &&
         std::isfinite(st.pressure);
}

template <int D>
void Model<D>::update_implicit_volume() {
  // W is symmetric positive definite for distinct points (Wendland functions are positive
  // definite), so conjugate gradients apply (§4.4). A fixed zero start and a relative residual of
  // 1e-12 make V and y functions of the positions alone; the tolerance enters the energy error
  // (the force is the exact gradient only for exact solves).
  //
  // The dummy particles keep the lattice volume m / rho_0 and only the gas's rows are solved:
  // W_gg V_g = 1 - W_gd V_d. Solving the dummies' rows too would put a cut support on the
  // outermost dummy layer, whose volumes then swing negative (measured: box-small fails at step
  // 27); the paper fills its quadrature test with dummies for the same reason (Fig. 2). The
  // energy then varies only through V_g, dV_g = -W_gg^-1 (dW_gg V_g + dW_gd V_d), so the force
  // keeps the form of (45b) with y = W_gg^-1 p_g on the gas and y = 0 on the dummies:
  // Phi_ab = y_a V_b + y_b V_a for every pair (models/entropic/derivations.md).
  const std::size_t n = layout_.carrier_count();
  const std::size_t gas = gas_count();
  implicit_system_.assemble<D>(layout_, [this](double r) { return kernel_.value(r); }, gas,
                               {1e-12, 5000});
  implicit_volume_.resize(n);
  for (std::size_t d = gas; d < n; ++d) {
    implicit_volume_[d] = mass_[d] / parameters_.initial_density;
  }
  if (!implicit_system_.solve_with_held(std::vector<double>(gas, 1.0), implicit_volume_)) {
    throw SimulationFault({"gas", 0, "volume",
                           "the implicit volume's solve W V = 1 did not converge (residual " +
                               format_scientific(implicit_system_.error(), 3) + ")"},
                          -1);
  }
  FaultRecorder faults;
  const std::size_t slots = layout_.slot_count();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    if (!update_slot(static_cast<std::uint32_t>(s))) {
      layout_.record_fault(faults, s, "volume",
                           "implicit volume, density or pressure not positive and finite (eq. "
                           "26 gives negative volumes near free surfaces: paper 4, Fig. 8)");
    }
  }
  faults.throw_if_any();
  implicit_pressure_.resize(gas);
  const std::span<const std::uint32_t> carrier = layout_.carrier_of_slot();
  for (std::size_t s = 0; s < slots; ++s) {
    if (carrier[s] < static_cast<std::uint32_t>(gas)) {
      implicit_pressure_[carrier[s]] = pressure_[s];
    }
  }
  implicit_y_.assign(n, 0.0); // the gas's entries solved (in a distributed run its ghosts' too)
  if (!implicit_system_.solve_unknowns(implicit_pressure_, implicit_y_)) { // (45): y = W^-1 p
    throw SimulationFault({"gas", 0, "pressure",
                           "the implicit volume's solve W y = p did not converge (residual " +
                               format_scientific(implicit_system_.error(), 3) + ")"},
                          -1);
  }
  for (std::size_t s = 0; s < slots; ++s) {
    alpha_[s] = implicit_system_.is_unknown(carrier[s]) ? implicit_y_[carrier[s]] : 0.0;
  }
}

template <int D>
void Model<D>::update_impulses(double dt) {
  update_geometry();
  if (impulses_valid_ && impulse_dt_ == dt) {
    return;
  }
  const ImpulseTerm<D> term{kernel_,
                            dt,
                            slot_mass_,
                            alpha_,
                            beta_,
                            gamma_,
                            delta_,
                            parameters_.wall_potential(),
                            parameters_.gravity,
                            parameters_.boussinesq ? std::span<const double>(temperature_)
                                                   : std::span<const double>(),
                            parameters_.initial_temperature()};
  sum_pairs<FixedArithmetic>(layout_, term, impulse_sums_, walls_.cross_pairs());
  impulse_dt_ = dt;
  impulses_valid_ = true;
}

template <int D>
void Model<D>::kick(double dt) {
  update_impulses(dt);
  // M_a += the exact sum of its rounded pair impulses: no rounding of its own, so a reversed
  // kick subtracts bit for bit what this one added.
  FaultRecorder faults;
  add_pair_totals<FixedArithmetic>(state_.gas.momentum, impulse_sums_, 0,
                                   layout_.slots_of(state_.gas), faults);
}

template <int D>
void Model<D>::drift(double dt) {
  update_constants();
  FaultRecorder faults;
  drift_by_momentum<FixedArithmetic>(state_.gas.position, state_.gas.momentum, of_gas(mass_), dt,
                                     faults);
  geometry_valid_ = false;
  layout_current_ = false;
}

template <int D>
typename Model<D>::Thermodynamics Model<D>::thermodynamics() {
  update_geometry();
  const std::span<const std::uint32_t> slots = layout_.slots_of(state_.gas);
  Thermodynamics values;
  for (const std::uint32_t s : slots) {
    values.density.push_back(density_[s]);
    values.entropy_density.push_back(entropy_density_[s]);
    values.volume.push_back(volume_[s]);
    values.pressure.push_back(pressure_[s]);
    values.temperature.push_back(temperature_[s]);
    values.specific_energy.push_back(specific_energy_[s]);
  }
  return values;
}

template <int D>
EnergyBudget Model<D>::energy() {
  const Thermodynamics values = thermodynamics();
  const Field& momentum = state_.gas.momentum;
  const Field& position = state_.gas.position;
  const std::span<const double> gas_mass = of_gas(mass_);
  // Exact sums (core/global_totals.hpp): the same value for any thread or process count.
  ExactDoubleSum kinetic;
  ExactDoubleSum internal;
  ExactDoubleSum gravitational;
  for (std::size_t i = 0; i < gas_count(); ++i) {
    double m_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double p = fixedpoint::to_real(momentum.at(k, i), momentum.info().scale);
      m_squared += p * p;
    }
    kinetic.add(0.5 * m_squared / gas_mass[i]);
    internal.add(gas_mass[i] * values.specific_energy[i]); // V_a eps_a = m_a u_a, eq. (20)
    const double height = fixedpoint::to_real(position.at(D - 1, i), position.info().scale);
    if (!parameters_.boussinesq) { // the Boussinesq body force has no potential
      gravitational.add(gas_mass[i] * parameters_.gravity *
                        (height - parameters_.gravity_reference_height));
    }
  }
  // Dummy and thermal particles store internal energy too: their density follows the gas around
  // them.
  for (const std::size_t set : {layout_.index_of(state_.dummy), layout_.index_of(state_.thermal)}) {
    for (const std::uint32_t s : layout_.slots_of_set(set)) {
      internal.add(slot_mass_[s] * specific_energy_[s]);
    }
  }
  PairSums<FloatArithmetic, 1> wall_sums(SummedQuantity{"wall_energy", fixedpoint::Scale()});
  sum_cross_pairs<FloatArithmetic>(
      layout_, WallEnergyTerm<D>{slot_mass_, layout_.in(state_.gas), parameters_.wall_potential()},
      wall_sums, walls_.cross_pairs());
  ExactDoubleSum wall;
  for (const std::uint32_t s : layout_.slots_of(state_.gas)) {
    wall.add(wall_sums.value(0, s));
  }
  EnergyBudget budget{{{"kinetic", global_total(kinetic)},
                       {"internal", global_total(internal)},
                       {"gravitational", global_total(gravitational)},
                       {"wall", global_total(wall)}}};
  if (has_thermal_walls_) {
    // The heat the thermal walls took in: with it the total is kept.
    budget.terms.push_back({"thermal_walls", wall_heat_});
  }
  if (parameters_.hyperbolic()) {
    // c_w sum_a V_a |w_a|^2 (§5.5, Fig. 13).
    const Field& flux = state_.gas.entropy_flux;
    ExactDoubleSum flux_energy;
    for (std::size_t i = 0; i < gas_count(); ++i) {
      double w_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double w = fixedpoint::to_real(flux.at(k, i), flux.info().scale);
        w_squared += w * w;
      }
      flux_energy.add(parameters_.flux_energy_coefficient * values.volume[i] * w_squared);
    }
    budget.terms.push_back({"entropy_flux", global_total(flux_energy)});
  }
  return budget;
}

template <int D>
void Model<D>::derived_views(const ViewSink& sink) {
  Thermodynamics values = thermodynamics();
  sink(ParticleView{"gas", "density", "kg/m^3", 1, std::move(values.density)});
  sink(ParticleView{"gas", "entropy_density", "J/(K m^3)", 1, std::move(values.entropy_density)});
  sink(ParticleView{"gas", "volume", D == 1 ? "m" : (D == 2 ? "m^2" : "m^3"), 1,
                    std::move(values.volume)});
  sink(ParticleView{"gas", "pressure", "Pa", 1, std::move(values.pressure)});
  sink(ParticleView{"gas", "temperature", "K", 1, std::move(values.temperature)});
  const Field& momentum = state_.gas.momentum;
  const std::span<const double> gas_mass = of_gas(mass_);
  std::vector<double> velocity(static_cast<std::size_t>(D) * gas_count());
  for (int k = 0; k < D; ++k) {
    for (std::size_t i = 0; i < gas_count(); ++i) {
      velocity[static_cast<std::size_t>(k) * gas_count() + i] =
          fixedpoint::to_real(momentum.at(k, i), momentum.info().scale) / gas_mass[i];
    }
  }
  sink(ParticleView{"gas", "velocity", "m/s", D, std::move(velocity)});
}

template <int D>
std::vector<EnergyTerm> Model<D>::diagnostics() {
  // The total momentum, summed exactly in integers: internal forces leave it unchanged bit for
  // bit, so what changes it is walls and gravity alone.
  static constexpr const char* names[] = {"momentum_x", "momentum_y", "momentum_z"};
  const Field& momentum = state_.gas.momentum;
  std::vector<EnergyTerm> terms;
  for (int k = 0; k < D; ++k) {
    fixedpoint::int128 total = 0;
    for (const std::int64_t raw : momentum.component(k)) {
      total += raw;
    }
    terms.push_back({names[k],
                     global_total_real(total, fixedpoint::to_real(1, momentum.info().scale)),
                     momentum.info().unit});
  }
  // The total entropy of the gas, summed exactly: the reversible part keeps it bit for bit, the
  // dissipation and the relaxation raise it.
  fixedpoint::int128 entropy = 0;
  for (const std::int64_t raw : state_.gas.entropy.component(0)) {
    entropy += raw;
  }
  terms.push_back(
      {"entropy",
       global_total_real(entropy, fixedpoint::to_real(1, state_.gas.entropy.info().scale)),
       state_.gas.entropy.info().unit});
  if (has_thermal_walls_) {
    // Since the run (or its restart) began: the entropy the walls gained, sum Q / T_w (with the
    // gas's, it never decreases), and the heat the hot walls gave and the cold walls took.
    terms.push_back({"thermal_wall_entropy", wall_entropy_, entropy_unit<D>});
    terms.push_back({"heat_out_of_hot_walls", hot_wall_heat_out_, energy_unit<D>});
    terms.push_back({"heat_into_cold_walls", cold_wall_heat_in_, energy_unit<D>});
  }
  if (parameters_.volume == ParticleVolume::implicit) {
    // How well the volumes solve eq. (26): max over the gas of |sum_b W_ab V_b - 1|.
    update_geometry();
    terms.push_back(
        {"implicit_volume_residual",
         implicit_system_.max_residual(implicit_volume_, std::vector<double>(gas_count(), 1.0)),
         "1"});
  }
  return terms;
}

template class Model<1>;
template class Model<2>;
template class Model<3>;

} // namespace revsph::entropic
