// Paper 5's Rayleigh-Taylor set-up (sec. V.1, Fig. 5): the hydrostatic start
// (initial.hydrostatic) and the viscosity term's output view of Fig. 5(b).

#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace {

using revsph::testing::make_simulation;
using revsph::testing::Override;
using revsph::testing::views_named;

// The root mean square of the fluid's vertical velocity over the elapsed time: the mean
// acceleration of the first steps.
double rms_vertical_acceleration(revsph::Simulation& simulation) {
  const auto velocities = views_named(simulation, "velocity");
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& [set, v] : velocities) {
    const std::size_t n = v.size() / 2;
    for (std::size_t i = 0; i < n; ++i) {
      sum += v[n + i] * v[n + i]; // component-major: y after every x
      ++count;
    }
  }
  return std::sqrt(sum / static_cast<double>(count)) / simulation.time();
}

// A flat interface (amplitude 0) is in equilibrium. From the uniform start the fluid falls and
// the walls push until sound has crossed the column: the first four steps' mean vertical
// acceleration is 3.2 g (root mean square over the fluid). From the hydrostatic start (each mass
// compressed to its column's pressure over its own number density, the walls' pressure lowered
// where their kernel is cut) what is left is the lattice's: 0.072 g at this 24 x 48 (0.083 g at
// the linear case's 96 x 192, in one step).
TEST(TwoFluidRayleighTaylor, HydrostaticStartHoldsAFlatInterfaceAtRest) {
  const std::vector<Override> flat = {{"interface.amplitude", "0"}};
  std::vector<Override> hydrostatic = flat;
  hydrostatic.push_back({"initial.hydrostatic", "true"});
  const auto uniform = make_simulation("rayleigh-taylor-small", flat);
  const auto balanced = make_simulation("rayleigh-taylor-small", hydrostatic);
  uniform->advance(4);
  balanced->advance(4);
  const double g = 9.8;
  EXPECT_GT(rms_vertical_acceleration(*uniform), 1.6 * g);
  EXPECT_LT(rms_vertical_acceleration(*balanced), 0.15 * g);
}

// Fig. 5(b): eq. (34)'s viscosity term acts on the normal fluid only (the superfluid is
// inviscid; the paper's caption says the opposite, README "Paper against revsph"), and it is
// linear in eta: doubling eta_n doubles it.
TEST(TwoFluidRayleighTaylor, ViscosityViewIsZeroOnTheSuperfluidAndLinearInEta) {
  const std::vector<Override> moving = {{"physics.normal_viscosity", "1.306e-6"},
                                        {"initial.random_velocity", "0.001"}};
  std::vector<Override> doubled = {{"physics.normal_viscosity", "2.612e-6"},
                                   {"initial.random_velocity", "0.001"}};
  const auto once = make_simulation("rayleigh-taylor-small", moving);
  const auto twice = make_simulation("rayleigh-taylor-small", doubled);
  const auto views = views_named(*once, "viscous_acceleration");
  ASSERT_EQ(views.count("superfluid"), 1u);
  ASSERT_EQ(views.count("normal"), 1u);
  for (const double a : views.at("superfluid")) {
    EXPECT_EQ(a, 0.0);
  }
  const std::vector<double>& normal = views.at("normal");
  double largest = 0.0;
  for (const double a : normal) {
    largest = std::max(largest, std::abs(a));
  }
  ASSERT_GT(largest, 0.0);
  const std::vector<double> doubled_normal =
      views_named(*twice, "viscous_acceleration").at("normal");
  ASSERT_EQ(doubled_normal.size(), normal.size());
  for (std::size_t i = 0; i < normal.size(); ++i) {
    EXPECT_NEAR(doubled_normal[i], 2.0 * normal[i], 1e-9 * largest) << i;
  }
  const auto inviscid = make_simulation("rayleigh-taylor-small");
  EXPECT_TRUE(views_named(*inviscid, "viscous_acceleration").empty());
}

} // namespace
