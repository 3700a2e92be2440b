// The irreversible sub-step of the superfluid model: viscosity and heat conduction
// (dissipation_terms.hpp), the heat turned into entropy so that the energy (15) is kept.
#include "core/particle_update.hpp"
#include "core/verlet.hpp"
#include "models/superfluid/dissipation_terms.hpp"
#include "models/superfluid/model.hpp"

#include <cmath>
#include <sstream>

namespace revsph::superfluid {

template <int D, class Arith>
std::string Model<D, Arith>::dissipation_acts(const Model& model) {
  const Parameters<D>& p = model.parameters_;
  if (p.viscosity == 0.0 && p.heat_conductivity == 0.0) {
    return "";
  }
  std::ostringstream text;
  text << "normal-fluid viscosity (mu = " << p.viscosity
       << " Pa s, eqs. 19, B22) and heat conduction (beta = " << p.heat_conductivity
       << " W/(m K), eqs. B21, B23), the heat kept as entropy";
  if (p.dummy_no_slip && p.viscosity != 0.0) {
    text << "; no-slip dummies (physics.dummy_slip)";
  }
  return text.str();
}

// Solves m [e(s + x) - e(s)] = heat at fixed v, v_s and rho, e the energy (15): its s-dependent
// part is the thermal term and the counterflow term (chi_s / chi_n)(s) |v - v_s|^2 / 2, whose
// derivative is T (helium.hpp). Newton's method from heat / (m T), a fixed number of iterations
// (deterministic; the heat of one sub-step is a tiny fraction of m T s).
template <int D, class Arith>
double Model<D, Arith>::entropy_for_heat(double s, double relative_squared, double mass,
                                         double heat) const {
  const Helium& he = parameters_.helium;
  auto energy = [&](double entropy) {
    return he.thermal_energy(entropy) + he.counterflow_energy(entropy, relative_squared);
  };
  auto temperature = [&](double entropy) {
    const double chi_n = he.chi_n(entropy);
    return he.temperature(entropy, relative_squared / (chi_n * chi_n));
  };
  const double target = heat / mass;
  const double e0 = energy(s);
  double x = target / temperature(s);
  for (int iteration = 0; iteration < 4; ++iteration) {
    x -= (energy(s + x) - e0 - target) / temperature(s + x);
  }
  return x;
}

template <int D, class Arith>
bool Model<D, Arith>::add_entropy(std::size_t i, double ds) {
  auto& s1 = state_.fluid.entropy;
  auto& s2 = state_.fluid.entropy_copy;
  if (!std::isfinite(ds)) {
    return false;
  }
  if constexpr (Arith::kind == Arithmetic::fixed) {
    std::int64_t increment = 0;
    return fixedpoint::try_round_up_to_fixed(ds, s1.info().scale, increment) &&
           fixedpoint::try_add(s1.at(0, i), increment, s1.at(0, i)) &&
           fixedpoint::try_add(s2.at(0, i), increment, s2.at(0, i));
  } else {
    s1.at(0, i) += ds;
    s2.at(0, i) += ds;
    return true;
  }
}

template <int D, class Arith>
void Model<D, Arith>::fill_superleak_sides() {
  const Superleak<D>& leak = parameters_.superleak;
  if (leak.rate == 0.0) {
    slot_side_.resize(layout_.slot_count(), 0); // all zero: nothing to redo each sub-step
    return;
  }
  slot_side_.assign(layout_.slot_count(), 0);
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  const auto& x_scale = state_.fluid.position.info().scale;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    bool within = true;
    for (int k = 0; k + 1 < D; ++k) {
      within = within && std::abs(Arith::real(state_.fluid.position.at(k, i), x_scale) -
                                  leak.centre[k]) <= leak.half_width;
    }
    if (within) {
      const double y = Arith::real(state_.fluid.position.at(D - 1, i), x_scale);
      slot_side_[fluid[i]] = y >= leak.centre[D - 1] ? 1 : -1;
    }
  }
}

template <int D, class Arith>
void Model<D, Arith>::dissipate(double dt) {
  if (parameters_.viscosity == 0.0 && parameters_.heat_conductivity == 0.0) {
    return;
  }
  const bool walls = has_walls_;
  const RunTotal energy_before = walls ? energy().total() : RunTotal();
  fill_rate_inputs(-1); // the mean of the copies: T, v_n, u = v - v_s, 1 / rho
  // Conducting walls: their own velocity as v_n, T0 as temperature (s = s0, no counterflow).
  // Absorbing walls got theirs, with their v_s, from fill_rate_inputs; no-slip dummies are at rest.
  if (!parameters_.absorbing_walls) {
    const std::span<const std::uint32_t> wall = layout_.slots_of(state_.wall);
    const auto& wall_scale = state_.wall.velocity.info().scale;
    for (std::size_t i = 0; i < wall.size(); ++i) {
      inputs_.temperature[wall[i]] = parameters_.helium.reference_temperature;
      for (int k = 0; k < D; ++k) {
        inputs_.normal_velocity[k][wall[i]] =
            Arith::real(state_.wall.velocity.at(k, i), wall_scale);
      }
    }
  }
  if (parameters_.dummy_no_slip) {
    for (const std::uint32_t slot : layout_.slots_of(state_.dummy)) {
      for (int k = 0; k < D; ++k) {
        inputs_.normal_velocity[k][slot] = 0.0;
      }
    }
  }
  fill_superleak_sides();
  // eta = h / 10 with h the kernel's support radius: Table I's h is the support, as the authors'
  // code uses it (README, "The kernel's width").
  const double eta = parameters_.support_radius / 10.0;
  sum_pairs_over<Arith>(layout_, fluid_pairs_,
                        DissipationTerm<D>{kernel_, slot_mass_, layout_.in(state_.fluid),
                                           layout_.in(state_.dummy), layout_.in(state_.wall),
                                           inputs_.inverse_density, inputs_.temperature,
                                           inputs_.normal_velocity, parameters_.viscosity,
                                           parameters_.heat_conductivity, eta * eta, dt, slot_side_,
                                           parameters_.dummy_no_slip, parameters_.absorbing_walls},
                        dissipation_sums_);
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  FaultRecorder faults;
  add_pair_totals<Arith>(state_.fluid.velocity, dissipation_sums_, 0, fluid, faults);
  add_pair_totals<Arith>(state_.fluid.velocity_copy, dissipation_sums_, 0, fluid, faults);
  if (parameters_.absorbing_walls) { // the cooler's v_s, dragged by the viscosity (terms' header)
    const std::span<const std::uint32_t> wall = layout_.slots_of(state_.wall);
    add_pair_totals<Arith>(state_.wall.superflow_velocity, dissipation_sums_, 0, wall, faults);
    add_pair_totals<Arith>(state_.wall.superflow_velocity_copy, dissipation_sums_, 0, wall, faults);
  }
  // The heat: what the pairs gave, less the kinetic energy the increments themselves carry,
  // m |dv|^2 / (2 chi_n) (e is quadratic in v with curvature 1 / chi_n at fixed v_s, s), so that
  // the heats add up to the mechanical energy removed.
  const Helium& he = parameters_.helium;
  const std::span<const double> mass =
      layout_.part_of(std::span<const double>(mass_), state_.fluid);
  auto& s1 = state_.fluid.entropy;
  auto& s2 = state_.fluid.entropy_copy;
  const auto& s_scale = s1.info().scale;
  update_each_particle(s1, "overflow or non-finite value in the heat update", [&](std::size_t i) {
    const std::uint32_t slot = fluid[i];
    const double s = 0.5 * (Arith::real(s1.at(0, i), s_scale) + Arith::real(s2.at(0, i), s_scale));
    double dv_squared = 0.0, u_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double dv = dissipation_sums_.value(k, slot);
      const double u = inputs_.relative[k][slot] + dv;
      dv_squared += dv * dv;
      u_squared += u * u;
    }
    const double heat = dissipation_sums_.value(D, slot) - 0.5 * mass[i] * dv_squared / he.chi_n(s);
    const double ds = entropy_for_heat(s, u_squared, mass[i], heat);
    return add_entropy(i, ds);
  });
  if (walls) {
    exchanged_energy_ += energy().total() - energy_before;
  }
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::superfluid
