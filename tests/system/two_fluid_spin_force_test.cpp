// Eq. (40)'s spin force as an output view (paper 5, Fig. 10): present on the fluid kinds when the
// spin term is on, absent when it is off; it acts on normal particles only (the superfluid has
// no viscosity).

#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace {

std::map<std::string, std::vector<double>> spin_force_views(revsph::Simulation& simulation) {
  return revsph::testing::views_named(simulation, "spin_force");
}

// Eq. (40): F = 2 eta_r curl omega, so at the same positions the view doubles with eta_r and
// with the spin (C_omega): it is the spin term and nothing else.
TEST(TwoFluidSpinForce, AViewOnTheNormalFluidProportionalToEtaRAndTheSpin) {
  const auto base = revsph::testing::make_simulation("rotating-cylinder-small");
  const auto views = spin_force_views(*base);
  ASSERT_EQ(views.count("normal"), 1u);
  ASSERT_EQ(views.count("superfluid"), 1u);
  for (const double f : views.at("superfluid")) {
    EXPECT_EQ(f, 0.0); // no viscosity, no spin term
  }
  const std::vector<double>& normal = views.at("normal");
  double largest = 0.0;
  for (const double f : normal) {
    largest = std::max(largest, std::abs(f));
  }
  ASSERT_GT(largest, 0.0);
  const auto doubled_eta = revsph::testing::make_simulation(
      "rotating-cylinder-small", {{"physics.rotational_viscosity", "2.612e-6"}});
  const auto doubled_spin =
      revsph::testing::make_simulation("rotating-cylinder-small", {{"spin.coefficient", "0.02"}});
  for (const auto* doubled : {&doubled_eta, &doubled_spin}) {
    const std::vector<double> twice = spin_force_views(**doubled).at("normal");
    ASSERT_EQ(twice.size(), normal.size());
    for (std::size_t i = 0; i < normal.size(); ++i) {
      EXPECT_NEAR(twice[i], 2.0 * normal[i], 1e-9 * largest) << i;
    }
  }
}

TEST(TwoFluidSpinForce, NoViewWithoutTheSpinTerm) {
  const auto simulation =
      revsph::testing::make_simulation("rotating-cylinder-small", {{"spin.coefficient", "0.0"}});
  EXPECT_TRUE(spin_force_views(*simulation).empty());
}

} // namespace
