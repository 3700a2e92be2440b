#pragma once
// Equations of state of entropic SPH (Pavelka, Klika, Kincl 2024,
// arXiv 2406.14229, Appendix C), pointwise; equation numbers are that paper's.
//
// Variables: rho mass density, s entropy per volume, sigma = s / rho = S_a / m_a entropy per mass
// (what a particle carries between dissipative updates), eps(rho, s) energy per volume,
// u = eps / rho. The thermodynamic quantities are the derivatives of eps (eq. 35; mu as in App. C):
//   p = -eps + rho eps_rho + s eps_s,   T = eps_s,   mu = eps_rho.
//
// Both equations of state have the form eps = eps1 + B with eps1 = rho c_V T and
// T = T_ref rho^(gamma-1) e^(sigma / c_V) (B = 0 for the ideal gas). From that, for both:
//   u = c_V T + B / rho,  p = (gamma-1) rho c_V T - B,  mu = (gamma c_V - sigma) T,
//   c^2 = dp/drho at fixed sigma = gamma (gamma-1) c_V T = gamma (p + B) / rho,
// so state() computes T (one pow, one exp) and the rest from it.
//
// Ideal gas (eqs. 88, 89): eps = rho^gamma e^(s / (rho c_V)) / (gamma-1). The paper sets the
// equation's constant to 1: sigma = 0 means p = rho^gamma in the case's units.
// Stiffened gas (eqs. 90-92): eps = c0^2 / (gamma (gamma-1)) rho (rho/rho0)^(gamma-1)
// e^(s / (rho c_V)) + B with B = (rho0 c0^2 - gamma p0) / gamma. Reference state rho = rho0,
// sigma = 0: p = p0, c = c0, T = T0 = c0^2 / (gamma (gamma-1) c_V).
//
// Slip: eq. (91c) prints the second term of mu without the factor e^(s / (rho c_V)); the
// derivative of eq. (90) has it (mu = (gamma c_V - sigma) T above). The printed form is right
// only at s = 0 (tests/unit/entropic_equation_of_state_test.cpp checks both against finite
// differences of eq. 90). Eq. (89c) for the ideal gas is right.
//
// pow and exp are not correctly rounded: results are reproducible bit for bit only with one libm.

#include "fixedpoint/deterministic_math.hpp"

#include <charconv>
#include <cmath>
#include <concepts>
#include <optional>
#include <string>

namespace revsph::entropic {

struct IdealGas {
  double gamma = 1.4;         // c_P / c_V
  double heat_capacity = 1.0; // c_V
};

struct StiffenedGas {
  double gamma = 1.4;
  double heat_capacity = 1.0;      // c_V
  double rest_density = 1.0;       // rho0
  double reference_pressure = 0.0; // p0
  double sound_speed = 1.0;        // c0
};

// Everything the particle loop needs from (rho, sigma).
struct ThermodynamicState {
  double pressure = 0.0;
  double temperature = 0.0;
  double specific_energy = 0.0; // u = eps / rho
  double chemical_potential = 0.0;
  double sound_speed_squared = 0.0;
};

// B = (rho0 c0^2 - gamma p0) / gamma, the constant of eq. (90); p + B = (gamma-1) eps1.
inline double stiffening_pressure(const StiffenedGas& eos) {
  return (eos.rest_density * eos.sound_speed * eos.sound_speed -
          eos.gamma * eos.reference_pressure) /
         eos.gamma;
}

// T0 = T(rho0, sigma = 0) of eq. (91b).
inline double reference_temperature(const StiffenedGas& eos) {
  return eos.sound_speed * eos.sound_speed / (eos.gamma * (eos.gamma - 1.0) * eos.heat_capacity);
}

// eps(rho, s) of eqs. 88 and 90, with rho^a e^b as one e^(a ln rho + b): a log and an exp cost a
// third of a pow and an exp, and change the value by a few ulp.
inline double energy_density(const IdealGas& eos, double density, double entropy_density) {
  return dmath::exp(eos.gamma * dmath::log(density) +
                    entropy_density / (density * eos.heat_capacity)) /
         (eos.gamma - 1.0);
}
inline double energy_density(const StiffenedGas& eos, double density, double entropy_density) {
  const double c0_squared = eos.sound_speed * eos.sound_speed;
  return density * (c0_squared / (eos.gamma * (eos.gamma - 1.0)) *
                        dmath::exp((eos.gamma - 1.0) * dmath::log(density / eos.rest_density) +
                                   entropy_density / (eos.heat_capacity * density)) +
                    (eos.rest_density * c0_squared - eos.gamma * eos.reference_pressure) /
                        (eos.gamma * density));
}

// T(rho, sigma): eqs. (89b) and (91b) with s / rho = sigma. Needs rho > 0.
inline double temperature(const IdealGas& eos, double density, double specific_entropy) {
  return dmath::exp((eos.gamma - 1.0) * dmath::log(density) +
                    specific_entropy / eos.heat_capacity) /
         (eos.heat_capacity * (eos.gamma - 1.0));
}
inline double temperature(const StiffenedGas& eos, double density, double specific_entropy) {
  return reference_temperature(eos) *
         dmath::exp((eos.gamma - 1.0) * dmath::log(density / eos.rest_density) +
                    specific_entropy / eos.heat_capacity);
}

namespace detail {

// The rest of the state from T (see the top of the file); stiffening = 0 for the ideal gas.
inline ThermodynamicState state_from_temperature(double gamma, double heat_capacity,
                                                 double stiffening, double density,
                                                 double specific_entropy, double temperature) {
  const double thermal = heat_capacity * temperature; // c_V T = eps1 / rho
  ThermodynamicState state;
  state.temperature = temperature;
  state.specific_energy = thermal + stiffening / density;          // (88), (90)
  state.pressure = (gamma - 1.0) * density * thermal - stiffening; // (89a), (91a), (92)
  // (89c), and (91c) corrected: mu = (eps1 / rho) (gamma - sigma / c_V).
  state.chemical_potential = (gamma * heat_capacity - specific_entropy) * temperature;
  state.sound_speed_squared = gamma * (gamma - 1.0) * thermal; // derived
  return state;
}

// sigma with c_V T = thermal at T = temperature_scale e^(sigma / c_V), or nothing.
inline std::optional<double> entropy_for_thermal_energy(double heat_capacity, double thermal,
                                                        double temperature_scale) {
  const double ratio = thermal / (heat_capacity * temperature_scale);
  if (!(ratio > 0.0) || !std::isfinite(ratio)) {
    return std::nullopt;
  }
  const double specific_entropy = heat_capacity * dmath::log(ratio);
  if (!std::isfinite(specific_entropy)) {
    return std::nullopt;
  }
  return specific_entropy;
}

inline std::string format_number(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

// "name must be > bound (got value)", or nothing when finite and above the bound.
inline std::optional<std::string> above(const char* name, double value, double bound,
                                        const char* bound_text) {
  if (!std::isfinite(value)) {
    return std::string(name) + " must be finite (got " + format_number(value) + ")";
  }
  if (!(value > bound)) {
    return std::string(name) + " must be > " + bound_text + " (got " + format_number(value) + ")";
  }
  return std::nullopt;
}

} // namespace detail

// All of ThermodynamicState at once: one pow and one exp.
inline ThermodynamicState state(const IdealGas& eos, double density, double specific_entropy) {
  return detail::state_from_temperature(eos.gamma, eos.heat_capacity, 0.0, density,
                                        specific_entropy,
                                        temperature(eos, density, specific_entropy));
}
inline ThermodynamicState state(const StiffenedGas& eos, double density, double specific_entropy) {
  return detail::state_from_temperature(eos.gamma, eos.heat_capacity, stiffening_pressure(eos),
                                        density, specific_entropy,
                                        temperature(eos, density, specific_entropy));
}

// The inverse of u(rho, sigma) at fixed rho, for the energy-conserving entropy update (digest
// §4.5): u = c_V T + B / rho with T = T_ref rho^(gamma-1) e^(sigma / c_V) gives
//   sigma = c_V ln((u - B / rho) / (c_V T_ref rho^(gamma-1))).
// Nothing when u is not reachable (u <= B / rho; u <= 0 for the ideal gas), rho is not positive
// and finite, or sigma would overflow.
inline std::optional<double> specific_entropy_for_energy(const IdealGas& eos, double density,
                                                         double specific_energy) {
  if (!(density > 0.0) || !std::isfinite(density)) {
    return std::nullopt;
  }
  // T_ref rho^(gamma-1) = T(rho, 0) = rho^(gamma-1) / (c_V (gamma-1)).
  return detail::entropy_for_thermal_energy(eos.heat_capacity, specific_energy,
                                            temperature(eos, density, 0.0));
}
inline std::optional<double> specific_entropy_for_energy(const StiffenedGas& eos, double density,
                                                         double specific_energy) {
  if (!(density > 0.0) || !std::isfinite(density)) {
    return std::nullopt;
  }
  return detail::entropy_for_thermal_energy(eos.heat_capacity,
                                            specific_energy - stiffening_pressure(eos) / density,
                                            temperature(eos, density, 0.0));
}

// The same inverse as an increment, accurate for small du: at fixed rho, u changes only through
// c_V T, so u + du is reached at sigma + c_V ln(1 + du / (c_V T)) for both equations of state
// (digest §4.5). Nothing when du <= -c_V T (the energy would fall to or below its T = 0 bound).
inline std::optional<double> specific_entropy_change(double heat_capacity, double temperature,
                                                     double specific_energy_change) {
  const double relative = specific_energy_change / (heat_capacity * temperature);
  if (!(relative > -1.0) || !std::isfinite(relative)) {
    return std::nullopt;
  }
  return heat_capacity * dmath::log1p(relative);
}

// The first bad constant as "name must be ... (got value)", or nothing when all are valid.
inline std::optional<std::string> constants_error(const IdealGas& eos) {
  if (auto error = detail::above("gamma", eos.gamma, 1.0, "1")) {
    return error;
  }
  return detail::above("heat_capacity", eos.heat_capacity, 0.0, "0");
}
inline std::optional<std::string> constants_error(const StiffenedGas& eos) {
  if (auto error = detail::above("gamma", eos.gamma, 1.0, "1")) {
    return error;
  }
  if (auto error = detail::above("heat_capacity", eos.heat_capacity, 0.0, "0")) {
    return error;
  }
  if (auto error = detail::above("rest_density", eos.rest_density, 0.0, "0")) {
    return error;
  }
  if (auto error = detail::above("sound_speed", eos.sound_speed, 0.0, "0")) {
    return error;
  }
  if (!std::isfinite(eos.reference_pressure)) {
    return "reference_pressure must be finite (got " +
           detail::format_number(eos.reference_pressure) + ")";
  }
  // Finite constants can still overflow the derived ones (c0 = 1e200, c_V = 1e-300).
  const double stiff = eos.rest_density * eos.sound_speed * eos.sound_speed;
  if (!std::isfinite(stiff) || !std::isfinite(stiffening_pressure(eos))) {
    return "rest_density * sound_speed^2 must be finite (got " + detail::format_number(stiff) + ")";
  }
  const double t0 = reference_temperature(eos);
  if (!std::isfinite(t0) || !(t0 > 0.0)) {
    return "sound_speed^2 / (gamma (gamma-1) heat_capacity), the reference temperature, must be "
           "finite and > 0 (got " +
           detail::format_number(t0) + ")";
  }
  return std::nullopt;
}

// What an equation of state provides (IdealGas, StiffenedGas).
template <class Eos>
concept EquationOfState = requires(const Eos& eos, double x) {
  { energy_density(eos, x, x) } -> std::same_as<double>;
  { state(eos, x, x) } -> std::same_as<ThermodynamicState>;
  { specific_entropy_for_energy(eos, x, x) } -> std::same_as<std::optional<double>>;
  { constants_error(eos) } -> std::same_as<std::optional<std::string>>;
};

} // namespace revsph::entropic
