#include "models/wcsph/model.hpp"

#include "core/verlet.hpp"
#include "models/wcsph/equations.hpp"
#include "models/wcsph/gresho.hpp"
#include "models/wcsph/pair_terms.hpp"

#include <algorithm>
#include <cmath>

namespace revsph::wcsph {

template <int D, class Arith>
Model<D, Arith>::Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state)
    : Parts(std::move(parameters), std::move(info), std::move(state)),
      kernel_(parameters_.support_radius),
      layout_(parameters_.domain, parameters_.support_radius * parameters_.cell_size_factor,
              carrier_sets(state_.fluid, state_.dummy)),
      walls_(parameters_.domain,
             std::max(parameters_.support_radius, parameters_.wall.radius) *
                 parameters_.cell_size_factor,
             state_.wall.position.count(), "wall"),
      density_sums_(SummedQuantity{"density", parameters_.density_scale}),
      acceleration_sums_(components_of<D>("acceleration", parameters_.acceleration_scale)),
      viscosity_sums_(components_of<D>("velocity", parameters_.velocity_scale)) {
  if (parameters_.anti_clump_pressure > 0.0) {
    anti_clump_kernel_.emplace(0.5 * parameters_.dr); // App. A: support dr / 2
  }
}

template <int D, class Arith>
void Model<D, Arith>::initialise_density_constants(std::span<const double> target_density) {
  // With C_a = 0 the density is the plain kernel sum; C_a = target - that sum.
  std::fill(state_.fluid.density_constant.all().begin(), state_.fluid.density_constant.all().end(),
            Raw{});
  std::fill(state_.dummy.density_constant.all().begin(), state_.dummy.density_constant.all().end(),
            Raw{});
  invalidate_derived();
  update_derived();
  const std::span<const double> target(target_density);
  for (const auto& [set, field] :
       {std::pair{layout_.index_of(state_.fluid), &state_.fluid.density_constant},
        std::pair{layout_.index_of(state_.dummy), &state_.dummy.density_constant}}) {
    const std::span<const double> wanted = layout_.part_of_set(target, set);
    const auto rho = layout_.in_set_order(density_sums_.values(0), set);
    for (std::size_t i = 0; i < rho.size(); ++i) {
      set_density_constant<Arith>(*field, i, wanted[i], rho[i]);
    }
  }
  invalidate_derived();
}

template <int D, class Arith>
std::span<const Substep<Model<D, Arith>>> Model<D, Arith>::palindrome() {
  return kick_drift_kick<Model>();
}

template <int D, class Arith>
void Model<D, Arith>::kick(double dt) {
  update_derived();
  FaultRecorder faults;
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  add_rate<Arith>(
      state_.fluid.velocity,
      [&](int k, std::size_t i) { return acceleration_sums_.value(k, fluid[i]); }, dt, faults);
}

template <int D, class Arith>
void Model<D, Arith>::drift(double dt) {
  FaultRecorder faults;
  revsph::drift<Arith>(state_.fluid.position, state_.fluid.velocity, dt, faults);
  derived_valid_ = false;
}

template <int D, class Arith>
void Model<D, Arith>::update_constants() {
  if (constants_valid_) {
    return;
  }
  walls_.template place_field<Arith>(state_.wall.position);
  constants_valid_ = true;
}

template <int D, class Arith>
void Model<D, Arith>::update_derived() {
  if (derived_valid_) {
    return;
  }
  update_constants();
  // The masses and density constants are gathered straight from the state (no per-carrier copy).
  const CarrierField<Arith> mass{&state_.fluid.mass, &state_.dummy.mass};
  const CarrierField<Arith> density_constant{&state_.fluid.density_constant,
                                             &state_.dummy.density_constant};
  layout_.build(
      carrier_position(), parameters_.support_radius,
      Gathered{[&](std::size_t c) { return mass.real(0, c); }, &slot_mass_},
      Gathered{[&](std::size_t c) { return density_constant.raw(0, c); }, &slot_density_constant_});
  const std::size_t carriers = layout_.slot_count();
  walls_.find_near(layout_, parameters_.wall.radius);

  pressure_over_density_squared_.resize(carriers);
  if (anti_clump_kernel_) {
    inverse_density_squared_.resize(carriers);
  }
  FaultRecorder faults;
  // Eq. (2) per slot as soon as its density is summed (no barrier of its own).
  const auto pressure_term = [&](std::uint32_t s) {
    const double rho = density_sums_.value(0, s);
    if (!(rho > 0.0)) {
      layout_.record_fault(faults, s, "density", "density not positive");
    }
    pressure_over_density_squared_[s] =
        tait_pressure(rho, parameters_.rest_density, parameters_.sound_speed) / (rho * rho);
    if (anti_clump_kernel_) {
      inverse_density_squared_[s] = 1.0 / (rho * rho);
    }
  };
  sum_pairs<Arith>(layout_, DensityTerm<D, Arith>{kernel_, slot_mass_, slot_density_constant_},
                   density_sums_, {}, pressure_term);
  faults.throw_if_any();
  const AccelerationTerm<D> acceleration{kernel_,
                                         slot_mass_,
                                         pressure_over_density_squared_,
                                         inverse_density_squared_,
                                         layout_.in(state_.fluid),
                                         anti_clump_kernel_ ? &*anti_clump_kernel_ : nullptr,
                                         parameters_.anti_clump_pressure,
                                         parameters_.wall_potential(),
                                         parameters_.gravity};
  sum_pairs<Arith>(layout_, acceleration, acceleration_sums_, walls_.cross_pairs());
  derived_valid_ = true;
}

template <int D, class Arith>
std::vector<double> Model<D, Arith>::density() {
  update_derived();
  std::vector<double> density;
  layout_.scatter(density_sums_.values(0), density);
  return density;
}

template <int D, class Arith>
const std::array<std::vector<double>, D>& Model<D, Arith>::acceleration() {
  update_derived();
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  for (int k = 0; k < D; ++k) {
    acceleration_[k].resize(fluid.size());
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      acceleration_[k][i] = acceleration_sums_.value(k, fluid[i]);
    }
  }
  return acceleration_;
}

template <int D, class Arith>
std::array<std::vector<double>, D> Model<D, Arith>::real_velocity() const {
  std::array<std::vector<double>, D> velocity;
  const auto& scale = state_.fluid.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    velocity[k].resize(fluid_count());
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      velocity[k][a] = Arith::real(state_.fluid.velocity.at(k, a), scale);
    }
  }
  return velocity;
}

template <int D, class Arith>
void Model<D, Arith>::gather_slot_velocity(
    std::array<std::vector<double>, D>& slot_velocity) const {
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  const auto& scale = state_.fluid.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    slot_velocity[k].assign(layout_.slot_count(), 0.0);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      slot_velocity[k][fluid[i]] = Arith::real(state_.fluid.velocity.at(k, i), scale);
    }
  }
}

template <int D, class Arith>
std::array<std::vector<double>, D> Model<D, Arith>::filtered_velocity() {
  update_derived();
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  std::array<std::vector<double>, D> slot_velocity;
  gather_slot_velocity(slot_velocity);
  // The weights V w are about 1 in sum; the weighted velocities share the velocity's scale.
  std::array<SummedQuantity, D + 1> quantities{};
  quantities.fill({"filtered_velocity", parameters_.velocity_scale});
  quantities[0] = {"shepard_weight", fixedpoint::Scale::covering(1.0, 50)};
  PairSums<Arith, D + 1> sums(quantities);
  sum_pairs<Arith>(layout_,
                   ShepardTerm<D>{kernel_, slot_mass_, density_sums_.values(0), slot_velocity,
                                  layout_.in(state_.fluid)},
                   sums);
  std::array<std::vector<double>, D> filtered;
  for (int k = 0; k < D; ++k) {
    filtered[k].resize(fluid.size());
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      filtered[k][i] = sums.value(k + 1, fluid[i]) / sums.value(0, fluid[i]);
    }
  }
  return filtered;
}

template <int D, class Arith>
std::span<const StepHook<Model<D, Arith>>> Model<D, Arith>::step_hooks() {
  static constexpr StepHook<Model> hooks[] = {
      {"shepard_filter", &Model::filter_velocity, &Model::shepard_filter_acts}};
  return hooks;
}

template <int D, class Arith>
std::string Model<D, Arith>::shepard_filter_acts(const Model& model) {
  if (!model.parameters_.shepard_active) {
    return "";
  }
  return "active Shepard filter every " + std::to_string(model.parameters_.shepard_every) +
         " steps (paper 1 App. A)";
}

template <int D, class Arith>
void Model<D, Arith>::filter_velocity(std::int64_t step) {
  if (!parameters_.shepard_active || step % parameters_.shepard_every != 0) {
    return;
  }
  // App. A active filter: u := u~. Dissipative, so outside the reversible palindrome.
  const std::array<std::vector<double>, D> filtered = filtered_velocity();
  const auto& scale = state_.fluid.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      if (!Arith::try_from_real(filtered[k][a], scale, state_.fluid.velocity.at(k, a))) {
        throw SimulationFault({"fluid", a, "velocity", "the filtered velocity overflows"}, -1);
      }
    }
  }
}

template <int D, class Arith>
double Model<D, Arith>::fluid_velocity(int axis, std::size_t a) const {
  return Arith::real(state_.fluid.velocity.at(axis, a), state_.fluid.velocity.info().scale);
}

// One kind of energy per particle at a time: a snapshot holds one view, not five.
template <int D, class Arith>
std::vector<double> Model<D, Arith>::particle_energy(EnergyOf what) {
  update_derived();
  const auto mass = mass_of(state_.fluid);
  std::vector<double> energy(fluid_count());
  switch (what) {
  case EnergyOf::kinetic:
    for (std::size_t a = 0; a < energy.size(); ++a) {
      double v_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        v_squared += fluid_velocity(k, a) * fluid_velocity(k, a);
      }
      energy[a] = 0.5 * mass[a] * v_squared;
    }
    break;
  case EnergyOf::gravitational:
    for (std::size_t a = 0; a < energy.size(); ++a) {
      energy[a] = mass[a] * parameters_.gravity *
                  (fluid_position(D - 1, a) - parameters_.gravity_reference_height);
    }
    break;
  case EnergyOf::compressional:
  case EnergyOf::dummy_compressional: {
    // Eq. (3); dummy particles store compressional energy too (their rho follows the fluid).
    const std::size_t set = what == EnergyOf::compressional ? layout_.index_of(state_.fluid)
                                                            : layout_.index_of(state_.dummy);
    const auto m = layout_.in_set_order(std::span<const double>(slot_mass_), set);
    const auto rho = layout_.in_set_order(density_sums_.values(0), set);
    energy.resize(rho.size());
    for (std::size_t a = 0; a < rho.size(); ++a) {
      energy[a] = m[a] * compressional_energy_per_mass(rho[a], parameters_.rest_density,
                                                       parameters_.sound_speed);
    }
    break;
  }
  case EnergyOf::wall: {
    // Eq. (7), attributed to the fluid particle.
    energy = cross_sums_of_set(
        layout_,
        WallEnergyTerm<D>{slot_mass_, layout_.in(state_.fluid), parameters_.wall_potential()},
        walls_.cross_pairs(), layout_.index_of(state_.fluid));
    break;
  }
  }
  return energy;
}

template <int D, class Arith>
EnergyBudget Model<D, Arith>::energy() {
  // Exact sums (core/global_totals.hpp): the same value for any thread or process count.
  auto total = [&](EnergyOf what) { return exact_sum_of(particle_energy(what)); };
  ExactDoubleSum compressional = total(EnergyOf::compressional);
  compressional.add(total(EnergyOf::dummy_compressional));
  EnergyBudget budget{{{"kinetic", global_total(total(EnergyOf::kinetic))},
                       {"gravitational", global_total(total(EnergyOf::gravitational))},
                       {"compressional", global_total(compressional)},
                       {"wall", global_total(total(EnergyOf::wall))}}};
  // Only where the viscosity acts (or acted before a restart): the reversible cases' energy.csv
  // keeps its columns.
  if (viscosity_on() || dissipated_ != 0.0) {
    budget.terms.push_back({"dissipated", dissipated_});
  }
  return budget;
}

template <int D, class Arith>
void Model<D, Arith>::derived_views(const ViewSink& sink) {
  auto in_canonical_order = [](const auto& values) {
    std::vector<double> copy(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      copy[i] = values[i];
    }
    return copy;
  };
  auto pressure_of = [&](const auto& density) {
    std::vector<double> pressure(density.size());
    for (std::size_t a = 0; a < density.size(); ++a) {
      pressure[a] = tait_pressure(density[a], parameters_.rest_density, parameters_.sound_speed);
    }
    return pressure;
  };
  // Each view is built, handed over and freed before the next (the snapshot write is the peak of
  // a run's memory).
  auto emit = [&](const char* set, const char* name, std::string unit, int components,
                  std::vector<double>&& values) {
    sink(ParticleView{set, name, std::move(unit), components, std::move(values)});
  };
  update_derived();
  emit("fluid", "density", "kg/m^3", 1, in_canonical_order(density_of(state_.fluid)));
  emit("fluid", "pressure", "Pa", 1, pressure_of(density_of(state_.fluid)));
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  std::vector<double> acceleration(D * fluid.size());
  for (int k = 0; k < D; ++k) {
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      acceleration[k * fluid.size() + i] = acceleration_sums_.value(k, fluid[i]);
    }
  }
  emit("fluid", "acceleration", "m/s^2", D, std::move(acceleration));
  emit("fluid", "kinetic_energy", energy_unit<D>, 1, particle_energy(EnergyOf::kinetic));
  emit("fluid", "gravitational_energy", energy_unit<D>, 1,
       particle_energy(EnergyOf::gravitational));
  emit("fluid", "compressional_energy", energy_unit<D>, 1,
       particle_energy(EnergyOf::compressional));
  emit("fluid", "wall_energy", energy_unit<D>, 1, particle_energy(EnergyOf::wall));
  if (parameters_.shepard_every > 0) {
    std::array<std::vector<double>, D> filtered = filtered_velocity();
    std::vector<double> values;
    for (int k = 0; k < D; ++k) {
      values.insert(values.end(), filtered[k].begin(), filtered[k].end());
      filtered[k] = {};
    }
    emit("fluid", "filtered_velocity", "m/s", D, std::move(values));
  }
  if (!layout_.slots_of(state_.dummy).empty()) {
    emit("dummy", "density", "kg/m^3", 1, in_canonical_order(density_of(state_.dummy)));
    emit("dummy", "pressure", "Pa", 1, pressure_of(density_of(state_.dummy)));
    emit("dummy", "compressional_energy", energy_unit<D>, 1,
         particle_energy(EnergyOf::dummy_compressional));
  }
}

template <int D, class Arith>
std::vector<EnergyTerm> Model<D, Arith>::diagnostics() {
  if constexpr (D != 2) {
    return {}; // the Gresho vortex is two-dimensional (parameters.cpp)
  } else {
    if (parameters_.initial_field != InitialField::gresho_vortex) {
      return {};
    }
    // Paper 1 eq. (11) at this instant: sqrt(75 / (4 pi) sum_a V_a |u_a - u0(r_a)|^2), for the
    // velocity and for its Shepard-filtered field; the error of a run is the maximum over time.
    update_derived();
    const std::array<std::vector<double>, D> velocity = real_velocity();
    const std::array<std::vector<double>, D> filtered = filtered_velocity();
    const auto mass = mass_of(state_.fluid);
    const auto rho = density_of(state_.fluid);
    ExactDoubleSum raw_sum;
    ExactDoubleSum filtered_sum;
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      const auto [exact_x, exact_y] =
          gresho::velocity(fluid_position(0, a) - parameters_.centre[0],
                           fluid_position(1, a) - parameters_.centre[1]);
      const double volume = mass[a] / rho[a];
      raw_sum.add(volume * ((velocity[0][a] - exact_x) * (velocity[0][a] - exact_x) +
                            (velocity[1][a] - exact_y) * (velocity[1][a] - exact_y)));
      filtered_sum.add(volume * ((filtered[0][a] - exact_x) * (filtered[0][a] - exact_x) +
                                 (filtered[1][a] - exact_y) * (filtered[1][a] - exact_y)));
    }
    // Relative to the exact field's norm: pure numbers.
    return {{"velocity_error", sqrt(global_total(raw_sum) / gresho::velocity_norm_squared), "1"},
            {"filtered_velocity_error",
             sqrt(global_total(filtered_sum) / gresho::velocity_norm_squared), "1"}};
  }
}

template class Model<1, FixedArithmetic>;
template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<1, FloatArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::wcsph
