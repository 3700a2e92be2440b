// What the superfluid model reports: energy (eq. 15), per-particle views, copy diagnostics.
#include "fixedpoint/deterministic_math.hpp"
#include "models/superfluid/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace revsph::superfluid {

template <int D, class Arith>
typename Model<D, Arith>::MeanState Model<D, Arith>::mean_state() const {
  const auto& f = state_.fluid;
  const auto& v_scale = f.velocity.info().scale;
  const auto& s_scale = f.entropy.info().scale;
  const std::size_t n = fluid_count();
  MeanState mean;
  mean.entropy.resize(n);
  for (int k = 0; k < D; ++k) {
    mean.velocity[k].resize(n);
    mean.superflow_velocity[k].resize(n);
    for (std::size_t a = 0; a < n; ++a) {
      mean.velocity[k][a] = 0.5 * (Arith::real(f.velocity.at(k, a), v_scale) +
                                   Arith::real(f.velocity_copy.at(k, a), v_scale));
      mean.superflow_velocity[k][a] =
          0.5 * (Arith::real(f.superflow_velocity.at(k, a), v_scale) +
                 Arith::real(f.superflow_velocity_copy.at(k, a), v_scale));
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    mean.entropy[a] = 0.5 * (Arith::real(f.entropy.at(0, a), s_scale) +
                             Arith::real(f.entropy_copy.at(0, a), s_scale));
  }
  return mean;
}

template <int D, class Arith>
EnergyBudget Model<D, Arith>::energy() {
  update_density();
  const Helium& he = parameters_.helium;
  const MeanState mean = mean_state();
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  const std::span<const std::uint32_t> dummy = layout_.slots_of(state_.dummy);
  const std::span<const double> mass =
      layout_.part_of(std::span<const double>(mass_), state_.fluid);
  const std::span<const double> dummy_mass =
      layout_.part_of(std::span<const double>(mass_), state_.dummy);
  // Exact sums (core/global_totals.hpp): the same value for any thread or process count.
  ExactDoubleSum kinetic, counterflow, compressional, thermal, gravitational;
  const auto& x_scale = state_.fluid.position.info().scale;
  for (std::size_t a = 0; a < fluid.size(); ++a) {
    double v_squared = 0.0, relative_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double v = mean.velocity[k][a];
      const double u = v - mean.superflow_velocity[k][a];
      v_squared += v * v;
      relative_squared += u * u;
    }
    const double s = mean.entropy[a];
    kinetic.add(mass[a] * 0.5 * v_squared);
    counterflow.add(mass[a] * he.counterflow_energy(s, relative_squared));
    compressional.add(mass[a] * he.compressional_energy(density_sums_.value(0, fluid[a])));
    thermal.add(mass[a] * he.thermal_energy(s));
    gravitational.add(mass[a] * parameters_.gravity *
                      (Arith::real(state_.fluid.position.at(D - 1, a), x_scale) -
                       parameters_.gravity_reference_height));
  }
  for (std::size_t d = 0; d < dummy.size(); ++d) {
    compressional.add(dummy_mass[d] *
                      he.boundary_compressional_energy(density_sums_.value(0, dummy[d])));
  }
  const std::span<const std::uint32_t> wall = layout_.slots_of(state_.wall);
  const std::span<const double> wall_mass =
      layout_.part_of(std::span<const double>(mass_), state_.wall);
  for (std::size_t w = 0; w < wall.size(); ++w) {
    compressional.add(wall_mass[w] *
                      he.boundary_compressional_energy(density_sums_.value(0, wall[w])));
  }
  return EnergyBudget{{{"kinetic", global_total(kinetic)},
                       {"counterflow", global_total(counterflow)},
                       {"compressional", global_total(compressional)},
                       {"thermal", global_total(thermal)},
                       {"gravitational", global_total(gravitational)},
                       {"wall_exchange", -exchanged_energy_},
                       {"heater_input", -heater_energy_}}};
}

template <int D, class Arith>
std::vector<EnergyTerm> Model<D, Arith>::diagnostics(double time) {
  const auto& f = state_.fluid;
  const auto& v_scale = f.velocity.info().scale;
  const auto& s_scale = f.entropy.info().scale;
  update_constants();
  const std::span<const double> mass =
      layout_.part_of(std::span<const double>(mass_), state_.fluid);
  double dv = 0.0, dvs = 0.0, ds = 0.0;
  ExactDoubleSum entropy_one, entropy_two;
  for (std::size_t a = 0; a < fluid_count(); ++a) {
    for (int k = 0; k < D; ++k) {
      dv = std::max(dv, std::abs(Arith::real(f.velocity.at(k, a), v_scale) -
                                 Arith::real(f.velocity_copy.at(k, a), v_scale)));
      dvs = std::max(dvs, std::abs(Arith::real(f.superflow_velocity.at(k, a), v_scale) -
                                   Arith::real(f.superflow_velocity_copy.at(k, a), v_scale)));
    }
    const double s1 = Arith::real(f.entropy.at(0, a), s_scale);
    const double s2 = Arith::real(f.entropy_copy.at(0, a), s_scale);
    ds = std::max(ds, std::abs(s1 - s2));
    entropy_one.add(mass[a] * s1);
    entropy_two.add(mass[a] * s2);
  }
  const std::string specific_entropy = f.entropy.info().unit;
  std::vector<EnergyTerm> terms{{"copy_velocity_difference", global_max(dv), "m/s"},
                                {"copy_superflow_difference", global_max(dvs), "m/s"},
                                {"copy_entropy_difference", global_max(ds), specific_entropy},
                                {"total_entropy", global_total(entropy_one), entropy_unit<D>},
                                {"total_entropy_copy", global_total(entropy_two), entropy_unit<D>}};
  if (!std::isnan(parameters_.jet_height)) {
    update_density();
    const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
    const auto& x_scale = f.position.info().scale;
    ExactDoubleSum volume;
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      if (Arith::real(f.position.at(D - 1, a), x_scale) > parameters_.jet_height) {
        volume.add(mass[a] / density_sums_.value(0, fluid[a]));
      }
    }
    terms.push_back({"volume_above_jet_height", global_total(volume), volume_unit<D>});
  }
  const InitialFields& wave = parameters_.initial;
  if (wave.wave_amplitude != 0.0) {
    const Helium& he = parameters_.helium;
    const double s0 = he.reference_entropy;
    const double pi = std::numbers::pi;
    // Eq. (25): s0 + A s0 prod_k sin(pi x_k / L) cos(sqrt(D) pi u2 t / L) (the 2D formula's
    // frequency sqrt(2) pi u2 / L is the mode's |k| u2); cosines for the adiabatic mode.
    const double phase = dmath::cos(std::sqrt(static_cast<double>(D)) * pi *
                                    he.second_sound_speed() * time / wave.wave_length);
    auto exact = [&](const std::array<double, D>& x) {
      double value = wave.wave_amplitude * s0 * phase;
      for (int k = 0; k < D; ++k) {
        const double angle = pi * x[k] / wave.wave_length;
        value *= wave.wave_cosine ? dmath::cos(angle) : dmath::sin(angle);
      }
      return s0 + value;
    };
    const MeanState mean = mean_state();
    const auto& x_scale = f.position.info().scale;
    std::array<double, D> probe_point{};
    probe_point.fill(0.25 * wave.wave_length);
    ExactDoubleSum squared;
    NearestParticle probe;
    for (std::size_t a = 0; a < fluid_count(); ++a) {
      std::array<double, D> x{};
      double distance = 0.0;
      for (int k = 0; k < D; ++k) {
        x[k] = Arith::real(f.position.at(k, a), x_scale);
        distance += (x[k] - probe_point[k]) * (x[k] - probe_point[k]);
      }
      const double error = (mean.entropy[a] - exact(x)) / (wave.wave_amplitude * s0);
      squared.add(error * error);
      probe.offer(distance, layout_.run_index(state_.fluid, a), mean.entropy[a]);
    }
    terms.push_back({"second_sound_error",
                     sqrt(global_total(squared) / static_cast<double>(global_count(fluid_count()))),
                     "1"});
    terms.push_back({"probe_entropy", global_value_of_nearest(probe), specific_entropy});
    // Eq. (25) at the probe point: a function of the time and the case alone.
    terms.push_back({"probe_entropy_exact", RunTotal::same_on_every_process(exact(probe_point)),
                     specific_entropy});
  }
  return terms;
}

template <int D, class Arith>
void Model<D, Arith>::derived_views(const ViewSink& sink) {
  update_density();
  const Helium& he = parameters_.helium;
  const MeanState mean = mean_state();
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  const std::size_t n = fluid.size();
  std::vector<double> density(n), pressure(n), temperature(n), normal_fraction(n);
  std::vector<double> counterflow(D * n), normal_velocity(D * n);
  for (std::size_t a = 0; a < n; ++a) {
    const double rho = density_sums_.value(0, fluid[a]);
    const double s = mean.entropy[a];
    const double chi_n = he.chi_n(s);
    double w_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      const double u = mean.velocity[k][a] - mean.superflow_velocity[k][a];
      counterflow[k * n + a] = u / chi_n;                                           // v_ns
      normal_velocity[k * n + a] = mean.velocity[k][a] + (1.0 - chi_n) / chi_n * u; // v_n
      w_squared += u * u / (chi_n * chi_n);
    }
    density[a] = rho;
    pressure[a] = he.pressure(rho);
    temperature[a] = he.temperature(s, w_squared);
    normal_fraction[a] = chi_n;
  }
  auto component_major = [n](const std::array<std::vector<double>, D>& vectors) {
    std::vector<double> values;
    values.reserve(D * n);
    for (int k = 0; k < D; ++k) {
      values.insert(values.end(), vectors[k].begin(), vectors[k].end());
    }
    return values;
  };
  sink(ParticleView{"fluid", "density", "kg/m^3", 1, std::move(density)});
  sink(ParticleView{"fluid", "pressure", "Pa", 1, std::move(pressure)});
  sink(ParticleView{"fluid", "temperature", "K", 1, std::move(temperature)});
  sink(ParticleView{"fluid", "normal_fraction", "1", 1, std::move(normal_fraction)});
  sink(ParticleView{"fluid", "mean_velocity", "m/s", D, component_major(mean.velocity)});
  sink(ParticleView{"fluid", "mean_superflow_velocity", "m/s", D,
                    component_major(mean.superflow_velocity)});
  sink(ParticleView{"fluid", "mean_entropy", "J/(kg K)", 1, std::vector<double>(mean.entropy)});
  sink(ParticleView{"fluid", "counterflow_velocity", "m/s", D, std::move(counterflow)});
  sink(ParticleView{"fluid", "normal_velocity", "m/s", D, std::move(normal_velocity)});
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::superfluid
