// Superfluid helium (paper 3), the reversible part: the random droplet (2D and 3D) and the
// second-sound wave return bit for bit on 1 and 2 threads; every sub-step is undone by itself on
// random states whose two copies differ; the hash does not depend on the cell size; each copy's
// momentum and total entropy are kept in integers (its golden hashes: tests/golden_hashes.csv).

#include "case_text.hpp"
#include "reversibility_expectations.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace {

using revsph::testing::hash_of;
using revsph::testing::make_simulation;
using revsph::testing::named_value;
using revsph::testing::raw_total;

// The index of the sub-step called "dissipate" (the number of sub-steps if there is none).
std::size_t dissipate_index(revsph::Simulation& simulation) {
  const std::vector<std::string> names = simulation.substep_names();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), "dissipate") -
                                  names.begin());
}

// The states and energies around one dissipation sub-step of ten times the step (so that the heat
// is large against rounding).
struct Dissipation {
  revsph::StateSnapshot before;
  revsph::StateSnapshot after;
  double energy_before = 0.0;
  double energy_after = 0.0;
  double kinetic_before = 0.0;
  double kinetic_after = 0.0;

  double moved() const { return std::abs(kinetic_after - kinetic_before); }
  double energy_error() const { return std::abs(energy_after - energy_before); }
  // Rounding: each particle's entropy increment is rounded up by less than one unit of its scale,
  // worth m T < m * 2 K of energy each.
  double rounding() const {
    const revsph::FieldSnapshot& entropy = *after.find("fluid", "entropy");
    return static_cast<double>(entropy.count) * after.find("fluid", "mass")->real(0, 0) * 2.0 *
           entropy.info.scale.unit();
  }
};

Dissipation dissipate_once(revsph::Simulation& simulation, std::size_t dissipate) {
  Dissipation step;
  step.before = simulation.capture_state();
  step.energy_before = simulation.energy().total();
  step.kinetic_before = named_value(simulation.energy().terms, "kinetic");
  simulation.apply_substep(dissipate, 10.0 * simulation.info().dt);
  step.after = simulation.capture_state();
  step.energy_after = simulation.energy().total();
  step.kinetic_after = named_value(simulation.energy().terms, "kinetic");
  return step;
}

REVSPH_REVERSAL_TEST(Superfluid, RandomDropletReturnsBitwiseOnOneAndTwoThreads, "droplet-small",
                     2000);

REVSPH_REVERSAL_TEST(Superfluid, SecondSoundReturnsBitwiseOnOneAndTwoThreads, "second-sound-small",
                     2000);

REVSPH_REVERSAL_TEST(Superfluid, AbsorbingCoolerReturnsBitwiseOnOneAndTwoThreads, "cooler-small",
                     2000);

REVSPH_REVERSAL_TEST(Superfluid, ThreeDimensionalDropletReturnsBitwise, "droplet-3d-small", 500);

// The reversible core on the fountain's geometry (glass shells, cooler walls, gravity, a free
// surface) at dr = d / 2: about 1 900 fluid and 2 600 wall and dummy particles.
REVSPH_REVERSAL_TEST(Superfluid, FountainReversibleCoreReturnsBitwiseOnOneAndTwoThreads,
                     "fountain-small", 2000);

// Each sub-step (drift, copy_one, copy_two) alone, forward then with -dt, on random states: the
// droplet's random v, v_s, s with copy 2 jittered away from copy 1 (as the copies drift apart in
// a run) and positions jittered by about dr / 30.
TEST(Superfluid, EverySubstepIsUndoneByItselfOnRandomStates) {
  for (const char* name : {"droplet-small", "droplet-3d-small", "cooler-small"}) {
    for (const std::uint64_t seed : {1u, 2u}) {
      auto simulation = make_simulation(name);
      revsph::testing::expect_substeps_undo_themselves_on_random_state(
          *simulation, seed,
          {{"fluid", "velocity_copy", 40},
           {"fluid", "superflow_velocity_copy", 40},
           {"fluid", "entropy_copy", 40},
           // The absorbing walls' own superflow velocities, differing between the copies.
           {"wall", "superflow_velocity", 40, true, 1024},
           {"wall", "superflow_velocity_copy", 40, true, 1024},
           {"fluid", "position", 40, true, 16}},
          std::string(name) + ", seed " + std::to_string(seed) + ", ");
    }
  }
}

TEST(Superfluid, HashDoesNotDependOnTheCellSize) {
  for (const char* name : {"droplet-small", "cooler-small"}) {
    auto hash_with_cells = [name](const char* factor) {
      auto simulation = make_simulation(name, {{"discretisation.cell_size_factor", factor}});
      simulation->advance(200);
      return hash_of(*simulation);
    };
    EXPECT_EQ(hash_with_cells("1.0"), hash_with_cells("1.7")) << name;
  }
}

// The absorbing cooler's budget: the energy its pair terms give the fluid (wall_exchange,
// counted to first order per sub-step) closes the budget at the scheme's own second order:
// the largest |E(t) - E(0)| over 3 ms falls about 4 times when dt halves, while the walls move
// more energy than the whole droplet holds (measured with the cooler's v_s driven by the
// thermomechanical force: 4.9e-7 and 1.2e-7 J/m, ratio 4.0; the exchange 0.034 J/m against
// E = 0.0026 J/m).
TEST(Superfluid, AbsorbingCoolerBudgetClosesAtSecondOrder) {
  auto largest_error = [](const char* courant, double& exchanged) {
    auto simulation = make_simulation("cooler-small", {{"discretisation.courant_number", courant}});
    const double e0 = simulation->energy().total();
    const std::int64_t steps = static_cast<std::int64_t>(std::lround(3e-3 / simulation->info().dt));
    double largest = 0.0;
    for (std::int64_t done = 0; done < steps; done += 20) {
      simulation->advance(20);
      largest = std::max(largest, std::abs(simulation->energy().total() - e0));
    }
    exchanged = named_value(simulation->energy().terms, "wall_exchange");
    return largest;
  };
  double exchanged_coarse = 0.0;
  double exchanged_fine = 0.0;
  const double coarse = largest_error("0.05", exchanged_coarse);
  const double fine = largest_error("0.025", exchanged_fine);
  EXPECT_GT(std::abs(exchanged_fine), 1e-2) << "the walls absorbed";
  EXPECT_GT(coarse / fine, 3.0) << coarse << " -> " << fine;
  EXPECT_LT(fine, 1e-3 * std::abs(exchanged_fine));
}

// Equal masses: the pair increments of v and s that a and b receive are exact negatives, so the
// raw sums over the particles of each copy's v and s never change (eq. B9, B10 in integers).
TEST(Superfluid, EachCopyKeepsMomentumAndEntropyInIntegers) {
  auto simulation = make_simulation("droplet-small");
  auto totals = [&] {
    const revsph::StateSnapshot state = simulation->capture_state();
    std::vector<revsph::fixedpoint::int128> sums;
    for (const char* field : {"velocity", "velocity_copy", "entropy", "entropy_copy"}) {
      const revsph::FieldSnapshot& f = *state.find("fluid", field);
      const std::size_t components = f.bits.size() / f.count;
      for (std::size_t k = 0; k < components; ++k) {
        sums.push_back(raw_total(state, "fluid", field, k));
      }
    }
    return sums;
  };
  const auto before = totals();
  simulation->advance(500);
  const auto after = totals();
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t q = 0; q < before.size(); ++q) {
    EXPECT_TRUE(before[q] == after[q]) << "total " << q << " changed";
  }
  // The droplet does move: its velocities are not the initial ones.
  EXPECT_NE(hash_of(*simulation), hash_of(*make_simulation("droplet-small")));
}

// The dissipation sub-step alone (viscosity and heat conduction, from the mean of the copies) on
// the random droplet after 300 steps: it keeps the energy (15) to 1e-12 of the mechanical energy
// it moves plus the rounding of the entropies (the heat becomes entropy by Newton's method on the
// exact energy), the
// momentum of each copy in integers (equal and opposite pair increments), the copies'
// difference bit for bit (the same increments to both), and it raises the total entropy.
TEST(Superfluid, DissipationKeepsEnergyAndMomentumAndRaisesEntropy) {
  auto simulation = make_simulation(
      "droplet-small", {{"physics.viscosity", "1e-4"}, {"physics.heat_conductivity", "5"}});
  simulation->advance(300);
  const std::size_t dissipate = dissipate_index(*simulation);
  ASSERT_LT(dissipate, simulation->substep_names().size());
  auto sum_of = [](const revsph::StateSnapshot& state, const char* field, std::size_t component) {
    return raw_total(state, "fluid", field, component);
  };
  const Dissipation step = dissipate_once(*simulation, dissipate);
  const revsph::StateSnapshot& before = step.before;
  const revsph::StateSnapshot& after = step.after;
  EXPECT_NE(step.kinetic_before, step.kinetic_after) << "the viscosity acted";
  EXPECT_LT(step.energy_error(), 1e-9 * step.moved() + step.rounding())
      << "energy " << step.energy_before << " -> " << step.energy_after << ", kinetic energy moved "
      << step.moved() << ", rounding bound " << step.rounding();
  EXPECT_TRUE(sum_of(after, "entropy", 0) > sum_of(before, "entropy", 0));
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_TRUE(sum_of(after, "velocity", k) == sum_of(before, "velocity", k));
    EXPECT_TRUE(sum_of(after, "velocity_copy", k) == sum_of(before, "velocity_copy", k));
  }
  for (const auto& [one, two] : {std::pair{"velocity", "velocity_copy"},
                                 std::pair{"superflow_velocity", "superflow_velocity_copy"},
                                 std::pair{"entropy", "entropy_copy"}}) {
    const auto& a0 = before.find("fluid", one)->bits;
    const auto& b0 = before.find("fluid", two)->bits;
    const auto& a1 = after.find("fluid", one)->bits;
    const auto& b1 = after.find("fluid", two)->bits;
    for (std::size_t i = 0; i < a0.size(); ++i) {
      ASSERT_EQ(a0[i] - b0[i], a1[i] - b1[i]) << one << " value " << i;
    }
  }
}

// No-slip glass (physics.dummy_slip = "no_slip", the authors' fountain code): the random droplet
// in a box of dummies one spacing away, viscosity only. One dissipation sub-step takes momentum
// (the glass holds the normal fluid) but keeps the energy to the entropies' rounding (the
// dissipated power heats the fluid particle); with free slip the same sub-step keeps momentum.
TEST(Superfluid, NoSlipDummiesTakeMomentumAndKeepEnergy) {
  using revsph::testing::replaced_once;
  auto droplet_in_glass = [](const std::string& slip) {
    std::string text = revsph::testing::builtin_case_text("droplet-small");
    text = replaced_once(text, "heat_capacity = 3902.0",
                         "heat_capacity = 3902.0\nviscosity = 1e-3\ndummy_slip = \"" + slip + "\"");
    text += "\n[[particles]]\nkind = \"dummy\"\nshape = \"container\"\nlayers = 3\n"
            "min = [0.0, 0.0]\nmax = [0.016, 0.016]\n";
    return revsph::testing::make_simulation_from_text(text);
  };
  for (const std::string slip : {"free", "no_slip"}) {
    auto simulation = droplet_in_glass(slip);
    simulation->advance(20);
    const std::size_t dissipate = dissipate_index(*simulation);
    ASSERT_LT(dissipate, simulation->substep_names().size());
    auto momentum = [&](const revsph::StateSnapshot& state) {
      const revsph::FieldSnapshot& v = *state.find("fluid", "velocity");
      const double m = state.find("fluid", "mass")->real(0, 0);
      double total = 0.0;
      for (std::size_t i = 0; i < v.count; ++i) {
        total += m * std::abs(v.real(0, i)) + m * std::abs(v.real(1, i));
      }
      double net_x = 0.0;
      for (std::size_t i = 0; i < v.count; ++i) {
        net_x += m * v.real(0, i);
      }
      return std::pair{net_x, total};
    };
    const Dissipation step = dissipate_once(*simulation, dissipate);
    EXPECT_GT(step.moved(), 0.0) << slip;
    EXPECT_LT(step.energy_error(), 1e-9 * step.moved() + step.rounding()) << slip;
    const auto [net_before, scale] = momentum(step.before);
    const double net_after = momentum(step.after).first;
    if (slip == "free") {
      EXPECT_NEAR(net_after, net_before, 1e-12 * scale) << "free slip keeps momentum";
    } else {
      EXPECT_GT(std::abs(net_after - net_before), 1e-6 * scale) << "the glass holds the fluid";
    }
  }
}

// The fountain's sources on the random droplet with viscosity and conduction: a superleak slab
// across its middle, a heater above it ramped over 1 ms. The heater's input follows its power
// (the kernel's quadrature over the particles: within 3 %), and the budget, heater input
// counted, closes to the reversible part's own error (1e-3 of what the heater put in).
TEST(Superfluid, FountainSourcesKeepTheEnergyBudget) {
  auto simulation = make_simulation("droplet-small", {{"physics.viscosity", "1e-4"},
                                                      {"physics.heat_conductivity", "5"},
                                                      {"superleak.rate", "1e6"},
                                                      {"superleak.centre", "[0.008, 0.008]"},
                                                      {"superleak.half_width", "0.004"},
                                                      {"superleak.half_thickness", "0.002"},
                                                      {"heater.power", "10"},
                                                      {"heater.centre", "[0.008, 0.012]"},
                                                      {"heater.support", "0.004"},
                                                      {"heater.ramp_time", "1e-3"}});
  EXPECT_EQ(simulation->info().irreversible_terms.size(), 3u);
  const double e0 = simulation->energy().total();
  simulation->advance(800);
  const revsph::EnergyBudget budget = simulation->energy();
  const double heater = -named_value(budget.terms, "heater_input");
  const double t = simulation->time();
  const double expected = 10.0 * (t - 0.5e-3); // ramped over the first millisecond
  EXPECT_NEAR(heater, expected, 0.03 * expected);
  EXPECT_LT(std::abs(budget.total() - e0), 1e-3 * heater);
}

} // namespace
