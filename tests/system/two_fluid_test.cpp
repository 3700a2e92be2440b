// Tsuzuki's two-fluid helium (paper 5), the conservative core: the Rayleigh-Taylor box and the
// random mixture return bit for bit on 1 and 2 threads; kick and drift are each undone by
// themselves on random states; the hash does not depend on the cell size; the antisymmetric pair
// forces keep the total momentum exactly in integers; the variational pressure keeps the energy
// to second order in dt (its golden hashes: tests/golden_hashes.csv).

#include "reversibility_expectations.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using revsph::testing::hash_of;
using revsph::testing::make_simulation;

REVSPH_REVERSAL_TEST(TwoFluid, RayleighTaylorReturnsBitwiseOnOneAndTwoThreads,
                     "rayleigh-taylor-small", 2000);

REVSPH_REVERSAL_TEST(TwoFluid, RandomMixtureReturnsBitwiseOnOneAndTwoThreads,
                     "two-fluid-mixture-small", 2000);

// Each sub-step alone, forward then with -dt, on the mixture's random momenta with positions
// jittered by about dr / 30, for each pressure form.
TEST(TwoFluid, EverySubstepIsUndoneByItselfOnRandomStates) {
  for (const char* form : {"\"hu_adams\"", "\"standard\"", "\"variational\""}) {
    for (const std::uint64_t seed : {1u, 2u}) {
      auto simulation = make_simulation("two-fluid-mixture-small", {{"pressure.form", form}});
      const std::size_t checked = revsph::testing::expect_substeps_undo_themselves_on_random_state(
          *simulation, seed,
          {{"superfluid", "position", 40, true, 16}, {"normal", "position", 40, true, 16}},
          std::string(form) + ", seed " + std::to_string(seed) + ", ");
      // kick, drift (without viscosity and friction no dissipation is placed in the step)
      EXPECT_EQ(checked, 2u);
    }
  }
}

TEST(TwoFluid, HashDoesNotDependOnTheCellSize) {
  auto hash_with_cells = [](const char* factor) {
    auto simulation =
        make_simulation("two-fluid-mixture-small", {{"discretisation.cell_size_factor", factor}});
    simulation->advance(200);
    return hash_of(*simulation);
  };
  EXPECT_EQ(hash_with_cells("1.0"), hash_with_cells("1.7"));
}

// The pressure and spin impulses of a pair are exact negatives and gravity is off, so the sum
// of every moving particle's raw momentum changes only by what the walls give: with the walls
// moved out of reach (a free block) it never changes. The thermomechanical force
// is not antisymmetric (README) and is off here.
TEST(TwoFluid, PairForcesKeepMomentumInIntegers) {
  auto simulation =
      make_simulation("two-fluid-mixture-small", {{"thermomechanical.entropy_scale", "0"},
                                                  {"physics.background_pressure", "0"},
                                                  {"initial.random_velocity", "0.002"},
                                                  {"particles[1].min", "[3.0e-4, 3.0e-4]"},
                                                  {"particles[1].max", "[3.2e-4, 3.2e-4]"},
                                                  {"domain.min", "[-1.0e-4, -1.0e-4]"},
                                                  {"domain.max", "[4.0e-4, 4.0e-4]"}});
  auto totals = [&] {
    const revsph::StateSnapshot state = simulation->capture_state();
    std::vector<revsph::fixedpoint::int128> sums;
    for (std::size_t k = 0; k < 2; ++k) {
      sums.push_back(revsph::testing::raw_total(state, "superfluid", "momentum", k) +
                     revsph::testing::raw_total(state, "normal", "momentum", k));
    }
    return sums;
  };
  const auto before = totals();
  simulation->advance(300);
  const auto after = totals();
  EXPECT_TRUE(before[0] == after[0] && before[1] == after[1]) << "total momentum changed";
}

// Velocity Verlet on the gradient of the energy: the energy error over a fixed time falls
// fourfold when dt is halved (measured: see the test's output).
TEST(TwoFluid, VariationalPressureKeepsEnergyToSecondOrder) {
  auto error_with = [](const char* courant, std::int64_t steps) {
    auto simulation =
        make_simulation("rayleigh-taylor-small", {{"discretisation.courant_number", courant}});
    const double initial = simulation->energy().total();
    double worst = 0.0;
    for (std::int64_t s = 0; s < steps; s += steps / 20) {
      simulation->advance(steps / 20);
      worst = std::max(worst, std::abs(simulation->energy().total() - initial));
    }
    return worst;
  };
  const double coarse = error_with("0.2", 400);
  const double fine = error_with("0.1", 800);
  std::printf("energy error over 400 coarse steps: %.3e, with dt / 2: %.3e, ratio %.2f\n", coarse,
              fine, coarse / fine);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.5);
}

// The difference form of the thermomechanical force, sigma_a sum_b V_b (T_b - T_a) grad W,
// vanishes for a uniform T: the mixture with the paper's C_e takes the same bits as without the
// force (eq. 27 as printed throws a particle out of the Rayleigh-Taylor box within 3 steps at
// this C_e: README).
TEST(TwoFluid, DifferenceFormOfTheThermomechanicalForceVanishesForAUniformTemperature) {
  auto hash_with = [](const char* entropy_scale) {
    auto simulation = make_simulation("two-fluid-mixture-small",
                                      {{"thermomechanical.entropy_scale", entropy_scale},
                                       {"thermomechanical.form", "\"difference\""}});
    simulation->advance(100);
    return hash_of(*simulation);
  };
  EXPECT_EQ(hash_with("1.428e-3"), hash_with("0"));
}

} // namespace
