// Entropic SPH's dissipation (paper 4 §5.1-5.2) on the expansion with the paper's non-adiabatic
// settings (mu = 0.001, lambda_F = 0.1, §5.3): one update keeps the total energy, the total
// entropy never decreases, viscosity keeps the momentum exactly, and the verifier is told.

#include "fixedpoint/exact_sum.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using revsph::testing::make_simulation;
using revsph::testing::named_value;
using revsph::testing::Override;
using revsph::testing::raw_total;

std::vector<Override> non_adiabatic(const char* splitting = "strang") {
  return {{"physics.viscosity", "0.001"},
          {"physics.heat_conductivity", "0.1"},
          {"step.splitting", splitting}};
}

// One dissipation update alone (sub-step 0, Strang) after 300 steps of flow: the kinetic energy
// it removes reappears as internal energy. What is left is rounding: of the pair impulses (one
// unit of the momentum scale per pair) and of the entropy (rounded up, one unit of its scale
// per particle), both below 1e-13 of the total here; 1e-11 leaves room.
TEST(EntropicDissipation, AnUpdateKeepsTheTotalEnergy) {
  auto simulation = make_simulation("expansion-small", non_adiabatic());
  simulation->advance(300);
  ASSERT_EQ(simulation->substep_names().front(), "dissipation");
  const revsph::EnergyBudget before = simulation->energy();
  const revsph::fixedpoint::int128 entropy_before = raw_total(*simulation, "gas", "entropy");
  simulation->apply_substep(0, 20 * simulation->info().dt); // a large update, to see it act
  const revsph::EnergyBudget after = simulation->energy();
  EXPECT_LT(named_value(after.terms, "kinetic"), named_value(before.terms, "kinetic"));
  EXPECT_GT(raw_total(*simulation, "gas", "entropy"), entropy_before);
  EXPECT_NEAR(after.total(), before.total(), 1e-11 * std::abs(before.total()));
}

// Conduction moves entropy from hot to cold particles and viscosity makes it; with the increments
// rounded up, the sum of the raw integers never goes down, in every splitting.
TEST(EntropicDissipation, TotalEntropyNeverDecreases) {
  for (const char* splitting : {"strang", "midpoint", "lie"}) {
    auto simulation = make_simulation("expansion-small", non_adiabatic(splitting));
    revsph::fixedpoint::int128 previous = raw_total(*simulation, "gas", "entropy");
    const revsph::fixedpoint::int128 initial = previous;
    for (int step = 0; step < 400; ++step) {
      simulation->advance(1);
      const revsph::fixedpoint::int128 now = raw_total(*simulation, "gas", "entropy");
      ASSERT_GE(now, previous) << splitting << ", step " << step + 1;
      previous = now;
    }
    EXPECT_GT(previous, initial) << splitting << ": the dissipation did act";
  }
}

// With the midpoint splitting the core places one update over the whole step between two half
// drifts (core/step_splitting.hpp). With the particles held in place (a temperature gradient to
// conduct) only the update acts: the energy stays to rounding, as in the previous test, and
// entropy is made.
TEST(EntropicDissipation, MidpointPlacesTheUpdateBetweenHalfDrifts) {
  std::vector<Override> overrides = non_adiabatic("midpoint");
  overrides.push_back({"physics.particles_move", "false"});
  overrides.push_back({"initial.temperature_gradient", "[1.0, 0.5]"});
  auto simulation = make_simulation("expansion-small", overrides);
  const std::vector<std::string> names = simulation->substep_names();
  const std::size_t middle = names.size() / 2;
  ASSERT_EQ(names[middle], "dissipation");
  ASSERT_EQ(names[middle - 1], "drift");
  ASSERT_EQ(names[middle + 1], "drift");
  const double total = simulation->energy().total();
  const revsph::fixedpoint::int128 entropy_before = raw_total(*simulation, "gas", "entropy");
  simulation->apply_substep(middle, 20 * simulation->info().dt);
  EXPECT_GT(raw_total(*simulation, "gas", "entropy"), entropy_before);
  EXPECT_NEAR(simulation->energy().total(), total, 1e-11 * std::abs(total));
}

// Viscous impulses are added to a and, negated, to b: without walls the total momentum stays
// exactly zero.
TEST(EntropicDissipation, ViscosityKeepsTheMomentumExactly) {
  std::vector<Override> overrides = non_adiabatic();
  overrides.push_back({"wall.energy_per_mass", "0"});
  auto simulation = make_simulation("expansion-small", overrides);
  simulation->advance(300);
  const auto diagnostics = simulation->diagnostics();
  EXPECT_EQ(named_value(diagnostics, "momentum_x"), 0.0);
  EXPECT_EQ(named_value(diagnostics, "momentum_y"), 0.0);
}

// The irreversible operator is declared once and placed by the core: the verifier and info()
// list it with its placement in every splitting, and nothing without dissipation.
TEST(EntropicDissipation, IrreversibleTermsAreDeclared) {
  for (const char* splitting : {"strang", "midpoint", "lie"}) {
    auto simulation = make_simulation("expansion-small", non_adiabatic(splitting));
    const auto& terms = simulation->info().irreversible_terms;
    ASSERT_EQ(terms.size(), 1u) << splitting;
    EXPECT_NE(terms[0].find("viscosity and heat conduction"), std::string::npos) << terms[0];
    EXPECT_EQ(terms[0].rfind("dissipation: ", 0), 0u) << terms[0];
  }
  EXPECT_TRUE(make_simulation("expansion-small")->info().irreversible_terms.empty());
}

} // namespace
