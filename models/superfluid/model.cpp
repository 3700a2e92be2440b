#include "models/superfluid/model.hpp"

#include "core/particle_update.hpp"
#include "core/summation_density.hpp"
#include "core/verlet.hpp"
#include "models/superfluid/dissipation_terms.hpp"

#include <algorithm>
#include <cmath>

namespace revsph::superfluid {

namespace {

template <int D>
std::array<SummedQuantity, 2 * D + 1> increment_quantities(const fixedpoint::Scale& velocity,
                                                           const fixedpoint::Scale& entropy) {
  std::array<SummedQuantity, 2 * D + 1> quantities{};
  for (int k = 0; k < D; ++k) {
    quantities[k] = {"velocity_increment", velocity};
    quantities[D + k] = {"superflow_velocity_increment", velocity};
  }
  quantities[2 * D] = {"entropy_increment", entropy};
  return quantities;
}

template <int D>
std::array<SummedQuantity, D + 1> dissipation_quantities(const fixedpoint::Scale& velocity,
                                                         const fixedpoint::Scale& heat) {
  std::array<SummedQuantity, D + 1> quantities{};
  for (int k = 0; k < D; ++k) {
    quantities[k] = {"viscous_velocity_increment", velocity};
  }
  quantities[D] = {"heat", heat};
  return quantities;
}

} // namespace

template <int D, class Arith>
Model<D, Arith>::Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state)
    : Parts(std::move(parameters), std::move(info), std::move(state)),
      kernel_(parameters_.support_radius),
      layout_(parameters_.domain, parameters_.support_radius * parameters_.cell_size_factor,
              carrier_sets(state_.fluid, state_.dummy, state_.wall)),
      density_sums_(SummedQuantity{"density", parameters_.density_scale}),
      increment_sums_(
          increment_quantities<D>(parameters_.velocity_scale, parameters_.entropy_scale)),
      dissipation_sums_(
          dissipation_quantities<D>(parameters_.velocity_scale, parameters_.heat_scale)),
      wall_work_sums_(SummedQuantity{"wall_work", parameters_.heat_scale}),
      has_walls_(state_.wall.position.count() > 0) {}

template <int D, class Arith>
void Model<D, Arith>::initialise_density_constants() {
  for (StateField<Raw>* field : {&state_.fluid.density_constant, &state_.dummy.density_constant,
                                 &state_.wall.density_constant}) {
    std::fill(field->all().begin(), field->all().end(), Raw{});
  }
  invalidate_derived();
  update_density();
  lattice_kernel_sum_ = lattice_kernel_sum(kernel_, parameters_.dr);
  struct Carriers {
    std::size_t set;
    StateField<Raw>* constant;
    const StateField<Raw>* position;
  };
  for (const Carriers& c : {Carriers{layout_.index_of(state_.fluid), &state_.fluid.density_constant,
                                     &state_.fluid.position},
                            Carriers{layout_.index_of(state_.dummy), &state_.dummy.density_constant,
                                     &state_.dummy.position},
                            Carriers{layout_.index_of(state_.wall), &state_.wall.density_constant,
                                     &state_.wall.position}}) {
    StateField<Raw>* field = c.constant;
    const std::span<const std::uint32_t> slots = layout_.slots_of_set(c.set);
    const std::span<const double> mass = layout_.part_of_set(std::span<const double>(mass_), c.set);
    for (std::size_t i = 0; i < slots.size(); ++i) {
      // A fluid particle starts at the target density (eq. 24). A boundary particle gets the
      // constant of a particle inside the liquid, whatever surrounds it now: a dry one (the
      // capillary's walls above the level) would otherwise be made as dense as a wet one, and
      // the liquid reaching it later would meet a wall at several kPa (README, "Walls").
      const double sum = c.set == layout_.index_of(state_.fluid) ? density_sums_.value(0, slots[i])
                                                                 : mass[i] * lattice_kernel_sum_;
      // rho0, or the hydrostatic density below a free surface.
      double target = parameters_.helium.rest_density;
      const double surface = parameters_.initial.hydrostatic_surface;
      if (!std::isnan(surface)) {
        const double y = Arith::real(c.position->at(D - 1, i), c.position->info().scale);
        const double u1 = parameters_.helium.first_sound_speed;
        target *= 1.0 + parameters_.gravity * (surface - y) / (u1 * u1);
      }
      set_density_constant<Arith>(*field, i, target, sum);
    }
  }
  invalidate_derived();
}

template <int D, class Arith>
std::span<const Substep<Model<D, Arith>>> Model<D, Arith>::palindrome() {
  // clang-format off
  // The strang splitting's half updates go after the half drifts (not at the ends): every
  // evaluation at the step's mid positions, no neighbour search of its own.
  static constexpr Substep<Model> sequence[] = {
      {"drift", 0.5, &Model::drift},
      strang_site<Model>(),
      {"copy_one", 0.5, &Model::update_copy_one},
      {"copy_two", 1.0, &Model::update_copy_two},
      {"copy_one", 0.5, &Model::update_copy_one},
      strang_site<Model>(),
      {"drift", 0.5, &Model::drift},
  };
  // clang-format on
  return sequence;
}

template <int D, class Arith>
std::span<const IrreversibleOperator<Model<D, Arith>>> Model<D, Arith>::irreversible_operators() {
  static constexpr IrreversibleOperator<Model> operators[] = {
      {"dissipate", &Model::dissipate, &Model::dissipation_acts}};
  return operators;
}

template <int D, class Arith>
typename Model<D, Arith>::Copy Model<D, Arith>::copy(int which) {
  auto& f = state_.fluid;
  auto& w = state_.wall;
  if (which == 0) {
    return {&f.velocity, &f.superflow_velocity, &f.entropy, &w.superflow_velocity};
  }
  return {&f.velocity_copy, &f.superflow_velocity_copy, &f.entropy_copy,
          &w.superflow_velocity_copy};
}

template <int D, class Arith>
void Model<D, Arith>::drift(double dt) {
  // x += dt (v + v') / 2: odd in the velocities bit for bit ((-a) + (-b) = -(a + b) in IEEE).
  auto& position = state_.fluid.position;
  const auto& v1 = state_.fluid.velocity;
  const auto& v2 = state_.fluid.velocity_copy;
  const auto& x_scale = position.info().scale;
  const auto& v_scale = v1.info().scale;
  update_each_particle(position, "overflow or non-finite value in a drift", [&](std::size_t i) {
    bool fits = true;
    for (int k = 0; k < D; ++k) {
      const double mean =
          0.5 * (Arith::real(v1.at(k, i), v_scale) + Arith::real(v2.at(k, i), v_scale));
      fits = Arith::try_increment(position.at(k, i), dt * mean, x_scale) && fits;
    }
    return fits;
  });
  wrap_into_period(position); // a periodic domain (core/periodic_wrap.hpp)
  density_valid_ = false;
}

template <int D, class Arith>
void Model<D, Arith>::update_copy(int to, double dt) {
  sum_increments(1 - to, dt);
  const Copy target = copy(to);
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  FaultRecorder faults;
  add_pair_totals<Arith>(*target.velocity, increment_sums_, 0, fluid, faults);
  add_pair_totals<Arith>(*target.superflow_velocity, increment_sums_, D, fluid, faults);
  add_pair_totals<Arith>(*target.entropy, increment_sums_, 2 * D, fluid, faults);
  if (parameters_.absorbing_walls) {
    add_pair_totals<Arith>(*target.wall_superflow_velocity, increment_sums_, D,
                           layout_.slots_of(state_.wall), faults);
    count_wall_work(dt);
  }
}

template <int D, class Arith>
void Model<D, Arith>::update_constants() {
  if (constants_valid_) {
    return;
  }
  mass_ = CarrierField<Arith>{&state_.fluid.mass, &state_.dummy.mass, &state_.wall.mass}.reals();
  density_constant_ =
      CarrierField<Arith>{&state_.fluid.density_constant, &state_.dummy.density_constant,
                          &state_.wall.density_constant}
          .raws();
  constants_valid_ = true;
}

template <int D, class Arith>
void Model<D, Arith>::update_density() {
  if (density_valid_) {
    return;
  }
  update_constants();
  layout_.build(carrier_position(), parameters_.support_radius,
                Gathered<double>{mass_, &slot_mass_},
                Gathered<Raw>{density_constant_, &slot_density_constant_});
  const SlotInSet is_fluid = layout_.in(state_.fluid);
  const SlotInSet interacts = interacting();
  const std::size_t carriers = layout_.slot_count();
  inputs_.pressure_over_density_squared.resize(carriers);
  inputs_.inverse_density.resize(carriers);
  FaultRecorder faults;
  const Helium& he = parameters_.helium;
  const auto pressure_term = [&](std::uint32_t s) {
    const double rho = density_sums_.value(0, s);
    if (!(rho > 0.0)) {
      layout_.record_fault(faults, s, "density", "density not positive");
    }
    const double p = is_fluid(s) ? he.pressure(rho) : he.boundary_pressure(rho); // (12)
    inputs_.pressure_over_density_squared[s] = p / (rho * rho);
    inputs_.inverse_density[s] = 1.0 / rho;
  };
  sum_pairs<Arith>(layout_,
                   SummationDensityTerm<D, Arith>{kernel_, slot_mass_, slot_density_constant_},
                   density_sums_, {}, pressure_term);
  faults.throw_if_any();
  // The rates and the dissipation reach fluid particles only: a third of the fountain's pairs
  // join two wall particles and are left out of their five pair loops per step.
  fluid_pairs_.assign_filtered(layout_.pairs(), [&](std::uint32_t a, std::uint32_t b) {
    return is_fluid(a) || is_fluid(b);
  });
  if (parameters_.absorbing_walls) {
    wall_pairs_.assign_filtered(layout_.pairs(), [&](std::uint32_t a, std::uint32_t b) {
      return is_fluid(a) != is_fluid(b) && interacts(a) && interacts(b);
    });
  }
  density_valid_ = true;
}

template <int D, class Arith>
void Model<D, Arith>::fill_rate_inputs(int from) {
  update_density();
  const std::size_t carriers = layout_.slot_count();
  RateInputs<D>& in = inputs_;
  in.flux_factor.resize(carriers);
  in.entropy_over_density.resize(carriers);
  in.temperature.resize(carriers);
  for (int k = 0; k < D; ++k) {
    in.relative[k].resize(carriers);
    in.entropy_flux[k].resize(carriers);
    in.normal_velocity[k].resize(carriers);
  }
  const Helium& he = parameters_.helium;
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  const Copy one = copy(0);
  const Copy two = copy(1);
  const auto& v_scale = one.velocity->info().scale;
  const auto& s_scale = one.entropy->info().scale;
  // The value of a field of copy `from`, or the mean of both copies (from = -1).
  auto value = [&](StateField<Raw>* first, StateField<Raw>* second, int k, std::size_t i,
                   const fixedpoint::Scale& scale) {
    if (from == 0) {
      return Arith::real(first->at(k, i), scale);
    }
    if (from == 1) {
      return Arith::real(second->at(k, i), scale);
    }
    return 0.5 * (Arith::real(first->at(k, i), scale) + Arith::real(second->at(k, i), scale));
  };
  FaultRecorder faults;
  const std::size_t n = fluid.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t slot = fluid[i];
    const double s = value(one.entropy, two.entropy, 0, i, s_scale);
    const double chi_n = he.chi_n(s); // eq. (8)
    if (!(chi_n > 0.0 && chi_n <= 1.0)) {
      faults.record(i, "fluid", "entropy", "the normal fraction chi_n (eq. 8) left (0, 1]");
    }
    const double ratio = (1.0 - chi_n) / chi_n; // chi_s / chi_n
    const double inverse_density = in.inverse_density[slot];
    double relative_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double v = value(one.velocity, two.velocity, k, i, v_scale);
      const double v_s = value(one.superflow_velocity, two.superflow_velocity, k, i, v_scale);
      const double u = v - v_s; // chi_n v_ns (eq. 22)
      in.relative[k][slot] = u;
      in.entropy_flux[k][slot] = s * ratio * inverse_density * u; // j / rho^2 (eq. 21)
      in.normal_velocity[k][slot] = v + ratio * u;                // eq. (22)
      relative_squared += u * u;
    }
    in.flux_factor[slot] = ratio * inverse_density;
    in.entropy_over_density[slot] = s * inverse_density;
    in.temperature[slot] = he.temperature(s, relative_squared / (chi_n * chi_n));
  }
  faults.throw_if_any();
  if (parameters_.absorbing_walls) {
    // The authors' cooler: s = s0 and T = T0 held, v the wall's own, v_s its own (this copy's).
    const std::span<const std::uint32_t> wall = layout_.slots_of(state_.wall);
    const double s0 = he.reference_entropy;
    const double ratio = (1.0 - he.chi_n(s0)) / he.chi_n(s0);
    const auto& w_scale = state_.wall.velocity.info().scale;
    for (std::size_t i = 0; i < wall.size(); ++i) {
      const std::uint32_t slot = wall[i];
      const double inverse_density = in.inverse_density[slot];
      for (int k = 0; k < D; ++k) {
        const double v = Arith::real(state_.wall.velocity.at(k, i), w_scale);
        const double v_s =
            value(one.wall_superflow_velocity, two.wall_superflow_velocity, k, i, v_scale);
        const double u = v - v_s;
        in.relative[k][slot] = u;
        in.entropy_flux[k][slot] = s0 * ratio * inverse_density * u;
        in.normal_velocity[k][slot] = v + ratio * u;
      }
      in.flux_factor[slot] = ratio * inverse_density;
      in.entropy_over_density[slot] = s0 * inverse_density;
      in.temperature[slot] = he.reference_temperature;
    }
  }
}

template <int D, class Arith>
void Model<D, Arith>::sum_increments(int from, double tau) {
  fill_rate_inputs(from);
  sum_pairs_over<Arith>(layout_, fluid_pairs_,
                        RateTerm<D>{kernel_, slot_mass_, layout_.in(state_.fluid), interacting(),
                                    inputs_, tau, parameters_.gravity,
                                    parameters_.helium.normal_fraction == 1.0 &&
                                        parameters_.helium.normal_fraction_slope == 0.0},
                        increment_sums_);
}

template <int D, class Arith>
void Model<D, Arith>::count_wall_work(double tau) {
  const RateTerm<D> rate{kernel_, slot_mass_, layout_.in(state_.fluid), interacting(),
                         inputs_, tau,        parameters_.gravity,      false};
  sum_pairs_over<Arith>(layout_, wall_pairs_, WallWorkTerm<D>{rate}, wall_work_sums_);
  // Summed exactly, so the same for any thread or process count and cell size; the mean of the
  // copies receives half of each copy's increments.
  ExactDoubleSum total;
  for (const std::uint32_t slot : layout_.slots_of(state_.fluid)) {
    total.add(wall_work_sums_.value(0, slot));
  }
  exchanged_energy_ += 0.5 * global_total(total);
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::superfluid
