// Entropic SPH's hyperbolic heat conduction (paper 4 §5.5) on a small resting body with a
// temperature gradient: the exchange of eq. (68) returns bit for bit and keeps the total entropy
// exactly; with the relaxation of eq. (69) the energy is kept, the entropy rises every step and
// ends where thermodynamics puts it once the body is at one temperature.

#include "fixedpoint/exact_sum.hpp"
#include "reversibility_expectations.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace {

using revsph::testing::make_simulation;
using revsph::testing::raw_total;

std::vector<double> gas_view(revsph::Simulation& simulation, const std::string& name) {
  auto views = revsph::testing::views_named(simulation, name);
  return views.count("gas") ? std::move(views.at("gas")) : std::vector<double>{};
}

// tau infinite: 2000 steps each way on 1 and 2 threads, and every sub-step alone.
TEST(EntropicHyperbolicHeat, ExchangeReturnsBitwiseOnOneAndTwoThreads) {
  revsph::testing::expect_returns_on_one_and_two_threads(
      "hyperbolic-small", 2000, {}, "", "heat did move", [](revsph::Simulation& simulation) {
        revsph::testing::expect_substeps_undo_themselves(simulation);
      });
}

// The S exchange is antisymmetric per pair in integers: the sum of the raw entropies does not
// change by one unit while the waves run.
TEST(EntropicHyperbolicHeat, ExchangeKeepsTheTotalEntropyExactly) {
  auto simulation = make_simulation("hyperbolic-small");
  const revsph::fixedpoint::int128 initial = raw_total(*simulation, "gas", "entropy");
  const std::vector<double> t0 = gas_view(*simulation, "temperature");
  simulation->advance(300);
  EXPECT_TRUE(raw_total(*simulation, "gas", "entropy") == initial);
  const std::vector<double> t1 = gas_view(*simulation, "temperature");
  double largest_change = 0.0;
  for (std::size_t i = 0; i < t0.size(); ++i) {
    largest_change = std::max(largest_change, std::abs(t1[i] - t0[i]));
  }
  EXPECT_GT(largest_change, 1.0) << "the temperatures did change (K)";
}

// With tau = 1e-5 (w relaxes at 2 c_w V / tau = 25 /s here) the waves die within the run. Every
// step the raw entropy sum rises or stays (increments rounded up), the total energy stays within
// 1e-6 of itself (the bound; measured 2.5e-8, the splitting error of the exchange), and
// at the end the body is at one temperature T_f, its mean (U = m c_V T + const at fixed density,
// equal masses), so the entropy has grown by sum_a m c_V ln(T_f / T_a(0)) (both gas laws,
// derivations.md §4.5). The residual wave energy, 1e-8 of the heat moved, bounds the mismatch;
// 1e-3 leaves room for the rounding of 2000 steps.
TEST(EntropicHyperbolicHeat, RelaxationRaisesEntropyToEquilibriumAndKeepsEnergy) {
  auto simulation =
      make_simulation("hyperbolic-small", {{"hyperbolic_heat.relaxation_time", "1e-5"}});
  const std::vector<double> t0 = gas_view(*simulation, "temperature");
  const std::vector<double> mass = [&] {
    const revsph::StateSnapshot state = simulation->capture_state();
    const revsph::FieldSnapshot& field = *state.find("gas", "mass");
    std::vector<double> values;
    for (std::size_t i = 0; i < field.count; ++i) {
      values.push_back(field.real(0, i));
    }
    return values;
  }();
  const double e0 = simulation->energy().total();
  const double s0 = revsph::testing::named_value(simulation->diagnostics(), "entropy");
  revsph::fixedpoint::int128 previous = raw_total(*simulation, "gas", "entropy");
  double largest_error = 0.0;
  for (int step = 0; step < 2000; ++step) {
    simulation->advance(1);
    const revsph::fixedpoint::int128 now = raw_total(*simulation, "gas", "entropy");
    ASSERT_TRUE(now >= previous) << "step " << step + 1;
    previous = now;
    if (step % 50 == 0) {
      largest_error = std::max(largest_error, std::abs(simulation->energy().total() - e0) / e0);
    }
  }
  EXPECT_LT(largest_error, 1e-6);
  const double t_final =
      std::accumulate(t0.begin(), t0.end(), 0.0) / static_cast<double>(t0.size());
  double predicted = 0.0;
  for (std::size_t i = 0; i < t0.size(); ++i) {
    predicted += mass[i] * 1.0 * std::log(t_final / t0[i]); // c_V = 1
  }
  const double gained = revsph::testing::named_value(simulation->diagnostics(), "entropy") - s0;
  EXPECT_GT(predicted, 0.0);
  EXPECT_NEAR(gained / predicted, 1.0, 1e-3);
  const std::vector<double> t_end = gas_view(*simulation, "temperature");
  for (const double t : t_end) {
    EXPECT_NEAR(t, t_final, 1e-3 * t_final);
  }
}

// Each sub-step alone (flux, entropy exchange and the rest), then the time reversal, the same
// sub-step and the reversal again returns every bit, on random states: w of either sign up to a
// quarter of the bound its scale covers (its energy up to a sixteenth of the heat), entropies
// jittered by up to m c_V / 16.
TEST(EntropicHyperbolicHeat, EverySubstepUndoesItselfOnRandomStates) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    auto simulation = make_simulation("hyperbolic-small");
    revsph::testing::expect_substeps_undo_themselves_on_random_state(
        *simulation, seed, {{"gas", "entropy_flux", 46, false}, {"gas", "entropy", 44}},
        "seed " + std::to_string(seed) + ", ");
  }
}

} // namespace
