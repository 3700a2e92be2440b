#include "models/shtc/model.hpp"

#include "core/case_values.hpp"
#include "core/verlet.hpp"
#include "models/shtc/elastic_energy.hpp"
#include "models/shtc/forces.hpp"
#include "models/shtc/mirrored_walls.hpp"
#include "models/shtc/relaxation.hpp"
#include "models/shtc/tensile_penalty.hpp"
#include "models/shtc/velocity_gradient.hpp"

#include <algorithm>
#include <cmath>

namespace revsph::shtc {

namespace {

constexpr int mass_fraction_bits = 52; // masses are constants; their double view stays exact

} // namespace

template <int D>
Model<D>::Model(Parameters<D> parameters, SimulationInfo info, State<D> state,
                std::optional<std::size_t> probe_particle)
    : parameters_(std::move(parameters)), info_(std::move(info)), state_(std::move(state)),
      probe_particle_(probe_particle), kernel_(parameters_.support_radius()),
      sum_scales_(sum_scales(parameters_.density_scale, parameters_.material.rest_density,
                             parameters_.material.sound_speed, parameters_.penalty_speed,
                             parameters_.support_radius())),
      layout_(parameters_.domain, parameters_.support_radius() * parameters_.cell_size_factor,
              {{"material", state_.material.position.count()},
               {"boundary", state_.boundary.position.count()}}),
      sums_(sum_scales_.density),
      acceleration_sums_(acceleration_sums<D>(sum_scales_.acceleration)),
      gradients_(sum_scales_.velocity_sum),
      mirror_sums_(mirror_sums<D>(sum_scales_.density, sum_scales_.mirror_velocity_sum)) {}

template <int D>
std::span<const Substep<Model<D>>> Model<D>::palindrome() {
  static constexpr Substep<Model> sequence[] = {
      {"relaxation", 0.5, &Model::relaxation_substep, &Model::relaxation_irreversibility},
      {"kick", 0.5, &Model::kick_substep},
      {"drift", 0.5, &Model::drift_substep},
      {"distortion", 1.0, &Model::distortion_substep, &Model::distortion_irreversibility},
      {"drift", 0.5, &Model::drift_substep},
      {"kick", 0.5, &Model::kick_substep},
      {"relaxation", 0.5, &Model::relaxation_substep, &Model::relaxation_irreversibility},
  };
  return sequence;
}

template <int D>
std::string Model<D>::relaxation_description() const {
  return "relaxation of the distortion, tau = " +
         format_scientific(*parameters_.relaxation_time, 3) + " s (paper 2 eqs. 51-53)";
}

template <int D>
std::string Model<D>::distortion_irreversibility(const Model& model) {
  std::string what;
  if (model.parameters_.cayley_distortion_update) {
    what = "the paper's Cayley distortion update (eq. 49), rounded to fixed point: not exactly "
           "invertible";
  }
  if (model.parameters_.relaxation_time && !model.parameters_.relaxation_splitting.at_step_ends) {
    what += (what.empty() ? "" : "; ") + model.relaxation_description() + " after the update";
  }
  return what;
}

template <int D>
std::string Model<D>::relaxation_irreversibility(const Model& model) {
  if (model.parameters_.relaxation_time && model.parameters_.relaxation_splitting.at_step_ends) {
    return model.relaxation_description() + " at the step's ends";
  }
  return "";
}

template <int D>
double Model<D>::real_position(int axis, std::size_t a) const {
  return a < material_count()
             ? fixedpoint::to_real(state_.material.position.at(axis, a),
                                   state_.material.position.info().scale)
             : fixedpoint::to_real(state_.boundary.position.at(axis, a - material_count()),
                                   state_.boundary.position.info().scale);
}

template <int D>
ExactDistortion<D> Model<D>::distortion_of(std::size_t a) {
  const CarrierFields<D>& set = set_of(a);
  const std::size_t i = index_in_set(a);
  ExactDistortion<D> distortion;
  distortion.log_det = set.log_det.at(0, i);
  for (int c = 0; c < D * D; ++c) {
    distortion.unimodular[c] = set.unimodular.at(c, i);
  }
  return distortion;
}

template <int D>
void Model<D>::store_distortion(std::size_t a, const ExactDistortion<D>& distortion) {
  CarrierFields<D>& set = set_of(a);
  const std::size_t i = index_in_set(a);
  set.log_det.at(0, i) = distortion.log_det;
  for (int c = 0; c < D * D; ++c) {
    set.unimodular.at(c, i) = distortion.unimodular[c];
  }
}

template <int D>
Vec<D> Model<D>::wall_velocity_now(std::size_t i) const {
  const std::int64_t clock = state_.boundary.drive_time.at(0, i);
  Vec<D> v{};
  if (clock == 0) {
    return v;
  }
  const double time = fixedpoint::to_real(clock, state_.boundary.drive_time.info().scale);
  // Odd in the clock: a reversed run pretends the opposite velocity at the same |t|.
  const double factor = std::copysign(parameters_.drive_ramp(std::fabs(time)), time);
  for (int k = 0; k < D; ++k) {
    v[k] = factor * fixedpoint::to_real(state_.boundary.wall_velocity.at(k, i),
                                        state_.boundary.wall_velocity.info().scale);
  }
  return v;
}

template <int D>
void Model<D>::initialise_constants() {
  const std::size_t n = carrier_count();
  // Equal trial masses m0 and no constants: the density sums are then m0 sum_b w_ab, and
  // m_a = rho0 V_a = rho0 m0 / that. m0 = rho0 / w(0) keeps the trial sums near rho0 (a few times
  // it, as many as there are neighbours), within the density scale's range.
  const double trial_mass = parameters_.material.rest_density / kernel_.value(0.0);
  mass_.assign(n, trial_mass);
  density_constant_.assign(n, 0);
  lambda_constant_.assign(n, 0);
  for (CarrierFields<D>* set : {&state_.material.carried, &state_.boundary.carried}) {
    set->density_constant.set_scale(parameters_.density_scale);
    set->lambda_constant.set_scale(parameters_.density_scale);
    std::fill(set->density_constant.all().begin(), set->density_constant.all().end(), 0);
    std::fill(set->lambda_constant.all().begin(), set->lambda_constant.all().end(), 0);
  }
  constants_valid_ = true;
  geometry_valid_ = false;
  update_geometry();
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  std::vector<double> mass(n);
  for (std::size_t s = 0; s < n; ++s) {
    mass[carrier_of_slot[s]] = parameters_.material.rest_density * trial_mass / sums_.density[s];
  }
  const double largest = *std::max_element(mass.begin(), mass.end());
  const fixedpoint::Scale mass_scale = fixedpoint::Scale::covering(largest, mass_fraction_bits);
  for (CarrierFields<D>* set : {&state_.material.carried, &state_.boundary.carried}) {
    set->mass.set_scale(mass_scale);
  }
  for (std::size_t a = 0; a < n; ++a) {
    fixedpoint::try_to_fixed(mass[a], mass_scale, set_of(a).mass.at(0, index_in_set(a)));
  }
  // The sums with the stored masses give the constants.
  invalidate_derived();
  update_geometry();
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t a = carrier_of_slot[s];
    CarrierFields<D>& set = set_of(a);
    const std::size_t i = index_in_set(a);
    if (!fixedpoint::try_to_fixed(parameters_.material.rest_density - sums_.density[s],
                                  parameters_.density_scale, set.density_constant.at(0, i)) ||
        !fixedpoint::try_to_fixed(-sums_.lambda[s], parameters_.density_scale,
                                  set.lambda_constant.at(0, i))) {
      throw SimulationFault({set_name(a), i, "density_constant", "does not fit its scale"}, 0);
    }
  }
  invalidate_derived();
}

template <int D>
void Model<D>::kick(double dt) {
  update_force();
  FaultRecorder faults;
  add_rate<FixedArithmetic, D>(state_.material.velocity, acceleration_, dt, faults);
}

template <int D>
void Model<D>::drift(double dt) {
  FaultRecorder faults;
  revsph::drift<FixedArithmetic>(state_.material.position, state_.material.velocity, dt, faults);
  // The walls' clock runs forward by dt whatever the direction of time: drive_time holds the
  // direction in its sign (state.hpp), so R drift R drift = id holds for it too.
  const auto tick = static_cast<std::int64_t>(
      std::llround(dt / fixedpoint::to_real(1, state_.boundary.drive_time.info().scale)));
  for (std::int64_t& clock : state_.boundary.drive_time.all()) {
    clock += tick;
  }
  geometry_valid_ = false;
  force_valid_ = false;
}

template <int D>
void Model<D>::update_carrier_velocities() {
  update_geometry();
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t n = carrier_count();
  const std::size_t material = material_count();
  const auto& v_scale = state_.material.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    slot_velocity_[k].resize(n);
  }
  slot_is_wall_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    slot_is_wall_[s] = a >= material;
    const Vec<D> wall = a < material ? Vec<D>{} : wall_velocity_now(a - material);
    for (int k = 0; k < D; ++k) {
      slot_velocity_[k][s] =
          a < material ? fixedpoint::to_real(state_.material.velocity.at(k, a), v_scale) : wall[k];
    }
  }
  if (parameters_.mirrored_walls) {
    slot_mirrored_velocity_ = slot_velocity_;
    mirror_wall_velocities<D>(kernel_, layout_, slot_mass_, slot_is_wall_, slot_mirrored_velocity_,
                              mirror_sums_);
  }
}

template <int D>
void Model<D>::update_distortion(double dt) {
  update_carrier_velocities();
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t n = carrier_count();
  const bool driven = walls_work();
  if (driven) {
    wall_forces(wall_force_before_);
  }
  // Eq. (10) with the velocities the walls pretend: their own (the paper's way) for every carrier,
  // or, with mirrored walls, the mirrored ones in the material's L while the walls' own L keeps
  // v_w (mirrored_walls.hpp).
  const CoordinateView<D> velocity = view_of<D>(slot_velocity_);
  const SeenVelocities<D> seen =
      parameters_.mirrored_walls
          ? SeenVelocities<D>{view_of<D>(slot_mirrored_velocity_), velocity, slot_is_wall_}
          : SeenVelocities<D>{velocity, velocity, {}};
  velocity_gradients<D>(kernel_, layout_, seen, slot_mass_, sums_.h_inverse, gradients_);
  FaultRecorder faults;
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    ExactDistortion<D> distortion = distortion_of(a);
    // dt L is odd in v bit for bit: the update with -dt L undoes this one exactly.
    const Matrix<D> step = dt * gradients_.gradient[s];
    const DistortionScales& scales = parameters_.distortion_scales;
    const bool updated =
        parameters_.cayley_distortion_update
            ? try_make_distortion<D>(cayley_update<D>(to_matrix<D>(distortion, scales), step),
                                     scales, distortion)
            : try_update_distortion<D>(distortion, step, scales);
    if (!updated) {
      faults.record(index_in_set(a), set_name(a), "distortion",
                    "overflow or non-finite value in the distortion update");
      continue;
    }
    store_distortion(a, distortion);
  }
  faults.throw_if_any();
  force_valid_ = false;
  if (driven) {
    wall_forces(wall_force_after_);
    if (!add_wall_work(dt)) {
      throw SimulationFault({"boundary", 0, "wall_work", "does not fit its fixed-point scale"}, 0);
    }
  }
  if (parameters_.relaxation_time && !parameters_.relaxation_splitting.at_step_ends) {
    relax_all(dt); // eq. (52d), after the update
  }
}

template <int D>
void Model<D>::relax_at_step_end(double dt) {
  if (parameters_.relaxation_time && parameters_.relaxation_splitting.at_step_ends) {
    relax_all(dt);
  }
}

template <int D>
void Model<D>::relax_all(double dt) {
  FaultRecorder faults;
  const std::size_t n = carrier_count();
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    ExactDistortion<D> distortion = distortion_of(a);
    CarrierFields<D>& set = set_of(a);
    const std::size_t i = index_in_set(a);
    if (!relax(distortion, set.dissipated_energy.at(0, i), dt)) {
      faults.record(i, set_name(a), "distortion", "overflow or non-finite value in the relaxation");
      continue;
    }
    store_distortion(a, distortion);
  }
  faults.throw_if_any();
  force_valid_ = false;
}

template <int D>
bool Model<D>::relax(ExactDistortion<D>& distortion, std::int64_t& dissipated, double dt) const {
  // Eq. (52d) after the reversible update (52c); the shear energy it removes is added to the
  // particle's dissipated energy, so that the budget of energy() closes.
  const ElasticMaterial& material = parameters_.material;
  const Matrix<D> before = to_matrix<D>(distortion, parameters_.distortion_scales);
  const Matrix<D> after =
      relax_distortion<D>(material, parameters_.relaxation_splitting, before, dt);
  const double removed = shear_energy<D>(material, before) - shear_energy<D>(material, after);
  return try_make_distortion<D>(after, parameters_.distortion_scales, distortion) &&
         FixedArithmetic::try_increment(dissipated, removed, parameters_.dissipated_scale);
}

template <int D>
void Model<D>::reverse_time() {
  apply_time_reversal<FixedArithmetic>(state_);
}

template <int D>
void Model<D>::update_constants() {
  if (constants_valid_) {
    return;
  }
  mass_ =
      CarrierField<FixedArithmetic>{&state_.material.carried.mass, &state_.boundary.carried.mass}
          .reals();
  density_constant_ = CarrierField<FixedArithmetic>{&state_.material.carried.density_constant,
                                                    &state_.boundary.carried.density_constant}
                          .raws();
  lambda_constant_ = CarrierField<FixedArithmetic>{&state_.material.carried.lambda_constant,
                                                   &state_.boundary.carried.lambda_constant}
                         .raws();
  // Mirrored walls pretend velocities even at rest, and do work.
  walls_work_ = any_wall_moves(state_) ||
                (parameters_.mirrored_walls && state_.boundary.position.count() > 0);
  constants_valid_ = true;
}

template <int D>
void Model<D>::update_geometry() {
  if (geometry_valid_) {
    return;
  }
  update_constants();
  const std::size_t n = carrier_count();
  layout_.build(carrier_position(), parameters_.support_radius());
  layout_.gather(std::span<const double>(mass_), slot_mass_);
  layout_.gather(std::span<const std::int64_t>(density_constant_), slot_density_constant_);
  layout_.gather(std::span<const std::int64_t>(lambda_constant_), slot_lambda_constant_);
  compute_kernel_sums<D>(kernel_, layout_, slot_mass_, slot_density_constant_,
                         slot_lambda_constant_, sums_);
  FaultRecorder faults;
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    if (!(sums_.density[s] > 0.0)) {
      layout_.record_fault(faults, s, "density", "density not positive");
    }
  }
  faults.throw_if_any();
  geometry_valid_ = true;
}

template <int D>
void Model<D>::update_force() {
  if (force_valid_) {
    return;
  }
  update_geometry();
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t n = carrier_count();
  slot_distortion_.resize(n);
  slot_stress_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    slot_distortion_[s] =
        to_matrix<D>(distortion_of(carrier_of_slot[s]), parameters_.distortion_scales);
    slot_stress_[s] = stress<D>(parameters_.material, sums_.density[s], slot_distortion_[s],
                                sums_.h_inverse[s]); // eq. (21b)
  }
  const PenaltyParameters penalty{parameters_.penalty_speed, parameters_.material.rest_density};
  compute_acceleration<D>(kernel_, penalty_strength(penalty), layout_, slot_mass_, slot_stress_,
                          sums_.lambda, acceleration_sums_, slot_acceleration_);
  const std::size_t material = material_count();
  FaultRecorder faults;
  for (int k = 0; k < D; ++k) {
    acceleration_[k].resize(material);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    if (a >= material) {
      continue; // boundary particles are held in place
    }
    for (int k = 0; k < D; ++k) {
      acceleration_[k][a] = slot_acceleration_[k][s];
      if (!std::isfinite(slot_acceleration_[k][s])) {
        faults.record(a, "material", "acceleration", "non-finite acceleration");
      }
    }
  }
  faults.throw_if_any();
  force_valid_ = true;
}

template <int D>
const CoordinateArrays<D>& Model<D>::acceleration() {
  update_force();
  return acceleration_;
}

template <int D>
typename Model<D>::CarrierValues Model<D>::carrier_values() {
  update_force();
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t n = carrier_count();
  CarrierValues values{std::vector<double>(n), std::vector<double>(n), std::vector<Matrix<D>>(n)};
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    values.density[a] = sums_.density[s];
    values.lambda[a] = sums_.lambda[s];
    values.distortion[a] = slot_distortion_[s];
  }
  return values;
}

template <int D>
typename Model<D>::ParticleEnergies Model<D>::particle_energies(const CarrierValues& values) {
  const std::size_t n = carrier_count();
  const ElasticMaterial& material = parameters_.material;
  const double cp = parameters_.penalty_speed;
  ParticleEnergies energies{std::vector<double>(n, 0.0), std::vector<double>(n),
                            std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  const auto& v_scale = state_.material.velocity.info().scale;
  for (std::size_t a = 0; a < n; ++a) {
    const double m = mass_[a];
    if (a < material_count()) {
      double v_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double v = fixedpoint::to_real(state_.material.velocity.at(k, a), v_scale);
        v_squared += v * v;
      }
      energies.kinetic[a] = 0.5 * m * v_squared;
    }
    energies.bulk[a] = m * bulk_energy(material, values.density[a]);         // eq. (29)
    energies.shear[a] = m * shear_energy<D>(material, values.distortion[a]); // eq. (31), (35)
    const double relative = values.lambda[a] / material.rest_density;
    energies.penalty[a] = 0.5 * m * cp * cp * relative * relative; // eq. (39)
    const auto& dissipated = set_of(a).dissipated_energy;
    energies.dissipated[a] =
        m * fixedpoint::to_real(dissipated.at(0, index_in_set(a)), dissipated.info().scale);
  }
  return energies;
}

template <int D>
EnergyBudget Model<D>::energy() {
  const ParticleEnergies energies = particle_energies(carrier_values());
  // Serial sums in particle order: the same value for any thread count.
  auto total = [](const std::vector<double>& values) {
    double sum = 0.0;
    for (const double value : values) {
      sum += value;
    }
    return sum;
  };
  EnergyBudget budget{{{"kinetic", total(energies.kinetic)},
                       {"volumetric", total(energies.bulk)},
                       {"shear", total(energies.shear)},
                       {"penalty", total(energies.penalty)}}};
  if (parameters_.relaxation_time) {
    budget.terms.push_back({"dissipated", total(energies.dissipated)});
  }
  if (walls_work()) {
    // What the walls have put in, counted negative: the total stays constant.
    double work = 0.0;
    for (std::size_t i = 0; i < state_.boundary.position.count(); ++i) {
      work +=
          mass_[material_count() + i] * fixedpoint::to_real(state_.boundary.wall_work.at(0, i),
                                                            state_.boundary.wall_work.info().scale);
    }
    budget.terms.push_back({"wall_work", -work});
  }
  return budget;
}

template <int D>
void Model<D>::derived_views(const ViewSink& sink) {
  const CarrierValues values = carrier_values();
  ParticleEnergies energies = particle_energies(values);
  const std::string energy_unit = D == 2 ? "J/m" : "J";
  const std::size_t material = material_count();
  const std::size_t n = carrier_count();
  struct Range {
    const char* set;
    std::size_t first, end;
  };
  for (const Range range : {Range{"material", 0, material}, Range{"boundary", material, n}}) {
    if (range.first == range.end) {
      continue;
    }
    auto slice = [&](const std::vector<double>& all) {
      return std::vector<double>(all.begin() + range.first, all.begin() + range.end);
    };
    const std::size_t count = range.end - range.first;
    std::vector<double> pressure_values(count);
    std::vector<double> distortion(count * D * D);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t a = range.first + i;
      pressure_values[i] = pressure(parameters_.material, values.density[a]); // eq. (30)
      for (int r = 0; r < D; ++r) {
        for (int c = 0; c < D; ++c) {
          distortion[static_cast<std::size_t>(r * D + c) * count + i] = values.distortion[a](r, c);
        }
      }
    }
    sink(ParticleView{range.set, "density", "kg/m^3", 1, slice(values.density)});
    sink(ParticleView{range.set, "pressure", "Pa", 1, std::move(pressure_values)});
    sink(ParticleView{range.set, "lambda", "kg/m^3", 1, slice(values.lambda)});
    sink(ParticleView{range.set, "distortion", "1", D * D, std::move(distortion)});
    if (range.first != 0 && walls_work()) {
      update_carrier_velocities();
      const CoordinateArrays<D>& seen = slot_velocity_seen();
      const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
      std::vector<double> wall(count * D);
      for (std::size_t s = 0; s < carrier_of_slot.size(); ++s) {
        const std::size_t a = carrier_of_slot[s];
        if (a >= range.first) {
          for (int k = 0; k < D; ++k) {
            wall[static_cast<std::size_t>(k) * count + (a - range.first)] = seen[k][s];
          }
        }
      }
      sink(ParticleView{range.set, "velocity", "m/s", D, std::move(wall)});
    }
    if (range.first == 0) {
      std::vector<double> acceleration_values;
      for (int k = 0; k < D; ++k) {
        acceleration_values.insert(acceleration_values.end(), acceleration_[k].begin(),
                                   acceleration_[k].end());
      }
      sink(ParticleView{range.set, "acceleration", "m/s^2", D, std::move(acceleration_values)});
      sink(ParticleView{range.set, "kinetic_energy", energy_unit, 1, slice(energies.kinetic)});
    }
    sink(ParticleView{range.set, "volumetric_energy", energy_unit, 1, slice(energies.bulk)});
    sink(ParticleView{range.set, "shear_energy", energy_unit, 1, slice(energies.shear)});
    sink(ParticleView{range.set, "penalty_energy", energy_unit, 1, slice(energies.penalty)});
    if (parameters_.relaxation_time) {
      sink(
          ParticleView{range.set, "dissipated_energy", energy_unit, 1, slice(energies.dissipated)});
    }
  }
}

template <int D>
void Model<D>::shear_accelerations(CoordinateArrays<D>& acceleration, StressOf carriers) {
  update_geometry();
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t n = carrier_count();
  const std::size_t material = material_count();
  slot_shear_stress_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    const bool counted =
        carriers == StressOf::all || (carriers == StressOf::material) == (a < material);
    if (!counted) {
      slot_shear_stress_[s].setZero();
      continue;
    }
    const Matrix<D> distortion = to_matrix<D>(distortion_of(a), parameters_.distortion_scales);
    slot_shear_stress_[s] = shear_stress<D>(parameters_.material, distortion, sums_.h_inverse[s]);
  }
  compute_acceleration<D>(kernel_, 0.0, layout_, slot_mass_, slot_shear_stress_, sums_.lambda,
                          acceleration_sums_, acceleration);
}

template <int D>
void Model<D>::wall_forces(WallForces& forces) {
  if (parameters_.mirrored_walls) {
    shear_accelerations(forces.from_material, StressOf::material);
    shear_accelerations(forces.from_walls, StressOf::walls);
  } else {
    shear_accelerations(forces.from_walls, StressOf::all);
  }
}

template <int D>
double Model<D>::wall_power() {
  update_carrier_velocities();
  WallForces forces;
  wall_forces(forces);
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t material = material_count();
  std::vector<double> power(carrier_count() - material, 0.0);
  for (std::size_t s = 0; s < carrier_count(); ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    if (a < material) {
      continue;
    }
    // The material's stress pairs with the velocity the material sees the wall move with, the
    // wall's own with the wall's velocity (model.hpp); without mirroring both are v_w and
    // from_walls holds the whole force.
    for (int k = 0; k < D; ++k) {
      power[a - material] -= slot_mass_[s] * forces.from_walls[k][s] * slot_velocity_[k][s];
      if (parameters_.mirrored_walls) {
        power[a - material] -=
            slot_mass_[s] * forces.from_material[k][s] * slot_mirrored_velocity_[k][s];
      }
    }
  }
  double total = 0.0; // serial, in canonical order: the same for any thread count
  for (const double p : power) {
    total += p;
  }
  return total;
}

template <int D>
bool Model<D>::add_wall_work(double dt) {
  const std::span<const std::uint32_t> carrier_of_slot = layout_.carrier_of_slot();
  const std::size_t material = material_count();
  bool fits = true;
  for (std::size_t s = 0; s < carrier_count(); ++s) {
    const std::uint32_t a = carrier_of_slot[s];
    if (a < material) {
      continue;
    }
    // Odd in (v, dt-direction) and symmetric in before/after, so a reversed step removes
    // exactly what this one added.
    const WallForces& before = wall_force_before_;
    const WallForces& after = wall_force_after_;
    double work = 0.0;
    for (int k = 0; k < D; ++k) {
      work -= (before.from_walls[k][s] + after.from_walls[k][s]) * slot_velocity_[k][s];
      if (parameters_.mirrored_walls) {
        work -= (before.from_material[k][s] + after.from_material[k][s]) *
                slot_mirrored_velocity_[k][s];
      }
    }
    fits = fits &&
           FixedArithmetic::try_increment(state_.boundary.wall_work.at(0, a - material),
                                          0.5 * dt * work, state_.boundary.wall_work.info().scale);
  }
  return fits;
}

template <int D>
std::vector<EnergyTerm> Model<D>::diagnostics() {
  std::vector<EnergyTerm> terms;
  if (probe_particle_) {
    static constexpr const char* names[] = {"probe_x", "probe_y", "probe_z"};
    for (int k = 0; k < D; ++k) {
      terms.push_back({names[k], real_position(k, *probe_particle_)});
    }
  }
  // Angular momentum of the material about the origin, eq. (26) (conserved without boundary
  // particles; the twisting column's changes sign when its rotation reverses). Serial sum in
  // particle order: the same for any thread count.
  update_constants();
  Vec<3> angular{};
  const auto& v_scale = state_.material.velocity.info().scale;
  for (std::size_t a = 0; a < material_count(); ++a) {
    Vec<3> x{};
    Vec<3> v{};
    for (int k = 0; k < D; ++k) {
      x[k] = real_position(k, a);
      v[k] = fixedpoint::to_real(state_.material.velocity.at(k, a), v_scale);
    }
    angular[0] += mass_[a] * (x[1] * v[2] - x[2] * v[1]);
    angular[1] += mass_[a] * (x[2] * v[0] - x[0] * v[2]);
    angular[2] += mass_[a] * (x[0] * v[1] - x[1] * v[0]);
  }
  if constexpr (D == 2) {
    terms.push_back({"angular_momentum", angular[2]});
  } else {
    terms.push_back({"angular_momentum_x", angular[0]});
    terms.push_back({"angular_momentum_y", angular[1]});
    terms.push_back({"angular_momentum_z", angular[2]});
  }
  if (walls_work()) {
    terms.push_back({"wall_power", wall_power()});
  }
  return terms;
}

template class Model<2>;
template class Model<3>;

} // namespace revsph::shtc
