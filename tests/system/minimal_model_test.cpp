// The worked example of docs/adding-a-model.md (tests/support/minimal_model.hpp): built from a
// state table, one pair term and a palindrome, it returns bit for bit, the same bits on one and
// two threads, and keeps its energy as a leapfrog does.

#include "minimal_model.hpp"

#include "core/threads.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace revsph {
namespace {

constexpr double dr = 0.01;
constexpr int side = 16; // particles per side of the square blob

// A square blob of gas at rest with rho about 1, centred in the trap: it expands under its own
// pressure and the trap brings it back.
std::unique_ptr<Simulation> minimal_blob() {
  minimal::State<2> state;
  resize_set(state.gas, side * side);
  minimal::Settings settings;
  settings.support_radius = 3.0 * dr;
  // One scale per quantity (core/particle_sets.hpp); the density constant is stored as a density
  // (it is added to the density sum as it is).
  set_scales(state, {{"position", fixedpoint::Scale(-50)},
                     {"velocity", fixedpoint::Scale(-50)},
                     {"mass", fixedpoint::Scale(-70)},
                     {"density", settings.density_scale}});
  for (int i = 0; i < side * side; ++i) {
    const auto a = static_cast<std::size_t>(i);
    EXPECT_TRUE(fixedpoint::try_to_fixed((i % side - side / 2 + 0.5) * dr,
                                         state.gas.position.info().scale,
                                         state.gas.position.at(0, a)));
    EXPECT_TRUE(fixedpoint::try_to_fixed((i / side - side / 2 + 0.5) * dr,
                                         state.gas.position.info().scale,
                                         state.gas.position.at(1, a)));
    EXPECT_TRUE(
        fixedpoint::try_to_fixed(dr * dr, state.gas.mass.info().scale, state.gas.mass.at(0, a)));
  }
  SimulationInfo info;
  info.case_name = "minimal-blob";
  info.model = "minimal";
  info.dt = 0.1 * settings.support_radius / std::sqrt(settings.gamma * settings.stiffness);
  const Box<2> domain{{-1.0, -1.0}, {1.0, 1.0}};
  return std::make_unique<ModelSimulation<minimal::Model<2>>>(
      minimal::Model<2>(domain, settings, info, std::move(state)));
}

TEST(MinimalModel, ReturnsBitwiseAfter2000StepsEachWayOnOneAndTwoThreads) {
  std::string turning_point;
  for (const int threads : {1, 2}) {
    set_thread_count(threads);
    auto simulation = minimal_blob();
    VerifyOptions options;
    options.steps = 2000;
    const VerifyReport report = verify_reversibility(*simulation, options);
    EXPECT_TRUE(report.identical()) << threads << " threads";
    if (threads == 1) {
      turning_point = report.turning_point_hash;
    } else {
      EXPECT_EQ(report.turning_point_hash, turning_point) << "the state after 2000 steps";
    }
  }
  set_thread_count(1);
}

// Leapfrog on a smooth flow: the total energy oscillates with an amplitude of order
// (c dt / h)^2 = 1e-2 of the energy that changes form; the blob turns internal energy into
// kinetic, so the error is measured against the largest kinetic energy it reaches.
TEST(MinimalModel, KeepsItsEnergyAsALeapfrogDoes) {
  auto simulation = minimal_blob();
  const auto total = [](const EnergyBudget& budget) { return budget.total(); };
  const double e0 = total(simulation->energy());
  double largest_error = 0.0;
  double kinetic = 0.0;
  for (int chunk = 0; chunk < 20; ++chunk) {
    simulation->advance(100);
    const EnergyBudget budget = simulation->energy();
    largest_error = std::max(largest_error, std::abs(total(budget) - e0));
    kinetic =
        std::max(kinetic, budget.terms.front().value.value()); // "kinetic" (minimal_model.hpp)
  }
  ASSERT_GT(kinetic, 0.0) << "the blob must expand";
  EXPECT_LT(largest_error, 1e-2 * kinetic);
}

} // namespace
} // namespace revsph
