#include "models/entropic/parameters.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "models/entropic/case_keys.hpp" // generated from keys.toml

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

namespace revsph::entropic {

namespace {

// Both laws have p = (gamma-1) rho c_V T - B and u = c_V T + B / rho (B = 0 for the ideal gas,
// equation_of_state.hpp), so the specific energy of (rho, p) is (p + B) / ((gamma-1) rho) + B / rho
// and sigma follows from the inverse of u(rho, sigma). Nothing when p + B <= 0 (no temperature
// reaches that pressure) or a value overflows.
std::optional<double> specific_entropy_for_pressure(const GasLaw& gas_law, double density,
                                                    double pressure) {
  return std::visit(
      [&](const auto& law) -> std::optional<double> {
        double stiffening = 0.0;
        if constexpr (std::is_same_v<std::decay_t<decltype(law)>, StiffenedGas>) {
          stiffening = stiffening_pressure(law);
        }
        const double thermal = (pressure + stiffening) / ((law.gamma - 1.0) * density); // c_V T
        if (!(thermal > 0.0) || !std::isfinite(thermal)) {
          return std::nullopt;
        }
        return specific_entropy_for_energy(law, density, thermal + stiffening / density);
      },
      gas_law);
}

// constants_error() names the constant first ("gamma must be > 1 (got 0.5)",
// "rest_density * sound_speed^2 must be finite ..."): that name is the key under [physics].
template <class Law>
void check_constants(const CaseFile& case_file, const Law& law) {
  if (const std::optional<std::string> error = constants_error(law)) {
    const std::size_t end = error->find_first_not_of("abcdefghijklmnopqrstuvwxyz_");
    case_file.fail("physics." + error->substr(0, end), *error);
  }
}

// "must be >= 0 and finite (got 1.000e+00)".

GasLaw read_gas_law(const CaseFile& case_file) {
  const Keys& k = keys();
  const GasLawName name = k.equation_of_state.read(case_file);
  const double gamma = k.gamma.read(case_file);
  const double heat_capacity = k.heat_capacity.read(case_file);
  if (name == GasLawName::ideal_gas) {
    for (const Key<double>* key : {&k.rest_density, &k.reference_pressure, &k.sound_speed}) {
      if (case_file.has(key->path())) {
        case_file.fail(key->path(), "only for equation_of_state = \"stiffened_gas\" (the ideal "
                                    "gas of eq. 88 has no reference state)");
      }
    }
    const IdealGas law{gamma, heat_capacity};
    check_constants(case_file, law);
    return law;
  }
  const StiffenedGas law{gamma, heat_capacity, k.rest_density.require(case_file),
                         k.reference_pressure.require(case_file), k.sound_speed.require(case_file)};
  check_constants(case_file, law);
  return law;
}

} // namespace

template <int D>
double Parameters<D>::initial_specific_entropy() const {
  const std::optional<double> sigma =
      specific_entropy_for_pressure(gas_law, initial_density, initial_pressure);
  if (!sigma) {
    throw std::invalid_argument("entropic SPH: no specific entropy gives the initial pressure at "
                                "the initial density");
  }
  return *sigma;
}

template <int D>
double Parameters<D>::initial_temperature() const {
  const double sigma = initial_specific_entropy();
  return std::visit([&](const auto& law) { return state(law, initial_density, sigma).temperature; },
                    gas_law);
}

// Hydrostatic equilibrium dp/dz = -rho g with p + B = R rho T (R = (gamma-1) c_V, both laws)
// and the linear T = T0 + G z: d ln(p + B) / dz = -g / (R T), so
// p + B = (p_c + B) exp(-(g / R) I(z)), I = ln(T / T0) / G (z / T0 for G = 0), rho = (p + B) / (R T).
template <int D>
std::optional<std::pair<double, double>> Parameters<D>::hydrostatic_state(double z) const {
  const double t0 = initial_temperature();
  const double g_t = initial_temperature_gradient[static_cast<std::size_t>(D - 1)];
  const double t = t0 + g_t * z;
  if (!(t > 0.0)) {
    return std::nullopt;
  }
  return std::visit(
      [&](const auto& law) -> std::optional<std::pair<double, double>> {
        double stiffening = 0.0;
        if constexpr (std::is_same_v<std::decay_t<decltype(law)>, StiffenedGas>) {
          stiffening = stiffening_pressure(law);
        }
        const double r = (law.gamma - 1.0) * law.heat_capacity;
        const double integral = g_t != 0.0 ? dmath::log(t / t0) / g_t : z / t0;
        const double shifted =
            (initial_pressure + stiffening) * dmath::exp(-gravity / r * integral); // p + B
        const double density = shifted / (r * t);
        const std::optional<double> sigma =
            specific_entropy_for_pressure(gas_law, density, shifted - stiffening);
        if (!sigma || !(density > 0.0) || !std::isfinite(density)) {
          return std::nullopt;
        }
        return std::pair{density, *sigma};
      },
      gas_law);
}

template <int D>
double Parameters<D>::initial_sound_speed() const {
  const double sigma = initial_specific_entropy();
  return std::sqrt(std::visit(
      [&](const auto& law) { return state(law, initial_density, sigma).sound_speed_squared; },
      gas_law));
}

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  const Keys& k = keys();
  Parameters<D> p = k.read_fields<Parameters<D>>(case_file);
  p.gas_law = read_gas_law(case_file);

  p.relaxation_time = k.relaxation_time.read_or(case_file, std::numeric_limits<double>::infinity());
  if (p.hyperbolic() && p.particles_move) {
    case_file.fail(k.flux_energy_coefficient.path(),
                   "the hyperbolic heat conduction of paper 4 §5.5 is derived for particles at "
                   "rest: set physics.particles_move = false");
  }
  if (p.hyperbolic() && p.volume != ParticleVolume::mass && p.volume != ParticleVolume::direct) {
    case_file.fail(k.flux_energy_coefficient.path(),
                   "needs a particle volume that does not depend on the entropies (the energy "
                   "c_w V |w|^2 of Fig. 13 and T = dE/dS): physics.particle_volume = \"mass\" "
                   "or \"direct\"");
  }

  if (!specific_entropy_for_pressure(p.gas_law, p.initial_density, p.initial_pressure)) {
    if (const auto* law = std::get_if<StiffenedGas>(&p.gas_law)) {
      case_file.fail(k.initial_pressure.path(),
                     "no temperature gives this pressure at initial.density: p + B must be > 0, "
                     "B = (rho0 c0^2 - gamma p0) / gamma = " +
                         format_scientific(stiffening_pressure(*law), 3) +
                         " (eq. 92), and the specific entropy finite");
    }
    case_file.fail(k.initial_pressure.path(),
                   "the specific entropy of this pressure at initial.density is not finite");
  }
  // The entropic volume V = S / s (eq. 24) needs S > 0 for every particle (§2.2; the paper's
  // conclusion: it is "sensitive to negative particle entropies").
  if (p.volume == ParticleVolume::entropic && !(p.initial_specific_entropy() > 0.0)) {
    case_file.fail(k.volume.path(),
                   "the entropic volume V = S / s needs positive particle entropies, but the "
                   "initial specific entropy is " +
                       format_scientific(p.initial_specific_entropy(), 3) +
                       " (raise initial.pressure at this initial.density)");
  }
  const double sound_speed = p.initial_sound_speed();
  require_positive_finite(case_file, k.initial_pressure.path().c_str(), "the initial sound speed c",
                          sound_speed);
  if (case_file.has(k.temperature_gradient)) {
    const std::vector<double> gradient = case_file.numbers(k.temperature_gradient, D);
    for (std::size_t axis = 0; axis < static_cast<std::size_t>(D); ++axis) {
      if (!std::isfinite(gradient[axis])) {
        case_file.fail(k.temperature_gradient, "must be finite");
      }
      p.initial_temperature_gradient[axis] = gradient[axis];
    }
  }

  if (p.initial_hydrostatic) {
    for (std::size_t axis = 0; axis + 1 < static_cast<std::size_t>(D); ++axis) {
      if (p.initial_temperature_gradient[axis] != 0.0) {
        case_file.fail(k.temperature_gradient,
                       "with initial.hydrostatic = true only its last (vertical) component may be "
                       "non-zero: a horizontal gradient has no hydrostatic state");
      }
    }
  }

  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, sound_speed);
  static_cast<ParticleDiscretisation&>(p) = discretisation;
  p.wall = read_wall_settings(case_file, discretisation);

  p.domain = read_domain<D>(case_file);

  // Default scales: positions keep 52 fraction bits below the domain size, so the double view of
  // a position is exact; momenta resolve m c * 2^-50 and entropies max(|m sigma0|, m c_V) * 2^-48
  // for the particle mass m = rho dr^D; kernel sums resolve rho * 2^-48.
  const double mass = p.initial_density * dmath::integer_power(p.dr, D);
  const double entropy_magnitude =
      std::max(std::abs(mass * p.initial_specific_entropy()), mass * p.heat_capacity());
  p.position_scale = k.position_exponent.read(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.momentum_scale = k.momentum_exponent.read(case_file, mass * sound_speed);
  p.entropy_scale = k.entropy_exponent.read(case_file, entropy_magnitude);
  p.density_scale = k.density_exponent.read(case_file, p.initial_density);
  // |w| stays below sqrt(rho c_V T / c_w): its energy c_w V |w|^2 cannot exceed the heat m c_V T.
  const double largest_flux = p.hyperbolic()
                                  ? std::sqrt(p.initial_density * p.heat_capacity() *
                                              p.initial_temperature() / p.flux_energy_coefficient)
                                  : 1.0;
  require_positive_finite(case_file, k.flux_energy_coefficient.path().c_str(),
                          "sqrt(rho c_V T0 / c_w), the scale of the entropy flux w", largest_flux);
  p.entropy_flux_scale = k.entropy_flux_exponent.read(case_file, largest_flux);
  // The heat flux q of eq. (54) reaches about lambda_F T0^2 / h (model.cpp).
  if (p.heat_conductivity > 0.0) {
    const double t0 = p.initial_temperature();
    require_positive_finite(case_file, k.heat_conductivity.path().c_str(),
                            "lambda_F T0^2 / h, the scale of the heat flux",
                            p.heat_conductivity * t0 * t0 / p.support_radius);
  }
  return p;
}

template struct Parameters<1>;
template struct Parameters<2>;
template struct Parameters<3>;
template Parameters<1> read_parameters<1>(const CaseFile&);
template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::entropic
