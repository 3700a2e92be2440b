#include "models/wcsph/model.hpp"

#include "core/verlet.hpp"
#include "models/wcsph/equations.hpp"
#include "models/wcsph/forces.hpp"

#include <algorithm>

namespace revsph::wcsph {

namespace {

// At most a few cells per particle, so a large empty domain cannot exhaust memory.
std::size_t cell_budget(std::size_t particles) {
  return 4 * particles + 4096;
}

template <class Arith, int D>
void real_coordinates(const StateField<typename Arith::Raw>& field, CoordinateArrays<D>& out) {
  for (int k = 0; k < D; ++k) {
    const auto raw = field.component(k);
    out[k].resize(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
      out[k][i] = Arith::real(raw[i], field.info().scale);
    }
  }
}

} // namespace

template <int D, class Arith>
Model<D, Arith>::Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state)
    : parameters_(std::move(parameters)), info_(std::move(info)), state_(std::move(state)),
      kernel_(parameters_.support_radius),
      fluid_cells_(parameters_.domain, parameters_.support_radius * parameters_.cell_size_factor,
                   cell_budget(state_.position.count())),
      wall_cells_(parameters_.domain,
                  std::max(parameters_.support_radius, parameters_.wall_radius) *
                      parameters_.cell_size_factor,
                  cell_budget(state_.wall_position.count())) {
  // Eq. (5): with C_a = 0 the density is the plain kernel sum; C_a = rho0 - that sum makes
  // rho_a(0) = rho0 for every particle.
  std::fill(state_.density_constant.all().begin(), state_.density_constant.all().end(), Raw{});
  update_derived();
  auto constant = state_.density_constant.component(0);
  const auto& scale = state_.density_constant.info().scale;
  for (std::size_t a = 0; a < constant.size(); ++a) {
    if (!Arith::try_from_real(parameters_.rest_density - density_[a], scale, constant[a])) {
      throw SimulationFault({"fluid", a, "density_constant", "does not fit its scale"}, 0);
    }
  }
  derived_valid_ = false;
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
void Model<D, Arith>::update_derived() {
  if (derived_valid_) {
    return;
  }
  update_walls();
  real_coordinates<Arith, D>(state_.position, position_);
  const CoordinateView<D> x = view_of<D>(position_);
  const CoordinateView<D> wall_x = view_of<D>(wall_position_);
  try {
    fluid_cells_.build(x);
  } catch (const PointOutsideDomain& outside) {
    throw SimulationFault(
        {"fluid", outside.index(), "position", "left the domain: " + std::string(outside.what())},
        -1);
  }
  find_neighbours<D>(fluid_cells_, x, x, parameters_.support_radius, SelfPairs::excluded,
                     fluid_neighbours_);
  find_neighbours<D>(wall_cells_, wall_x, x, parameters_.wall_radius, SelfPairs::included,
                     wall_neighbours_);

  FaultRecorder faults;
  compute_density<D, Arith>(kernel_, x, mass_, state_.density_constant, fluid_neighbours_,
                            parameters_.density_scale, density_, faults);
  faults.throw_if_any();
  pressure_over_density_squared_.resize(density_.size());
  for (std::size_t a = 0; a < density_.size(); ++a) {
    const double rho = density_[a];
    pressure_over_density_squared_[a] =
        tait_pressure(rho, parameters_.rest_density, parameters_.sound_speed) / (rho * rho);
  }
  compute_acceleration<D, Arith>(kernel_, x, wall_x, mass_, pressure_over_density_squared_,
                                 fluid_neighbours_, wall_neighbours_, parameters_.gravity,
                                 parameters_.wall_potential(), parameters_.acceleration_scale,
                                 acceleration_, faults);
  faults.throw_if_any();
  derived_valid_ = true;
}

template <int D, class Arith>
void Model<D, Arith>::update_walls() {
  if (walls_valid_) {
    return;
  }
  real_coordinates<Arith, D>(state_.wall_position, wall_position_);
  try {
    wall_cells_.build(view_of<D>(wall_position_));
  } catch (const PointOutsideDomain& outside) {
    throw SimulationFault({"wall", outside.index(), "position", outside.what()}, -1);
  }
  mass_.resize(state_.mass.count());
  for (std::size_t a = 0; a < mass_.size(); ++a) {
    mass_[a] = Arith::real(state_.mass.at(0, a), state_.mass.info().scale);
  }
  walls_valid_ = true;
}

template <int D, class Arith>
typename Model<D, Arith>::ParticleEnergies Model<D, Arith>::particle_energies() {
  update_derived();
  const WallPotential wall = parameters_.wall_potential();
  const auto& velocity_scale = state_.velocity.info().scale;
  const std::size_t n = mass_.size();
  ParticleEnergies energies{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n),
                            std::vector<double>(n)};
  for (std::size_t a = 0; a < n; ++a) {
    const double m = mass_[a];
    double v_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double v = Arith::real(state_.velocity.at(k, a), velocity_scale);
      v_squared += v * v;
    }
    energies.kinetic[a] = 0.5 * m * v_squared;
    energies.gravitational[a] =
        m * parameters_.gravity * (position_[D - 1][a] - parameters_.gravity_reference_height);
    energies.compressional[a] =
        m * compressional_energy_per_mass(density_[a], parameters_.rest_density,
                                          parameters_.sound_speed); // eq. (3)
    double wall_energy = 0.0; // eq. (7), attributed to the fluid particle
    for (const std::uint32_t w : wall_neighbours_.of(a)) {
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = position_[k][a] - wall_position_[k][w];
        r_squared += d * d;
      }
      wall_energy += m * wall.energy_per_fluid_mass(r_squared);
    }
    energies.wall[a] = wall_energy;
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
  return EnergyBudget{{{"kinetic", total(energies.kinetic)},
                       {"gravitational", total(energies.gravitational)},
                       {"compressional", total(energies.compressional)},
                       {"wall", total(energies.wall)}}};
}

template <int D, class Arith>
std::vector<ParticleView> Model<D, Arith>::derived_views() {
  ParticleEnergies energies = particle_energies();
  std::vector<double> pressure(density_.size());
  for (std::size_t a = 0; a < pressure.size(); ++a) {
    pressure[a] = tait_pressure(density_[a], parameters_.rest_density, parameters_.sound_speed);
  }
  std::vector<double> acceleration;
  for (int k = 0; k < D; ++k) {
    acceleration.insert(acceleration.end(), acceleration_[k].begin(), acceleration_[k].end());
  }
  const std::string energy_unit = D == 2 ? "J/m" : "J";
  return {{"fluid", "density", "kg/m^3", 1, density_},
          {"fluid", "pressure", "Pa", 1, std::move(pressure)},
          {"fluid", "acceleration", "m/s^2", D, std::move(acceleration)},
          {"fluid", "kinetic_energy", energy_unit, 1, std::move(energies.kinetic)},
          {"fluid", "gravitational_energy", energy_unit, 1, std::move(energies.gravitational)},
          {"fluid", "compressional_energy", energy_unit, 1, std::move(energies.compressional)},
          {"fluid", "wall_energy", energy_unit, 1, std::move(energies.wall)}};
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
const NeighbourList& Model<D, Arith>::fluid_neighbours() {
  update_derived();
  return fluid_neighbours_;
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::wcsph
