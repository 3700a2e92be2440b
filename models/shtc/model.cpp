#include "models/shtc/model.hpp"

#include "core/case_values.hpp"
#include "core/particle_update.hpp"
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

namespace {} // namespace

template <int D>
Model<D>::Model(Parameters<D> parameters, SimulationInfo info, State<D> state,
                std::optional<std::size_t> probe_particle)
    : Parts(std::move(parameters), std::move(info), std::move(state)),
      probe_particle_(probe_particle), kernel_(parameters_.support_radius()),
      sum_scales_(sum_scales(parameters_.density_scale, parameters_.material.rest_density,
                             parameters_.material.sound_speed, parameters_.penalty_speed,
                             parameters_.support_radius())),
      layout_(parameters_.domain, parameters_.support_radius() * parameters_.cell_size_factor,
              carrier_sets(state_.material, state_.boundary)),
      sums_(sum_scales_.density),
      acceleration_sums_(acceleration_sums<D>(sum_scales_.acceleration)),
      gradients_(sum_scales_.velocity_sum),
      mirror_sums_(mirror_sums<D>(sum_scales_.density, sum_scales_.mirror_velocity_sum)) {}

template <int D>
std::span<const Substep<Model<D>>> Model<D>::palindrome() {
  static constexpr Substep<Model> sequence[] = {
      {"kick", 0.5, &Model::kick},
      {"drift", 0.5, &Model::drift},
      {"distortion", 1.0, &Model::update_distortion, &Model::distortion_irreversibility},
      {"drift", 0.5, &Model::drift},
      {"kick", 0.5, &Model::kick},
  };
  return sequence;
}

template <int D>
std::span<const IrreversibleOperator<Model<D>>> Model<D>::irreversible_operators() {
  static constexpr IrreversibleOperator<Model> operators[] = {
      {"relaxation", &Model::relax_all, &Model::relaxation_irreversibility}};
  return operators;
}

template <int D>
std::string Model<D>::relaxation_description() const {
  return "relaxation of the distortion, tau = " +
         format_scientific(*parameters_.relaxation_time, 3) + " s (paper 2 eqs. 51-53)";
}

template <int D>
std::string Model<D>::distortion_irreversibility(const Model& model) {
  if (model.parameters_.cayley_distortion_update) {
    return "the paper's Cayley distortion update (eq. 49), rounded to fixed point: not exactly "
           "invertible";
  }
  return "";
}

template <int D>
std::string Model<D>::relaxation_irreversibility(const Model& model) {
  return model.parameters_.relaxation_time ? model.relaxation_description() : "";
}

template <int D>
ExactDistortion<D> Model<D>::distortion_of(const CarrierFields<D>& set, std::size_t i) const {
  ExactDistortion<D> distortion;
  distortion.log_det = set.log_det.at(0, i);
  for (int c = 0; c < D * D; ++c) {
    distortion.unimodular[c] = set.unimodular.at(c, i);
  }
  return distortion;
}

template <int D>
void Model<D>::store_distortion(CarrierFields<D>& set, std::size_t i,
                                const ExactDistortion<D>& distortion) {
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
  const double rest_density = parameters_.material.rest_density;
  const double trial_mass = rest_density / kernel_.value(0.0);
  mass_.assign(n, trial_mass);
  density_constant_.assign(n, 0);
  lambda_constant_.assign(n, 0);
  const auto carried = carried_by_set();
  for (CarrierFields<D>* set : carried) {
    std::fill(set->density_constant.all().begin(), set->density_constant.all().end(), 0);
    std::fill(set->lambda_constant.all().begin(), set->lambda_constant.all().end(), 0);
  }
  constants_valid_ = true;
  geometry_valid_ = false;
  update_geometry();
  double largest = 0.0;
  for (std::size_t s = 0; s < n; ++s) {
    largest = std::max(largest, rest_density * trial_mass / sums_.density[s]);
  }
  const fixedpoint::Scale mass_scale = fixedpoint::Scale::covering(largest, mass_fraction_bits);
  for (std::size_t set = 0; set < carried.size(); ++set) {
    Field& mass = carried[set]->mass;
    mass.set_scale(mass_scale);
    const std::span<const std::uint32_t> slots = layout_.slots_of_set(set);
    for (std::size_t i = 0; i < slots.size(); ++i) {
      fixedpoint::try_to_fixed(rest_density * trial_mass / sums_.density[slots[i]], mass_scale,
                               mass.at(0, i));
    }
  }
  // The sums with the stored masses give the constants.
  invalidate_derived();
  update_geometry();
  FaultRecorder faults;
  for (std::size_t s = 0; s < n; ++s) {
    const SetParticle particle = layout_.particle_in_slot(s);
    CarrierFields<D>& set = *carried[particle.set];
    if (!fixedpoint::try_to_fixed(rest_density - sums_.density[s], parameters_.density_scale,
                                  set.density_constant.at(0, particle.index)) ||
        !fixedpoint::try_to_fixed(-sums_.lambda[s], parameters_.density_scale,
                                  set.lambda_constant.at(0, particle.index))) {
      layout_.record_fault(faults, s, "density_constant", "does not fit its scale");
    }
  }
  faults.throw_if_any();
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
  const std::size_t n = carrier_count();
  const auto& v_scale = state_.material.velocity.info().scale;
  for (int k = 0; k < D; ++k) {
    slot_velocity_[k].resize(n);
  }
  const std::span<const std::uint32_t> material = layout_.slots_of(state_.material);
  const std::span<const std::uint32_t> walls = layout_.slots_of(state_.boundary);
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < material.size(); ++i) {
      for (int k = 0; k < D; ++k) {
        slot_velocity_[k][material[i]] =
            fixedpoint::to_real(state_.material.velocity.at(k, i), v_scale);
      }
    }
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < walls.size(); ++i) {
      const Vec<D> wall = wall_velocity_now(i);
      for (int k = 0; k < D; ++k) {
        slot_velocity_[k][walls[i]] = wall[k];
      }
    }
  }
  if (parameters_.mirrored_walls) {
    slot_mirrored_velocity_ = slot_velocity_;
    mirror_wall_velocities<D>(kernel_, layout_, slot_mass_, layout_.in(state_.boundary),
                              slot_mirrored_velocity_, mirror_sums_);
  }
}

template <int D>
void Model<D>::update_distortion(double dt) {
  update_carrier_velocities();
  const std::size_t n = carrier_count();
  const bool driven = walls_work();
  if (driven) {
    wall_forces(wall_force_before_);
  }
  // Eq. (10) with the velocities the walls pretend: their own (the paper's way) for every carrier,
  // or, with mirrored walls, the mirrored ones in the material's L while the walls' own L keeps
  // v_w (mirrored_walls.hpp).
  const CoordinateView<D> velocity = view_of<D>(slot_velocity_);
  const SeenVelocities<D> seen = parameters_.mirrored_walls
                                     ? SeenVelocities<D>{view_of<D>(slot_mirrored_velocity_),
                                                         velocity, layout_.in(state_.boundary)}
                                     : SeenVelocities<D>{velocity, velocity, {}};
  velocity_gradients<D>(kernel_, layout_, seen, slot_mass_, sums_.h_inverse, gradients_);
  const auto carried = carried_by_set();
  FaultRecorder faults;
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const SetParticle particle = layout_.particle_in_slot(s);
    CarrierFields<D>& set = *carried[particle.set];
    ExactDistortion<D> distortion = distortion_of(set, particle.index);
    // dt L is odd in v bit for bit: the update with -dt L undoes this one exactly.
    const Matrix<D> step = dt * gradients_.gradient[s];
    const DistortionScales& scales = parameters_.distortion_scales;
    const bool updated =
        parameters_.cayley_distortion_update
            ? try_make_distortion<D>(cayley_update<D>(to_matrix<D>(distortion, scales), step),
                                     scales, distortion)
            : try_update_distortion<D>(distortion, step, scales);
    if (!updated) {
      layout_.record_fault(faults, s, "distortion",
                           "overflow or non-finite value in the distortion update");
      continue;
    }
    store_distortion(set, particle.index, distortion);
  }
  faults.throw_if_any();
  force_valid_ = false;
  if (driven) {
    wall_forces(wall_force_after_);
    if (!add_wall_work(dt)) {
      throw SimulationFault({"boundary", 0, "wall_work", "does not fit its fixed-point scale"}, 0);
    }
  }
}

template <int D>
void Model<D>::relax_all(double dt) {
  force_valid_ = false;
  for (CarrierFields<D>* set : carried_by_set()) {
    update_each_particle(set->log_det, "overflow or non-finite value in the relaxation",
                         [&](std::size_t i) {
                           ExactDistortion<D> distortion = distortion_of(*set, i);
                           if (!relax(distortion, set->dissipated_energy.at(0, i), dt)) {
                             return false;
                           }
                           store_distortion(*set, i, distortion);
                           return true;
                         });
  }
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
  // Mirrored walls pretend velocities even at rest, and do work. Decided once, from the whole
  // state the setup made (a distributed run's process may hold no wall: what the passes do must
  // not depend on it).
  if (!walls_work_known_) {
    walls_work_ = any_wall_moves(state_) ||
                  (parameters_.mirrored_walls && state_.boundary.position.count() > 0);
    walls_work_known_ = true;
  }
  constants_valid_ = true;
}

template <int D>
void Model<D>::update_geometry() {
  if (geometry_valid_) {
    return;
  }
  update_constants();
  const std::size_t n = carrier_count();
  layout_.build(carrier_position(), parameters_.support_radius(),
                Gathered<double>{mass_, &slot_mass_},
                Gathered<std::int64_t>{density_constant_, &slot_density_constant_},
                Gathered<std::int64_t>{lambda_constant_, &slot_lambda_constant_});
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
  const std::size_t n = carrier_count();
  slot_distortion_.resize(n);
  slot_stress_.resize(n);
  const auto carried = carried_by_set();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const SetParticle particle = layout_.particle_in_slot(s);
    slot_distortion_[s] = to_matrix<D>(distortion_of(*carried[particle.set], particle.index),
                                       parameters_.distortion_scales);
    slot_stress_[s] = stress<D>(parameters_.material, sums_.density[s], slot_distortion_[s],
                                sums_.h_inverse[s]); // eq. (21b)
  }
  const PenaltyParameters penalty{parameters_.penalty_speed, parameters_.material.rest_density};
  compute_acceleration<D>(kernel_, penalty_strength(penalty), layout_, slot_mass_, slot_stress_,
                          sums_.lambda, acceleration_sums_, slot_acceleration_);
  // Boundary particles are held in place: only the material takes its acceleration.
  const std::span<const std::uint32_t> material = layout_.slots_of(state_.material);
  FaultRecorder faults;
  for (int k = 0; k < D; ++k) {
    acceleration_[k].resize(material.size());
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < material.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      acceleration_[k][i] = slot_acceleration_[k][material[i]];
      if (!std::isfinite(acceleration_[k][i])) {
        layout_.record_fault(faults, material[i], "acceleration", "non-finite acceleration");
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
std::array<typename Model<D>::CarrierValues, 2> Model<D>::carrier_values() {
  update_force();
  std::array<CarrierValues, 2> values;
  for (std::size_t set = 0; set < values.size(); ++set) {
    const std::span<const std::uint32_t> slots = layout_.slots_of_set(set);
    CarrierValues& of_set = values[set];
    for (const std::uint32_t s : slots) {
      of_set.density.push_back(sums_.density[s]);
      of_set.lambda.push_back(sums_.lambda[s]);
      of_set.distortion.push_back(slot_distortion_[s]);
    }
  }
  return values;
}

template <int D>
std::array<typename Model<D>::ParticleEnergies, 2>
Model<D>::particle_energies(const std::array<CarrierValues, 2>& values) {
  const ElasticMaterial& material = parameters_.material;
  const double cp = parameters_.penalty_speed;
  const auto carried = carried_by_set();
  std::array<ParticleEnergies, 2> energies;
  for (std::size_t set = 0; set < energies.size(); ++set) {
    const std::span<const std::uint32_t> slots = layout_.slots_of_set(set);
    const CarrierValues& of_set = values[set];
    const Field& dissipated = carried[set]->dissipated_energy;
    ParticleEnergies& e = energies[set];
    for (std::size_t i = 0; i < slots.size(); ++i) {
      const double m = slot_mass_[slots[i]];
      e.bulk.push_back(m * bulk_energy(material, of_set.density[i]));         // eq. (29)
      e.shear.push_back(m * shear_energy<D>(material, of_set.distortion[i])); // eq. (31), (35)
      const double relative = of_set.lambda[i] / material.rest_density;
      e.penalty.push_back(0.5 * m * cp * cp * relative * relative); // eq. (39)
      e.dissipated.push_back(m * fixedpoint::to_real(dissipated.at(0, i), dissipated.info().scale));
    }
  }
  const auto& velocity = state_.material.velocity;
  const std::span<const std::uint32_t> moving = layout_.slots_of(state_.material);
  for (std::size_t i = 0; i < moving.size(); ++i) {
    double v_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double v = fixedpoint::to_real(velocity.at(k, i), velocity.info().scale);
      v_squared += v * v;
    }
    energies[layout_.index_of(state_.material)].kinetic.push_back(0.5 * slot_mass_[moving[i]] *
                                                                  v_squared);
  }
  return energies;
}

template <int D>
EnergyBudget Model<D>::energy() {
  const auto energies = particle_energies(carrier_values());
  // Exact sums (core/global_totals.hpp): the same value for any thread or process count.
  auto total = [&energies](std::vector<double> ParticleEnergies::*term) {
    ExactDoubleSum sum;
    for (const ParticleEnergies& of_set : energies) {
      sum.add(exact_sum_of(of_set.*term));
    }
    return global_total(sum);
  };
  EnergyBudget budget{{{"kinetic", total(&ParticleEnergies::kinetic)},
                       {"volumetric", total(&ParticleEnergies::bulk)},
                       {"shear", total(&ParticleEnergies::shear)},
                       {"penalty", total(&ParticleEnergies::penalty)}}};
  if (parameters_.relaxation_time) {
    budget.terms.push_back({"dissipated", total(&ParticleEnergies::dissipated)});
  }
  if (walls_work()) {
    // What the walls have put in, counted negative: the total stays constant.
    const std::span<const std::uint32_t> walls = layout_.slots_of(state_.boundary);
    const Field& wall_work = state_.boundary.wall_work;
    ExactDoubleSum work;
    for (std::size_t i = 0; i < walls.size(); ++i) {
      work.add(slot_mass_[walls[i]] *
               fixedpoint::to_real(wall_work.at(0, i), wall_work.info().scale));
    }
    budget.terms.push_back({"wall_work", -global_total(work)});
  }
  return budget;
}

template <int D>
void Model<D>::derived_views(const ViewSink& sink) {
  const auto values = carrier_values();
  const auto energies = particle_energies(values);
  const std::vector<CarrierSet>& sets = layout_.sets();
  for (std::size_t set = 0; set < sets.size(); ++set) {
    const CarrierValues& of_set = values[set];
    const ParticleEnergies& e = energies[set];
    // Every set's views, even where this process holds none of its particles (a distributed
    // run's snapshot takes each view from every process).
    const std::size_t count = of_set.density.size();
    const std::string& name = sets[set].name;
    std::vector<double> pressure_values(count);
    std::vector<double> distortion(count * D * D);
    for (std::size_t i = 0; i < count; ++i) {
      pressure_values[i] = pressure(parameters_.material, of_set.density[i]); // eq. (30)
      for (int r = 0; r < D; ++r) {
        for (int c = 0; c < D; ++c) {
          distortion[static_cast<std::size_t>(r * D + c) * count + i] = of_set.distortion[i](r, c);
        }
      }
    }
    sink(ParticleView{name, "density", "kg/m^3", 1, of_set.density});
    sink(ParticleView{name, "pressure", "Pa", 1, std::move(pressure_values)});
    sink(ParticleView{name, "lambda", "kg/m^3", 1, of_set.lambda});
    sink(ParticleView{name, "distortion", "1", D * D, std::move(distortion)});
    sink(ParticleView{name, "volumetric_energy", energy_unit<D>, 1, e.bulk});
    sink(ParticleView{name, "shear_energy", energy_unit<D>, 1, e.shear});
    sink(ParticleView{name, "penalty_energy", energy_unit<D>, 1, e.penalty});
    if (parameters_.relaxation_time) {
      sink(ParticleView{name, "dissipated_energy", energy_unit<D>, 1, e.dissipated});
    }
  }
  {
    std::vector<double> acceleration_values;
    for (int k = 0; k < D; ++k) {
      acceleration_values.insert(acceleration_values.end(), acceleration_[k].begin(),
                                 acceleration_[k].end());
    }
    sink(ParticleView{"material", "acceleration", "m/s^2", D, std::move(acceleration_values)});
    sink(ParticleView{"material", "kinetic_energy", energy_unit<D>, 1,
                      energies[layout_.index_of(state_.material)].kinetic});
  }
  const std::span<const std::uint32_t> walls = layout_.slots_of(state_.boundary);
  if (walls_work()) { // on every process (its pass is collective), with or without own walls
    update_carrier_velocities();
    const CoordinateArrays<D>& seen = slot_velocity_seen();
    std::vector<double> velocity(walls.size() * D);
    for (int k = 0; k < D; ++k) {
      for (std::size_t i = 0; i < walls.size(); ++i) {
        velocity[static_cast<std::size_t>(k) * walls.size() + i] = seen[k][walls[i]];
      }
    }
    sink(ParticleView{"boundary", "velocity", "m/s", D, std::move(velocity)});
  }
}

template <int D>
void Model<D>::shear_accelerations(CoordinateArrays<D>& acceleration, StressOf carriers) {
  update_geometry();
  const std::size_t n = carrier_count();
  const auto carried = carried_by_set();
  const auto stress_in_slot = [&](std::size_t s) {
    const SetParticle particle = layout_.particle_in_slot(s);
    const Matrix<D> distortion = to_matrix<D>(distortion_of(*carried[particle.set], particle.index),
                                              parameters_.distortion_scales);
    slot_shear_stress_[s] = shear_stress<D>(parameters_.material, distortion, sums_.h_inverse[s]);
  };
  slot_shear_stress_.resize(n);
  if (carriers == StressOf::all) {
#pragma omp parallel for schedule(static)
    for (std::size_t s = 0; s < n; ++s) {
      stress_in_slot(s);
    }
  } else {
    for (GradientMatrix<D>& stress : slot_shear_stress_) {
      stress.setZero();
    }
    const std::span<const std::uint32_t> slots = carriers == StressOf::material
                                                     ? layout_.slots_of(state_.material)
                                                     : layout_.slots_of(state_.boundary);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < slots.size(); ++i) {
      stress_in_slot(slots[i]);
    }
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
RunTotal Model<D>::wall_power() {
  update_carrier_velocities();
  WallForces forces;
  wall_forces(forces);
  ExactDoubleSum total; // exact: the same for any thread or process count
  for (const std::uint32_t s : layout_.slots_of(state_.boundary)) {
    // The material's stress pairs with the velocity the material sees the wall move with, the
    // wall's own with the wall's velocity (model.hpp); without mirroring both are v_w and
    // from_walls holds the whole force.
    double power = 0.0;
    for (int k = 0; k < D; ++k) {
      power -= slot_mass_[s] * forces.from_walls[k][s] * slot_velocity_[k][s];
      if (parameters_.mirrored_walls) {
        power -= slot_mass_[s] * forces.from_material[k][s] * slot_mirrored_velocity_[k][s];
      }
    }
    total.add(power);
  }
  return global_total(total);
}

template <int D>
bool Model<D>::add_wall_work(double dt) {
  const std::span<const std::uint32_t> walls = layout_.slots_of(state_.boundary);
  Field& wall_work = state_.boundary.wall_work;
  bool fits = true;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const std::uint32_t s = walls[i];
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
    fits = fits && FixedArithmetic::try_increment(wall_work.at(0, i), 0.5 * dt * work,
                                                  wall_work.info().scale);
  }
  return fits;
}

template <int D>
std::vector<EnergyTerm> Model<D>::diagnostics() {
  const Field& position = state_.material.position;
  const auto x_of = [&position](int axis, std::size_t a) {
    return fixedpoint::to_real(position.at(axis, a), position.info().scale);
  };
  std::vector<EnergyTerm> terms;
  // Angular momentum of the material about the origin, eq. (26) (conserved without boundary
  // particles; the twisting column's changes sign when its rotation reverses). Exact sums: the
  // same for any thread or process count.
  const Field& mass = state_.material.carried.mass;
  std::array<ExactDoubleSum, 3> angular;
  const auto& v_scale = state_.material.velocity.info().scale;
  for (std::size_t a = 0; a < material_count(); ++a) {
    Vec<3> x{};
    Vec<3> v{};
    for (int k = 0; k < D; ++k) {
      x[k] = x_of(k, a);
      v[k] = fixedpoint::to_real(state_.material.velocity.at(k, a), v_scale);
    }
    const double m = fixedpoint::to_real(mass.at(0, a), mass.info().scale);
    angular[0].add(m * (x[1] * v[2] - x[2] * v[1]));
    angular[1].add(m * (x[2] * v[0] - x[0] * v[2]));
    angular[2].add(m * (x[0] * v[1] - x[1] * v[0]));
  }
  if constexpr (D == 2) {
    terms.push_back({"angular_momentum", global_total(angular[2]), angular_momentum_unit<D>});
  } else {
    terms.push_back({"angular_momentum_x", global_total(angular[0]), angular_momentum_unit<D>});
    terms.push_back({"angular_momentum_y", global_total(angular[1]), angular_momentum_unit<D>});
    terms.push_back({"angular_momentum_z", global_total(angular[2]), angular_momentum_unit<D>});
  }
  if (walls_work()) {
    terms.push_back({"wall_power", wall_power(), power_unit<D>});
  }
  return terms;
}

template class Model<2>;
template class Model<3>;

} // namespace revsph::shtc
