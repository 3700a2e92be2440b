// Entropic SPH equations of state (models/entropic/equation_of_state.hpp; Pavelka,
// Klika, Kincl 2024, App. C):
// p, T, mu and c^2 against central finite differences of eps(rho, s) as printed in eqs. (88) and
// (90), the stiffened gas's reference state, the slip in eq. (91c), the ideal gas's adiabatic
// law, the inverse sigma(u, rho) and the messages for bad constants.

#include "models/entropic/equation_of_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace {

using revsph::entropic::IdealGas;
using revsph::entropic::StiffenedGas;
using revsph::entropic::ThermodynamicState;

static_assert(revsph::entropic::EquationOfState<IdealGas>);
static_assert(revsph::entropic::EquationOfState<StiffenedGas>);

const IdealGas ideal_gas{1.4, 1.0}; // the adiabatic expansion (§4.6)
const IdealGas monatomic_gas{5.0 / 3.0, 2.5};
// Fig. 13's constants, with c0 = 10 sqrt(gamma p0 / rho0) from the authors' heat.jl (the paper
// gives no c0), and a water-like liquid where the constant B dominates the energy.
const StiffenedGas hyperbolic_heat{1.6, 1.0, 10.0, 10.0, 10.0 * std::sqrt(1.6)};
const StiffenedGas water{7.0, 4186.0, 1000.0, 1.0e5, 1500.0};

struct Point {
  double density;
  double specific_entropy;
};

// rho around its reference, sigma / c_V in [-1.5, 2]: T spans a factor of ~30 at each density.
std::vector<Point> points(double rest_density, double heat_capacity) {
  std::vector<Point> result;
  for (const double density : {0.5, 0.97, 1.0, 1.3, 2.0}) {
    for (const double entropy : {-1.5, 0.0, 0.4, 2.0}) {
      result.push_back({density * rest_density, entropy * heat_capacity});
    }
  }
  return result;
}

// Central differences of eps(rho, s) in rho and in s. Steps: h = 1e-5 of the natural scales,
// rho for rho and rho c_V for s (s enters only through e^(s / (rho c_V))). The truncation error
// is h^2 / 6 times the third derivative: ~2e-11 relative, times at most ~100 from the factors
// (gamma - sigma / c_V)^3 at these points. Rounding of eps (|eps| + |B| ~ 1e-16 relative) divided
// by 2h gives ~1e-11 relative to (|eps| + |B|) / rho. A tolerance of 1e-7 of those scales is far
// above both and far below the size of any error in the formulas (the slip in eq. 91c is ~1).
constexpr double relative_step = 1e-5;
constexpr double tolerance = 1e-7;

struct Derivatives {
  double by_density;         // eps_rho = mu
  double by_entropy_density; // eps_s = T
};

template <class Eos>
Derivatives finite_differences(const Eos& eos, double density, double entropy_density) {
  const double d_rho = relative_step * density;
  const double d_s = relative_step * density * eos.heat_capacity;
  using revsph::entropic::energy_density;
  return {(energy_density(eos, density + d_rho, entropy_density) -
           energy_density(eos, density - d_rho, entropy_density)) /
              (2.0 * d_rho),
          (energy_density(eos, density, entropy_density + d_s) -
           energy_density(eos, density, entropy_density - d_s)) /
              (2.0 * d_s)};
}

double stiffening(const IdealGas&) {
  return 0.0;
}
double stiffening(const StiffenedGas& eos) {
  return revsph::entropic::stiffening_pressure(eos);
}

double rest_density(const IdealGas&) {
  return 1.0;
}
double rest_density(const StiffenedGas& eos) {
  return eos.rest_density;
}

template <class Eos>
void expect_thermodynamics_of_the_energy(const Eos& eos) {
  for (const Point& point : points(rest_density(eos), eos.heat_capacity)) {
    const double rho = point.density;
    const double s = rho * point.specific_entropy;
    const double eps = revsph::entropic::energy_density(eos, rho, s);
    const ThermodynamicState state = revsph::entropic::state(eos, rho, point.specific_entropy);
    const Derivatives numeric = finite_differences(eos, rho, s);
    const double energy_scale = std::fabs(eps) + std::fabs(stiffening(eos));
    const std::string where =
        "rho = " + std::to_string(rho) + ", sigma = " + std::to_string(point.specific_entropy);

    EXPECT_NEAR(state.specific_energy * rho, eps, 1e-13 * energy_scale) << where;
    EXPECT_NEAR(state.temperature, numeric.by_entropy_density,
                tolerance * (state.temperature + energy_scale / (rho * eos.heat_capacity)))
        << where;
    EXPECT_NEAR(state.chemical_potential, numeric.by_density,
                tolerance * (std::fabs(state.chemical_potential) + energy_scale / rho))
        << where;
    // p = -eps + rho eps_rho + s eps_s (eq. 35), every term from the differences.
    const double numeric_pressure =
        -eps + rho * numeric.by_density + s * numeric.by_entropy_density;
    EXPECT_NEAR(state.pressure, numeric_pressure,
                tolerance * (energy_scale + rho * std::fabs(state.chemical_potential) +
                             std::fabs(s) * state.temperature))
        << where;
  }
}

TEST(EntropicEquationOfState, IdealGasPressureTemperatureAndChemicalPotentialAreDerivatives) {
  expect_thermodynamics_of_the_energy(ideal_gas);
  expect_thermodynamics_of_the_energy(monatomic_gas);
}

TEST(EntropicEquationOfState, StiffenedGasPressureTemperatureAndChemicalPotentialAreDerivatives) {
  expect_thermodynamics_of_the_energy(hyperbolic_heat);
  expect_thermodynamics_of_the_energy(water);
}

// c^2 = dp/drho at fixed sigma (the isentropic sound speed), by central differences of p; same
// step and error budget as above with the scale (|p| + |B|) / rho of dp/drho.
template <class Eos>
void expect_sound_speed_is_isentropic_derivative(const Eos& eos) {
  for (const Point& point : points(rest_density(eos), eos.heat_capacity)) {
    const double rho = point.density;
    const double sigma = point.specific_entropy;
    const double d_rho = relative_step * rho;
    const double numeric = (revsph::entropic::state(eos, rho + d_rho, sigma).pressure -
                            revsph::entropic::state(eos, rho - d_rho, sigma).pressure) /
                           (2.0 * d_rho);
    const ThermodynamicState state = revsph::entropic::state(eos, rho, sigma);
    EXPECT_GT(state.sound_speed_squared, 0.0);
    EXPECT_NEAR(state.sound_speed_squared, numeric,
                tolerance * (state.sound_speed_squared +
                             (std::fabs(state.pressure) + std::fabs(stiffening(eos))) / rho))
        << "rho = " << rho << ", sigma = " << sigma;
    // c^2 = gamma (p + B) / rho, as in the header.
    EXPECT_NEAR(state.sound_speed_squared, eos.gamma * (state.pressure + stiffening(eos)) / rho,
                1e-13 * eos.gamma * (std::fabs(state.pressure) + std::fabs(stiffening(eos))) / rho);
  }
}

TEST(EntropicEquationOfState, SoundSpeedIsTheIsentropicPressureDerivative) {
  expect_sound_speed_is_isentropic_derivative(ideal_gas);
  expect_sound_speed_is_isentropic_derivative(monatomic_gas);
  expect_sound_speed_is_isentropic_derivative(hyperbolic_heat);
  expect_sound_speed_is_isentropic_derivative(water);
}

TEST(EntropicEquationOfState, StiffenedGasReferenceState) {
  for (const StiffenedGas& eos : {hyperbolic_heat, water}) {
    const ThermodynamicState state = revsph::entropic::state(eos, eos.rest_density, 0.0);
    const double t0 =
        eos.sound_speed * eos.sound_speed / (eos.gamma * (eos.gamma - 1.0) * eos.heat_capacity);
    // pow(1, x) = exp(0) = 1 exactly, so T = T0; p = p0 up to the cancellation in
    // rho0 c0^2 / gamma - B.
    EXPECT_DOUBLE_EQ(state.temperature, t0);
    EXPECT_DOUBLE_EQ(revsph::entropic::reference_temperature(eos), t0);
    EXPECT_NEAR(state.pressure, eos.reference_pressure,
                1e-14 * eos.rest_density * eos.sound_speed * eos.sound_speed);
    EXPECT_NEAR(std::sqrt(state.sound_speed_squared), eos.sound_speed, 1e-14 * eos.sound_speed);
    // And the one-parameter family through it: p(rho0, s) = p0 + rho0 c0^2 / gamma (e^sigma/c_V - 1).
    const double sigma = 0.3 * eos.heat_capacity;
    EXPECT_NEAR(revsph::entropic::state(eos, eos.rest_density, sigma).pressure,
                eos.reference_pressure + eos.rest_density * eos.sound_speed * eos.sound_speed /
                                             eos.gamma * std::expm1(0.3),
                1e-13 * eos.rest_density * eos.sound_speed * eos.sound_speed);
  }
}

// Eq. (91c) as printed: the second term lacks e^(s / (rho c_V)).
double printed_chemical_potential(const StiffenedGas& eos, double rho, double s) {
  const double c0_squared = eos.sound_speed * eos.sound_speed;
  const double g = eos.gamma;
  const double power = std::pow(rho / eos.rest_density, g - 1.0);
  return c0_squared / (g - 1.0) * power * std::exp(s / (rho * eos.heat_capacity)) -
         rho * c0_squared / (g * (g - 1.0)) * power * s / (rho * rho * eos.heat_capacity);
}

TEST(EntropicEquationOfState, PrintedStiffenedGasChemicalPotentialIsWrongAwayFromZeroEntropy) {
  const StiffenedGas& eos = hyperbolic_heat;
  for (const double rho : {5.0, 10.0, 17.0}) {
    // At s = 0 the missing factor is 1: printed and corrected agree.
    const double at_zero = finite_differences(eos, rho, 0.0).by_density;
    EXPECT_NEAR(printed_chemical_potential(eos, rho, 0.0), at_zero, tolerance * at_zero);
    for (const double sigma : {-1.0, 0.5, 2.0}) {
      const double s = rho * sigma;
      const double numeric = finite_differences(eos, rho, s).by_density;
      const double corrected = revsph::entropic::state(eos, rho, sigma).chemical_potential;
      const double printed = printed_chemical_potential(eos, rho, s);
      const double scale = std::fabs(numeric) + std::fabs(stiffening(eos)) / rho;
      EXPECT_NEAR(corrected, numeric, tolerance * scale)
          << "rho = " << rho << ", sigma = " << sigma;
      // printed - true = (eps1 / rho) (sigma / c_V) (1 - e^(-sigma/c_V)): 20 % to 170 % of
      // eps1 / rho = c_V T here, at least 9e5 times the tolerance.
      EXPECT_GT(std::fabs(printed - numeric), 1e4 * tolerance * scale)
          << "rho = " << rho << ", sigma = " << sigma;
    }
  }
}

TEST(EntropicEquationOfState, IdealGasAdiabaticLawAndPressureFromEnergy) {
  for (const IdealGas& eos : {ideal_gas, monatomic_gas}) {
    for (const double sigma : {-1.0, 0.0, 1.7}) {
      const double reference =
          revsph::entropic::state(eos, 1.0, sigma).temperature; // T rho^(1-gamma) at rho = 1
      for (const double rho : {0.1, 0.5, 2.0, 30.0}) {
        const ThermodynamicState state = revsph::entropic::state(eos, rho, sigma);
        // Few roundings in each of pow and exp, and one in rho^(1-gamma) here.
        EXPECT_NEAR(state.temperature * std::pow(rho, 1.0 - eos.gamma), reference,
                    1e-14 * reference);
        // p = (gamma - 1) eps (eq. 89a) with eps as printed in eq. (88); that exp sees s / rho,
        // which may differ from sigma in the last bit: relative error ~ |sigma / c_V| 1e-16.
        const double eps = revsph::entropic::energy_density(eos, rho, rho * sigma);
        EXPECT_NEAR(state.pressure, (eos.gamma - 1.0) * eps, 1e-14 * state.pressure);
        // p = rho^gamma e^(sigma / c_V) (eq. 89a) and eps = rho c_V T (after eq. 89c).
        EXPECT_NEAR(state.pressure, std::pow(rho, eos.gamma) * std::exp(sigma / eos.heat_capacity),
                    1e-14 * state.pressure);
        EXPECT_NEAR(eps, rho * eos.heat_capacity * state.temperature, 1e-14 * eps);
      }
    }
  }
}

// sigma(u(rho, sigma), rho) = sigma. u carries a relative rounding error of a few 1e-16 from
// pow and exp; c_V ln(...) turns a relative error e of its argument into an absolute error c_V e.
// For the stiffened gas u - B / rho magnifies e by (|u| + |B| / rho) / (c_V T): up to ~3e3 for
// the water at half its rest density and sigma = -1.5 c_V (measured error 6e-14 (|sigma| + c_V));
// the ideal gas and the gas of Fig. 13 stay below 3e-16. 1e-12 (|sigma| + c_V) covers all.
template <class Eos>
void expect_inverse_recovers_entropy(const Eos& eos) {
  for (const Point& point : points(rest_density(eos), eos.heat_capacity)) {
    const double u =
        revsph::entropic::state(eos, point.density, point.specific_entropy).specific_energy;
    const std::optional<double> sigma =
        revsph::entropic::specific_entropy_for_energy(eos, point.density, u);
    ASSERT_TRUE(sigma.has_value()) << "rho = " << point.density << ", u = " << u;
    EXPECT_NEAR(*sigma, point.specific_entropy,
                1e-12 * (std::fabs(point.specific_entropy) + eos.heat_capacity))
        << "rho = " << point.density;

    // The increment form agrees with the closed form for a heat input and a heat loss, and for a
    // tiny du it keeps full relative precision (log1p; ln(1 + x) would lose ~7 digits here).
    const ThermodynamicState state =
        revsph::entropic::state(eos, point.density, point.specific_entropy);
    for (const double fraction : {1e-9, 0.3, -0.5}) {
      const double du = fraction * eos.heat_capacity * state.temperature;
      const std::optional<double> change =
          revsph::entropic::specific_entropy_change(eos.heat_capacity, state.temperature, du);
      const std::optional<double> closed =
          revsph::entropic::specific_entropy_for_energy(eos, point.density, u + du);
      ASSERT_TRUE(change.has_value() && closed.has_value());
      if (fraction == 1e-9) {
        const double series = eos.heat_capacity * fraction * (1.0 - fraction / 2.0);
        EXPECT_NEAR(*change, series, 1e-14 * std::fabs(series));
      }
      EXPECT_NEAR(point.specific_entropy + *change, *closed,
                  1e-12 * (std::fabs(point.specific_entropy) + eos.heat_capacity));
    }
  }
}

TEST(EntropicEquationOfState, InverseRecoversSpecificEntropy) {
  expect_inverse_recovers_entropy(ideal_gas);
  expect_inverse_recovers_entropy(monatomic_gas);
  expect_inverse_recovers_entropy(hyperbolic_heat);
  expect_inverse_recovers_entropy(water);
}

TEST(EntropicEquationOfState, InverseRejectsUnreachableEnergies) {
  using revsph::entropic::specific_entropy_for_energy;
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  // Ideal gas: u = c_V T > 0.
  EXPECT_FALSE(specific_entropy_for_energy(ideal_gas, 1.0, 0.0));
  EXPECT_FALSE(specific_entropy_for_energy(ideal_gas, 1.0, -1.0));
  EXPECT_FALSE(specific_entropy_for_energy(ideal_gas, 1.0, inf));
  EXPECT_FALSE(specific_entropy_for_energy(ideal_gas, 1.0, nan));
  EXPECT_FALSE(specific_entropy_for_energy(ideal_gas, 0.0, 1.0));
  EXPECT_FALSE(specific_entropy_for_energy(ideal_gas, -1.0, 1.0));
  EXPECT_TRUE(specific_entropy_for_energy(ideal_gas, 1.0, 1e-300)); // very cold, still reachable
  // Stiffened gas: u > B / rho, the energy's T -> 0 limit at that density.
  const StiffenedGas& eos = water;
  const double rho = 1010.0;
  const double floor = revsph::entropic::stiffening_pressure(eos) / rho;
  EXPECT_FALSE(specific_entropy_for_energy(eos, rho, floor));
  EXPECT_FALSE(specific_entropy_for_energy(eos, rho, 0.5 * floor));
  EXPECT_FALSE(specific_entropy_for_energy(eos, rho, -floor));
  EXPECT_FALSE(specific_entropy_for_energy(eos, 0.0, 2.0 * floor));
  EXPECT_TRUE(specific_entropy_for_energy(eos, rho, 1.001 * floor));
  // The increment form: du <= -c_V T would take u to or below that floor.
  EXPECT_FALSE(revsph::entropic::specific_entropy_change(2.0, 3.0, -6.0));
  EXPECT_FALSE(revsph::entropic::specific_entropy_change(2.0, 3.0, -7.0));
  EXPECT_FALSE(revsph::entropic::specific_entropy_change(2.0, 3.0, nan));
  EXPECT_TRUE(revsph::entropic::specific_entropy_change(2.0, 3.0, -5.9));
  EXPECT_EQ(*revsph::entropic::specific_entropy_change(2.0, 3.0, 0.0), 0.0);
}

template <class Eos>
std::string error_of(const Eos& eos) {
  return revsph::entropic::constants_error(eos).value_or("(none)");
}

TEST(EntropicEquationOfState, ValidationNamesTheBadConstant) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(revsph::entropic::constants_error(ideal_gas));
  EXPECT_FALSE(revsph::entropic::constants_error(hyperbolic_heat));
  EXPECT_FALSE(revsph::entropic::constants_error(water));

  EXPECT_EQ(error_of(IdealGas{0.9, 1.0}), "gamma must be > 1 (got 0.9)");
  EXPECT_EQ(error_of(IdealGas{1.0, 1.0}), "gamma must be > 1 (got 1)");
  EXPECT_EQ(error_of(IdealGas{nan, 1.0}), "gamma must be finite (got nan)");
  EXPECT_EQ(error_of(IdealGas{1.4, 0.0}), "heat_capacity must be > 0 (got 0)");
  EXPECT_EQ(error_of(IdealGas{1.4, -2.5}), "heat_capacity must be > 0 (got -2.5)");
  EXPECT_EQ(error_of(IdealGas{1.4, inf}), "heat_capacity must be finite (got inf)");

  auto with = [](auto change) {
    StiffenedGas eos = hyperbolic_heat;
    change(eos);
    return error_of(eos);
  };
  EXPECT_EQ(with([](StiffenedGas& e) { e.gamma = 0.9; }), "gamma must be > 1 (got 0.9)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.gamma = -inf; }), "gamma must be finite (got -inf)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.heat_capacity = 0.0; }),
            "heat_capacity must be > 0 (got 0)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.rest_density = -10.0; }),
            "rest_density must be > 0 (got -10)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.rest_density = nan; }),
            "rest_density must be finite (got nan)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.sound_speed = 0.0; }), "sound_speed must be > 0 (got 0)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.reference_pressure = inf; }),
            "reference_pressure must be finite (got inf)");
  // Any finite p0 is allowed, including one that makes B negative.
  EXPECT_EQ(with([](StiffenedGas& e) { e.reference_pressure = -1e6; }), "(none)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.reference_pressure = 1e6; }), "(none)");
  // Finite constants whose derived ones overflow.
  EXPECT_EQ(with([](StiffenedGas& e) { e.sound_speed = 1e200; }),
            "rest_density * sound_speed^2 must be finite (got inf)");
  EXPECT_EQ(with([](StiffenedGas& e) { e.heat_capacity = 1e-310; }),
            "sound_speed^2 / (gamma (gamma-1) heat_capacity), the reference temperature, must be "
            "finite and > 0 (got inf)");
}

} // namespace
