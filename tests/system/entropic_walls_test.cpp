// Entropic SPH's walls in the side-heated cavity (cavity-small: a heater and a cooler held at
// their temperatures, adiabatic dummy walls, no-slip, gravity, conduction and viscosity): the
// energy budget closes once the heat the walls took is counted, and the entropy of the gas and
// the walls together never decreases.

#include "simulation_fixture.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using revsph::testing::make_simulation;
using revsph::testing::named_value;
using revsph::testing::Override;

// In 1000 steps (0.94 s) the heater gives and the cooler takes about 15 J/m each (Nu ~ 3 early
// on), 1.3 J/m more into the cooler: without the walls' term the budget would miss 3e-4 of the
// total. With it the error is 3.4e-7 of the total (the Verlet error of the sound waves the
// start sets off, O(dt^2)); 2e-6 leaves room.
TEST(EntropicWalls, EnergyBudgetClosesWithTheHeatOfTheThermalWalls) {
  auto simulation = make_simulation("cavity-small");
  const double e0 = simulation->energy().total();
  double largest = 0.0;
  for (int chunk = 0; chunk < 20; ++chunk) {
    simulation->advance(50);
    largest = std::max(largest, std::abs(simulation->energy().total() - e0) / std::abs(e0));
  }
  const double wall_heat = named_value(simulation->energy().terms, "thermal_walls");
  EXPECT_GT(std::abs(wall_heat), 1e-4 * std::abs(e0)) << "the walls did pass heat";
  EXPECT_LT(largest, 2e-6);
  EXPECT_GT(named_value(simulation->diagnostics(), "heat_out_of_hot_walls"), 0.0);
  EXPECT_GT(named_value(simulation->diagnostics(), "heat_into_cold_walls"), 0.0);
}

// The gas's entropy may fall (heat leaves it into the cooler) but the walls' sum Q / T_w then
// rises by more, for both conduction schemes: the entropy produced per step, about
// lambda dT^2 / T^2 dt ~ 5e-4 J/(K m), stands far above the rounding of the sums (1e-8).
void expect_entropy_never_decreases(const char* conduction) {
  auto simulation = make_simulation("cavity-small", {{"physics.heat_conduction", conduction}});
  const auto total = [&] {
    const auto terms = simulation->diagnostics();
    return named_value(terms, "entropy") + named_value(terms, "thermal_wall_entropy");
  };
  double previous = total();
  for (int step = 0; step < 1000; ++step) {
    simulation->advance(1);
    const double now = total();
    ASSERT_GE(now, previous) << "step " << step + 1;
    previous = now;
  }
}

TEST(EntropicWalls, EntropyOfGasAndWallsNeverDecreases) {
  for (const char* conduction : {"pairwise", "two_pass"}) {
    SCOPED_TRACE(conduction);
    expect_entropy_never_decreases(conduction);
  }
}

// physics.buoyancy = "boussinesq" (the cavity diagnostic): the body force m g (T - T0) / T0
// depends on positions and entropies only, so without dissipation the step still returns bit
// for bit; and it lifts the warm side of a seeded roll (T0 + A cos(pi x) sin(pi y): warm on the
// left) and sinks the cool one, which a sign slip would reverse.
std::vector<Override> boussinesq_roll() {
  return {{"physics.buoyancy", "boussinesq"},
          {"physics.viscosity", "0"},
          {"physics.heat_conductivity", "0"},
          {"initial.temperature_perturbation", "0.05"}};
}

TEST(EntropicWalls, BoussinesqBuoyancyReturnsBitwise) {
  auto simulation = make_simulation("cavity-small", boussinesq_roll());
  revsph::VerifyOptions options;
  options.steps = 2000;
  const auto report = revsph::verify_reversibility(*simulation, options);
  EXPECT_TRUE(report.identical()) << report.comparison.verdict();
  EXPECT_NE(report.initial_hash, report.turning_point_hash);
}

TEST(EntropicWalls, BoussinesqBuoyancyLiftsTheWarmSide) {
  auto simulation = make_simulation("cavity-small", boussinesq_roll());
  simulation->advance(200);
  const revsph::StateSnapshot state = simulation->capture_state();
  const revsph::FieldSnapshot& position = *state.find("gas", "position");
  const revsph::FieldSnapshot& momentum = *state.find("gas", "momentum");
  double left = 0.0;
  double right = 0.0;
  for (std::size_t i = 0; i < position.count; ++i) {
    (position.real(0, i) < 0.5 ? left : right) += momentum.real(1, i);
  }
  EXPECT_GT(left, 0.0);
  EXPECT_LT(right, 0.0);
}

// initial.hydrostatic (the authors' RaBe.jl start): the cavity's gas begins with the weight of
// the gas above it in its pressure, so under gravity it stays nearly at rest, where the uniform
// start falls by rho g L / (rho c0^2) = 0.6 % and rings. What remains is the kernel sums' own
// error at the walls of this coarse lattice (20 x 20); in 200 steps it moves the gas with 2 %
// of the kinetic energy the uniform start's fall gives it (measured; a profile of the wrong sign
// would fall twice as far, with four times the energy). At 105 x 105 (rayleigh-benard) the
// largest speed after 400 steps is a tenth of the uniform start's.
double kinetic_energy_after(int steps, bool hydrostatic) {
  std::vector<Override> settings{{"physics.viscosity", "0"},
                                 {"physics.heat_conductivity", "0"},
                                 {"initial.temperature_gradient", "[0.0, -0.1]"}};
  if (hydrostatic) {
    settings.push_back({"initial.hydrostatic", "true"});
  }
  auto simulation = make_simulation("cavity-small", settings);
  simulation->advance(steps);
  return named_value(simulation->energy().terms, "kinetic");
}

TEST(EntropicWalls, HydrostaticStartStaysNearlyAtRest) {
  const double uniform = kinetic_energy_after(200, false);
  const double hydrostatic = kinetic_energy_after(200, true);
  EXPECT_GT(uniform, 0.0);
  EXPECT_LT(hydrostatic, 0.05 * uniform) << "uniform " << uniform;
}

} // namespace
