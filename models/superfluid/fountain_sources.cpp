// The fountain's sources (paper 3 sec. III.C, eqs. 29-30), applied after every step, outside the
// reversible palindrome: the superleak's friction on the normal fluid and the heater. Both act
// on the mean of the copies and give both copies the same increments.
#include "core/kernel_wendland.hpp"
#include "fixedpoint/deterministic_math.hpp"
#include "models/superfluid/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace revsph::superfluid {

template <int D, class Arith>
std::span<const StepHook<Model<D, Arith>>> Model<D, Arith>::step_hooks() {
  static constexpr StepHook<Model> hooks[] = {
      {"superleak", &Model::relax_superleak, &Model::superleak_acts},
      {"heater", &Model::heat, &Model::heater_acts},
  };
  return hooks;
}

template <int D, class Arith>
std::string Model<D, Arith>::superleak_acts(const Model& model) {
  const Superleak<D>& leak = model.parameters_.superleak;
  if (leak.rate == 0.0) {
    return "";
  }
  std::ostringstream text;
  text << "superleak friction on the normal fluid (eq. 30, rate " << leak.rate
       << " 1/s, exact relaxation after each step), its energy kept as entropy";
  return text.str();
}

template <int D, class Arith>
std::string Model<D, Arith>::heater_acts(const Model& model) {
  const Heater<D>& heater = model.parameters_.heater;
  if (heater.power == 0.0) {
    return "";
  }
  std::ostringstream text;
  text << "heater (eq. 30, power " << heater.power << (D == 2 ? " W/m" : " W") << ", ramped over "
       << heater.ramp_time << " s, after each step)";
  return text.str();
}

// Eq. (30), f_sup = -chi_n v_n / tau in the slab, solved exactly at fixed v_s and s:
// dv_n/dt = (dv/dt) / chi_n = -rate v_n, so v_n -> v_n e^(-rate dt) and v = chi_n v_n + chi_s v_s.
// The energy it takes, m [v_n . dv + |dv|^2 / (2 chi_n)] (e is quadratic in v with curvature
// 1 / chi_n), becomes entropy: the friction conserves energy (App. B, Prop. 4).
template <int D, class Arith>
void Model<D, Arith>::relax_superleak(std::int64_t) {
  const Superleak<D>& leak = parameters_.superleak;
  if (leak.rate == 0.0) {
    return;
  }
  update_constants();
  const Helium& he = parameters_.helium;
  const double decay = dmath::exp(-leak.rate * info_.dt);
  const MeanState mean = mean_state();
  const std::span<const double> mass =
      layout_.part_of(std::span<const double>(mass_), state_.fluid);
  const auto& x_scale = state_.fluid.position.info().scale;
  auto& v1 = state_.fluid.velocity;
  auto& v2 = state_.fluid.velocity_copy;
  const auto& v_scale = v1.info().scale;
  FaultRecorder faults;
  const std::size_t n = fluid_count();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    bool inside = true;
    for (int k = 0; k < D; ++k) {
      const double half = k == D - 1 ? leak.half_thickness : leak.half_width;
      inside = inside && std::abs(Arith::real(state_.fluid.position.at(k, i), x_scale) -
                                  leak.centre[k]) <= half;
    }
    if (!inside) {
      continue;
    }
    const double s = mean.entropy[i];
    const double chi_n = he.chi_n(s);
    const double chi_s = 1.0 - chi_n;
    double work = 0.0, u_squared = 0.0;
    bool ok = true;
    for (int k = 0; k < D; ++k) {
      const double v = mean.velocity[k][i];
      const double v_s = mean.superflow_velocity[k][i];
      const double v_n = (v - chi_s * v_s) / chi_n; // eq. (22)
      const double target = chi_n * v_n * decay + chi_s * v_s;
      // The same raw increment to both copies.
      Raw increment{};
      ok = ok && Arith::try_from_real(target - v, v_scale, increment);
      const double dv = Arith::real(increment, v_scale);
      ok = ok && Arith::try_increment(v1.at(k, i), dv, v_scale) &&
           Arith::try_increment(v2.at(k, i), dv, v_scale);
      work += v_n * dv + 0.5 * dv * dv / chi_n;
      u_squared += (v + dv - v_s) * (v + dv - v_s);
    }
    ok = ok && add_entropy(i, entropy_for_heat(s, u_squared, mass[i], -mass[i] * work));
    if (!ok) {
      faults.record(i, "fluid", "velocity", "overflow or non-finite value in the superleak");
    }
  }
  faults.throw_if_any();
}

// Eq. (30): zeta_heat = W (w_H * delta)(r_a), the power per unit volume at a particle; over a
// step a particle gets the heat m_a zeta / rho_a dt, as entropy at fixed v, v_s (eq. 29).
template <int D, class Arith>
void Model<D, Arith>::heat(std::int64_t step) {
  const Heater<D>& heater = parameters_.heater;
  if (heater.power == 0.0) {
    return;
  }
  update_density();
  const Helium& he = parameters_.helium;
  const double time = static_cast<double>(step) * info_.dt;
  const double ramp = heater.ramp_time > 0.0 ? std::min(1.0, time / heater.ramp_time) : 1.0;
  const WendlandQuintic<D> spread(heater.support);
  const MeanState mean = mean_state();
  const std::span<const double> mass =
      layout_.part_of(std::span<const double>(mass_), state_.fluid);
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  const auto& x_scale = state_.fluid.position.info().scale;
  FaultRecorder faults;
  ExactDoubleSum given;
  for (std::size_t i = 0; i < fluid_count(); ++i) {
    double r_squared = 0.0, u_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double d = Arith::real(state_.fluid.position.at(k, i), x_scale) - heater.centre[k];
      const double u = mean.velocity[k][i] - mean.superflow_velocity[k][i];
      r_squared += d * d;
      u_squared += u * u;
    }
    const double w = spread.value(std::sqrt(r_squared));
    if (w == 0.0) {
      continue;
    }
    const double rho = density_sums_.value(0, fluid[i]);
    const double q = mass[i] * heater.power * ramp * w / rho * info_.dt;
    const double s = mean.entropy[i];
    const double before = he.thermal_energy(s) + he.counterflow_energy(s, u_squared);
    const double ds = entropy_for_heat(s, u_squared, mass[i], q);
    if (!add_entropy(i, ds)) {
      faults.record(i, "fluid", "entropy", "overflow or non-finite value in the heater");
    }
    const double s_new =
        0.5 *
        (Arith::real(state_.fluid.entropy.at(0, i), state_.fluid.entropy.info().scale) +
         Arith::real(state_.fluid.entropy_copy.at(0, i), state_.fluid.entropy_copy.info().scale));
    given.add(mass[i] *
              (he.thermal_energy(s_new) + he.counterflow_energy(s_new, u_squared) - before));
  }
  faults.throw_if_any();
  heater_energy_ += global_total(given);
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::superfluid
