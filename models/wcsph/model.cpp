#include "models/wcsph/model.hpp"

#include "core/cell_order.hpp"
#include "core/verlet.hpp"
#include "models/wcsph/equations.hpp"
#include "models/wcsph/forces.hpp"
#include "models/wcsph/gresho.hpp"

#include <algorithm>
#include <cmath>

namespace revsph::wcsph {

namespace {

// At most a few cells per particle, so a large empty domain cannot exhaust memory.
std::size_t cell_budget(std::size_t particles) {
  return 4 * particles + 4096;
}

// Real coordinates of a field, written into `out` from index `first` on.
template <class Arith, int D>
void real_coordinates(const StateField<typename Arith::Raw>& field, CoordinateArrays<D>& out,
                      std::size_t first) {
  for (int k = 0; k < D; ++k) {
    const auto raw = field.component(k);
    out[k].resize(std::max(out[k].size(), first + raw.size()));
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < raw.size(); ++i) {
      out[k][first + i] = Arith::real(raw[i], field.info().scale);
    }
  }
}

} // namespace

template <int D, class Arith>
Model<D, Arith>::Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state)
    : parameters_(std::move(parameters)), info_(std::move(info)), state_(std::move(state)),
      kernel_(parameters_.support_radius),
      carrier_cells_(parameters_.domain, parameters_.support_radius * parameters_.cell_size_factor,
                     cell_budget(state_.position.count() + state_.dummy_position.count())),
      wall_cells_(parameters_.domain,
                  std::max(parameters_.support_radius, parameters_.wall_radius) *
                      parameters_.cell_size_factor,
                  cell_budget(state_.wall_position.count())),
      density_sums_(parameters_.density_scale),
      acceleration_sums_(sums_at<typename Arith::Sums, D>(parameters_.acceleration_scale)) {
  if (parameters_.anti_clump_pressure > 0.0) {
    anti_clump_kernel_.emplace(0.5 * parameters_.dr); // App. A: support dr / 2
  }
}

template <int D, class Arith>
void Model<D, Arith>::initialise_density_constants(std::span<const double> target_density) {
  // With C_a = 0 the density is the plain kernel sum; C_a = target - that sum.
  std::fill(state_.density_constant.all().begin(), state_.density_constant.all().end(), Raw{});
  std::fill(state_.dummy_density_constant.all().begin(), state_.dummy_density_constant.all().end(),
            Raw{});
  invalidate_derived();
  update_derived();
  const std::size_t fluid = fluid_count();
  for (std::size_t a = 0; a < density_.size(); ++a) {
    auto& field = a < fluid ? state_.density_constant : state_.dummy_density_constant;
    const std::size_t i = a < fluid ? a : a - fluid;
    if (!Arith::try_from_real(target_density[a] - density_[a], field.info().scale,
                              field.at(0, i))) {
      throw SimulationFault(
          {a < fluid ? "fluid" : "dummy", i, "density_constant", "does not fit its scale"}, 0);
    }
  }
  invalidate_derived();
}

template <int D, class Arith>
std::span<const Substep<Model<D, Arith>>> Model<D, Arith>::palindrome() {
  static constexpr Substep<Model> sequence[] = {
      {"kick", 0.5, &Model::kick_substep},
      {"drift", 1.0, &Model::drift_substep},
      {"kick", 0.5, &Model::kick_substep},
  };
  return sequence;
}

template <int D, class Arith>
void Model<D, Arith>::kick(double dt) {
  update_derived();
  FaultRecorder faults;
  add_rate<Arith, D>(state_.velocity, acceleration_, dt, faults);
}

template <int D, class Arith>
void Model<D, Arith>::drift(double dt) {
  FaultRecorder faults;
  revsph::drift<Arith>(state_.position, state_.velocity, dt, faults);
  derived_valid_ = false;
}

template <int D, class Arith>
void Model<D, Arith>::reverse_time() {
  apply_time_reversal<Arith>(state_);
}

template <int D, class Arith>
void Model<D, Arith>::update_constants() {
  if (constants_valid_) {
    return;
  }
  wall_position_ = {};
  real_coordinates<Arith, D>(state_.wall_position, wall_position_, 0);
  try {
    wall_cells_.build(view_of<D>(wall_position_));
  } catch (const PointOutsideDomain& outside) {
    throw SimulationFault({"wall", outside.index(), "position", outside.what()}, -1);
  }
  const std::size_t fluid = fluid_count();
  const std::size_t dummies = state_.dummy_position.count();
  mass_.resize(fluid + dummies);
  for (std::size_t a = 0; a < fluid; ++a) {
    mass_[a] = Arith::real(state_.mass.at(0, a), state_.mass.info().scale);
  }
  for (std::size_t d = 0; d < dummies; ++d) {
    mass_[fluid + d] = Arith::real(state_.dummy_mass.at(0, d), state_.dummy_mass.info().scale);
  }
  dummy_position_ = {};
  real_coordinates<Arith, D>(state_.dummy_position, dummy_position_, 0);
  constants_valid_ = true;
}

template <int D, class Arith>
void Model<D, Arith>::update_derived() {
  if (derived_valid_) {
    return;
  }
  update_constants();
  const std::size_t fluid = fluid_count();
  const std::size_t carriers = mass_.size();
  // Straight from the fixed-point state: no copy of all coordinates in doubles.
  sort_into_cells<D>(
      carrier_cells_, carriers, [&](int axis, std::size_t a) { return real_position(axis, a); },
      [&](std::size_t a) {
        return std::pair{carrier_set(a, fluid), index_in_set(a, fluid)};
      },
      slot_position_);
  // Gather the other carrier arrays into cell order.
  const std::span<const std::uint32_t> carrier_of_slot = carrier_cells_.sorted_points();
  slot_mass_.resize(carriers);
  slot_density_constant_.resize(carriers);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < carriers; ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    slot_mass_[s] = mass_[a];
    slot_density_constant_[s] = a < fluid ? state_.density_constant.at(0, a)
                                          : state_.dummy_density_constant.at(0, a - fluid);
  }
  const CoordinateView<D> x = view_of<D>(slot_position_);
  carrier_pairs_.build<D>(carrier_cells_, x, parameters_.support_radius);
  const CoordinateView<D> wall_x = view_of<D>(wall_position_);
  find_neighbours<D>(wall_cells_, wall_x, x, parameters_.wall_radius, SelfPairs::included,
                     wall_neighbours_);

  FaultRecorder faults;
  compute_density<D, Arith>(kernel_, x, slot_mass_, slot_density_constant_, carrier_pairs_,
                            carrier_of_slot, fluid, density_sums_, slot_density_, faults);
  faults.throw_if_any();
  pressure_over_density_squared_.resize(carriers);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < carriers; ++s) {
    const double rho = slot_density_[s];
    pressure_over_density_squared_[s] =
        tait_pressure(rho, parameters_.rest_density, parameters_.sound_speed) / (rho * rho);
  }
  if (anti_clump_kernel_) {
    inverse_density_squared_.resize(carriers);
#pragma omp parallel for schedule(static)
    for (std::size_t s = 0; s < carriers; ++s) {
      inverse_density_squared_[s] = 1.0 / (slot_density_[s] * slot_density_[s]);
    }
  }
  compute_acceleration<D, Arith>(
      kernel_, x, wall_x, slot_mass_, pressure_over_density_squared_, inverse_density_squared_,
      carrier_pairs_, wall_neighbours_, carrier_of_slot, fluid, parameters_.gravity,
      parameters_.wall_potential(), anti_clump_kernel_ ? &*anti_clump_kernel_ : nullptr,
      parameters_.anti_clump_pressure, acceleration_sums_, acceleration_, faults);
  faults.throw_if_any();

  density_.resize(carriers); // in the canonical order, for the outputs
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < carriers; ++s) {
    density_[carrier_of_slot[s]] = slot_density_[s];
  }
  derived_valid_ = true;
}

template <int D, class Arith>
const std::vector<double>& Model<D, Arith>::density() {
  update_derived();
  return density_;
}

template <int D, class Arith>
const std::array<std::vector<double>, D>& Model<D, Arith>::acceleration() {
  update_derived();
  return acceleration_;
}

template <int D, class Arith>
std::array<std::vector<double>, D> Model<D, Arith>::real_velocity() const {
  std::array<std::vector<double>, D> velocity;
  const auto& scale = state_.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    velocity[k].resize(fluid_count());
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      velocity[k][a] = Arith::real(state_.velocity.at(k, a), scale);
    }
  }
  return velocity;
}

template <int D, class Arith>
std::array<std::vector<double>, D> Model<D, Arith>::filtered_velocity() {
  update_derived();
  const std::span<const std::uint32_t> carrier_of_slot = carrier_cells_.sorted_points();
  const std::size_t fluid = fluid_count();
  const std::array<std::vector<double>, D> velocity = real_velocity();
  std::array<std::vector<double>, D> slot_velocity;
  for (int k = 0; k < D; ++k) {
    slot_velocity[k].assign(carrier_of_slot.size(), 0.0);
    for (std::size_t s = 0; s < carrier_of_slot.size(); ++s) {
      if (carrier_of_slot[s] < fluid) {
        slot_velocity[k][s] = velocity[k][carrier_of_slot[s]];
      }
    }
  }
  std::array<std::vector<double>, D> slot_filtered;
  shepard_filter<D>(kernel_, view_of<D>(slot_position_), slot_mass_, slot_density_, slot_velocity,
                    carrier_pairs_, carrier_of_slot, fluid, slot_filtered);
  std::array<std::vector<double>, D> filtered;
  for (int k = 0; k < D; ++k) {
    filtered[k].resize(fluid);
    for (std::size_t s = 0; s < carrier_of_slot.size(); ++s) {
      if (carrier_of_slot[s] < fluid) {
        filtered[k][carrier_of_slot[s]] = slot_filtered[k][s];
      }
    }
  }
  return filtered;
}

template <int D, class Arith>
void Model<D, Arith>::after_step(std::int64_t step) {
  if (!parameters_.shepard_active || step % parameters_.shepard_every != 0) {
    return;
  }
  // App. A active filter: u := u~. Dissipative, so outside the reversible palindrome.
  const std::array<std::vector<double>, D> filtered = filtered_velocity();
  const auto& scale = state_.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      if (!Arith::try_from_real(filtered[k][a], scale, state_.velocity.at(k, a))) {
        throw SimulationFault({"fluid", a, "velocity", "the filtered velocity overflows"}, -1);
      }
    }
  }
}

template <int D, class Arith>
typename Model<D, Arith>::ParticleEnergies Model<D, Arith>::particle_energies() {
  update_derived();
  const WallPotential wall = parameters_.wall_potential();
  const std::array<std::vector<double>, D> velocity = real_velocity();
  const std::size_t n = fluid_count();
  ParticleEnergies energies{std::vector<double>(n),
                            std::vector<double>(n),
                            std::vector<double>(n),
                            std::vector<double>(n),
                            {}};
  for (std::size_t a = 0; a < n; ++a) {
    const double m = mass_[a];
    double v_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      v_squared += velocity[k][a] * velocity[k][a];
    }
    energies.kinetic[a] = 0.5 * m * v_squared;
    energies.gravitational[a] =
        m * parameters_.gravity * (real_position(D - 1, a) - parameters_.gravity_reference_height);
    energies.compressional[a] =
        m * compressional_energy_per_mass(density_[a], parameters_.rest_density,
                                          parameters_.sound_speed); // eq. (3)
  }
  // eq. (7), attributed to the fluid particle; the wall lists are per slot.
  const std::span<const std::uint32_t> carrier_of_slot = carrier_cells_.sorted_points();
  const CoordinateView<D> x = view_of<D>(slot_position_);
  const CoordinateView<D> wall_x = view_of<D>(wall_position_);
  for (std::size_t s = 0; s < carrier_of_slot.size(); ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    if (a >= n) {
      continue;
    }
    double wall_energy = 0.0;
    for (const std::uint32_t w : wall_neighbours_.of(s)) {
      wall_energy += mass_[a] * wall.energy_per_fluid_mass(squared_distance<D>(x, s, wall_x, w));
    }
    energies.wall[a] = wall_energy;
  }
  // Dummy particles store compressional energy too (their density follows the fluid).
  for (std::size_t d = n; d < density_.size(); ++d) {
    energies.dummy_compressional.push_back(
        mass_[d] * compressional_energy_per_mass(density_[d], parameters_.rest_density,
                                                 parameters_.sound_speed));
  }
  return energies;
}

template <int D, class Arith>
EnergyBudget Model<D, Arith>::energy() {
  const ParticleEnergies energies = particle_energies();
  // Serial sums in particle order: the same value for any thread count.
  auto total = [](const std::vector<double>& values) {
    double sum = 0.0;
    for (const double value : values) {
      sum += value;
    }
    return sum;
  };
  return EnergyBudget{
      {{"kinetic", total(energies.kinetic)},
       {"gravitational", total(energies.gravitational)},
       {"compressional", total(energies.compressional) + total(energies.dummy_compressional)},
       {"wall", total(energies.wall)}}};
}

template <int D, class Arith>
void Model<D, Arith>::derived_views(const ViewSink& sink) {
  const std::size_t fluid = fluid_count();
  const std::size_t carriers = density_.size();
  auto pressure_of = [&](std::size_t first, std::size_t end) {
    std::vector<double> pressure(end - first);
    for (std::size_t a = first; a < end; ++a) {
      pressure[a - first] =
          tait_pressure(density_[a], parameters_.rest_density, parameters_.sound_speed);
    }
    return pressure;
  };
  auto component_major = [](const std::array<std::vector<double>, D>& vectors) {
    std::vector<double> values;
    for (int k = 0; k < D; ++k) {
      values.insert(values.end(), vectors[k].begin(), vectors[k].end());
    }
    return values;
  };
  const std::string energy_unit = D == 2 ? "J/m" : "J";
  // Each view is built, handed over and freed before the next (the snapshot write is the peak of
  // a run's memory).
  auto emit = [&](const char* set, const char* name, std::string unit, int components,
                  std::vector<double>&& values) {
    sink(ParticleView{set, name, std::move(unit), components, std::move(values)});
  };
  ParticleEnergies energies = particle_energies();
  emit("fluid", "density", "kg/m^3", 1, {density_.begin(), density_.begin() + fluid});
  emit("fluid", "pressure", "Pa", 1, pressure_of(0, fluid));
  emit("fluid", "acceleration", "m/s^2", D, component_major(acceleration_));
  emit("fluid", "kinetic_energy", energy_unit, 1, std::move(energies.kinetic));
  emit("fluid", "gravitational_energy", energy_unit, 1, std::move(energies.gravitational));
  emit("fluid", "compressional_energy", energy_unit, 1, std::move(energies.compressional));
  emit("fluid", "wall_energy", energy_unit, 1, std::move(energies.wall));
  if (parameters_.shepard_every > 0) {
    emit("fluid", "filtered_velocity", "m/s", D, component_major(filtered_velocity()));
  }
  if (carriers > fluid) {
    emit("dummy", "density", "kg/m^3", 1, {density_.begin() + fluid, density_.end()});
    emit("dummy", "pressure", "Pa", 1, pressure_of(fluid, carriers));
    emit("dummy", "compressional_energy", energy_unit, 1, std::move(energies.dummy_compressional));
  }
}

template <int D, class Arith>
std::vector<EnergyTerm> Model<D, Arith>::diagnostics() {
  if (parameters_.initial_field != InitialField::gresho_vortex) {
    return {};
  }
  // Paper 1 eq. (11) at this instant: sqrt(75 / (4 pi) sum_a V_a |u_a - u0(r_a)|^2), for the
  // velocity and for its Shepard-filtered field; the error of a run is the maximum over time.
  update_derived();
  const std::array<std::vector<double>, D> velocity = real_velocity();
  const std::array<std::vector<double>, D> filtered = filtered_velocity();
  double raw_sum = 0.0;
  double filtered_sum = 0.0;
  for (std::size_t a = 0; a < fluid_count(); ++a) {
    const auto [exact_x, exact_y] = gresho::velocity(real_position(0, a) - parameters_.centre[0],
                                                     real_position(1, a) - parameters_.centre[1]);
    const double volume = mass_[a] / density_[a];
    raw_sum += volume * ((velocity[0][a] - exact_x) * (velocity[0][a] - exact_x) +
                         (velocity[1][a] - exact_y) * (velocity[1][a] - exact_y));
    filtered_sum += volume * ((filtered[0][a] - exact_x) * (filtered[0][a] - exact_x) +
                              (filtered[1][a] - exact_y) * (filtered[1][a] - exact_y));
  }
  return {{"velocity_error", std::sqrt(raw_sum / gresho::velocity_norm_squared)},
          {"filtered_velocity_error", std::sqrt(filtered_sum / gresho::velocity_norm_squared)}};
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::wcsph
