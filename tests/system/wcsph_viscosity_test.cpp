// The WCSPH model's optional artificial viscosity (models/wcsph/viscosity_term.hpp): off, the step
// is the reversible palindrome; on, an irreversible operator that takes kinetic energy and never
// gives it, keeps the fluid's momentum exact in integers, and whose energy, counted as
// dissipated, closes the budget to the Verlet step's second-order error; and a dam break with it
// comes to rest in a hydrostatic pressure field.

#include "core/threads.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {

using revsph::testing::make_simulation;
using revsph::testing::named_value;
using revsph::testing::Override;

// One thread while it lives: the long runs of 300 particles are barrier-bound, and ctest -j2 runs
// them beside other tests on two cores.
class OneThread {
public:
  OneThread() : previous_(revsph::thread_count()) { revsph::set_thread_count(1); }
  ~OneThread() { revsph::set_thread_count(previous_); }
  OneThread(const OneThread&) = delete;
  OneThread& operator=(const OneThread&) = delete;

private:
  int previous_;
};

double kinetic(revsph::Simulation& simulation) {
  return named_value(simulation.energy().terms, "kinetic");
}
double dissipated(revsph::Simulation& simulation) {
  return named_value(simulation.energy().terms, "dissipated");
}

std::size_t substep_index(const revsph::Simulation& simulation, const std::string& name) {
  const std::vector<std::string> names = simulation.substep_names();
  const auto found = std::find(names.begin(), names.end(), name);
  EXPECT_NE(found, names.end()) << name;
  return static_cast<std::size_t>(found - names.begin());
}

// Every fluid velocity moved by a uniform draw from [-u, u] m/s per component: many approaching
// pairs, at every distance.
void stir(revsph::Simulation& simulation, double u, std::uint64_t seed) {
  revsph::StateSnapshot state = simulation.capture_state();
  revsph::FieldSnapshot& v = *state.find("fluid", "velocity");
  const double unit = std::ldexp(1.0, v.info.scale.exponent());
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> draw(-u, u);
  for (std::int64_t& bits : v.bits) {
    bits += std::llround(draw(engine) / unit);
  }
  simulation.restore_state(state);
}

TEST(WcsphViscosity, OffTheStepIsThePalindrome) {
  auto off = make_simulation("dambreak-small");
  EXPECT_TRUE(off->info().irreversible_terms.empty());
  EXPECT_EQ(off->substep_names(), (std::vector<std::string>{"kick", "drift", "kick"}));
  EXPECT_TRUE(std::isnan(dissipated(*off))) << "no dissipated column in a reversible case";

  auto on = make_simulation("dambreak-small", {{"physics.artificial_viscosity", "0.1"}});
  ASSERT_EQ(on->info().irreversible_terms.size(), 1u);
  EXPECT_EQ(on->info().irreversible_terms[0].rfind("artificial_viscosity: Monaghan's", 0), 0u)
      << on->info().irreversible_terms[0];
  EXPECT_EQ(on->substep_names(), (std::vector<std::string>{"artificial_viscosity", "kick", "drift",
                                                           "kick", "artificial_viscosity"}));
  EXPECT_EQ(dissipated(*on), 0.0);
}

// The operator alone, over tau = dt, on a dam break in motion with stirred velocities: each
// application lowers the kinetic energy, by what the dissipated account gains (both sum the same
// products exactly, up to their last-place roundings), and leaves the sum of the raw velocities
// (the momentum over the equal mass) unchanged bit for bit: there are no dummy particles.
TEST(WcsphViscosity, OperatorTakesKineticEnergyAndKeepsMomentumExact) {
  auto simulation = make_simulation("dambreak-small", {{"physics.artificial_viscosity", "0.1"}});
  simulation->advance(300);
  stir(*simulation, 0.5, 1);
  const std::size_t viscosity = substep_index(*simulation, "artificial_viscosity");
  const double dt = simulation->info().dt;
  const auto momentum = [&](std::size_t k) {
    return revsph::testing::raw_total(simulation->capture_state(), "fluid", "velocity", k);
  };
  const revsph::fixedpoint::int128 px = momentum(0), py = momentum(1);
  double before = kinetic(*simulation);
  const double first = before;
  double account = dissipated(*simulation);
  for (int i = 0; i < 20; ++i) {
    simulation->apply_substep(viscosity, dt);
    const double after = kinetic(*simulation);
    const double gained = dissipated(*simulation) - account;
    EXPECT_LT(after, before) << "application " << i;
    EXPECT_NEAR(gained, before - after, 1e-12 * first) << "application " << i;
    before = after;
    account += gained;
  }
  std::printf("kinetic energy %.6e -> %.6e J/m in 20 applications\n", first, before);
  EXPECT_LT(before, 0.9 * first);
  EXPECT_TRUE(momentum(0) == px && momentum(1) == py) << "the fluid's momentum changed";
}

// With dummy particles (the Gresho vortex's walls, App. A) the fluid gives momentum to the walls,
// but the kinetic energy still only falls.
TEST(WcsphViscosity, DummyWallsTakeEnergyToo) {
  auto simulation = make_simulation("gresho", {{"physics.artificial_viscosity", "0.1"}});
  stir(*simulation, 0.05, 2);
  const std::size_t viscosity = substep_index(*simulation, "artificial_viscosity");
  double before = kinetic(*simulation);
  for (int i = 0; i < 5; ++i) {
    simulation->apply_substep(viscosity, simulation->info().dt);
    const double after = kinetic(*simulation);
    EXPECT_LT(after, before) << "application " << i;
    before = after;
  }
}

// The limit parameters.cpp refuses beyond: at alpha c tau / h = 1 (h = support / 2) each
// application still lowers the kinetic energy of a stirred state in 1D, 2D and 3D. Kinetic energy
// first grows at 1.5 in 1D, 2 in 2D, 3 in 3D (measured with these states, which still lose it at
// 1.25, 1.75 and 2.5).
TEST(WcsphViscosity, ExplicitUpdateTakesEnergyUpToTheRefusedLimit) {
  struct Probe {
    const char* name;
    std::int64_t steps;
  };
  for (const Probe& probe : {Probe{"column-1d", 200}, Probe{"dambreak-settling", 1500},
                             Probe{"dambreak-3d-small", 300}}) {
    auto simulation = make_simulation(probe.name, {{"physics.artificial_viscosity", "0.1"}});
    simulation->advance(probe.steps);
    stir(*simulation, 0.5, 3);
    const std::size_t viscosity = substep_index(*simulation, "artificial_viscosity");
    const double c = simulation->info().sound_speed;
    const double h = 0.5 * simulation->info().dt * c / 0.2; // dt = 0.2 (support) / c
    double before = kinetic(*simulation);
    for (int i = 0; i < 20; ++i) {
      simulation->apply_substep(viscosity, h / (0.1 * c)); // alpha c tau / h = 1
      const double after = kinetic(*simulation);
      EXPECT_LT(after, before) << probe.name << ", application " << i;
      before = after;
    }
  }
}

// The budget kinetic + gravitational + compressional + wall + dissipated over the first second
// of the settling dam break at dr = 0.04 m (the collapse, the run-up and the first breaking wave:
// most of the potential energy released is dissipated by then) is constant to the Verlet step's
// error: below 1 % of the energy dissipated, and second order (halving dt divides it by about
// four). `revsph run` at courant numbers 0.2, 0.1, 0.05: 1.0e-3, 2.0e-4, 6.4e-5 of the energy
// moved; without the viscosity 2.8e-3, 7.7e-4, 1.9e-4.
TEST(WcsphViscosity, EnergyBudgetClosesToTheVerletError) {
  const OneThread one_thread;
  struct Budget {
    double drift = 0.0;
    double dissipated = 0.0;
  };
  const auto budget_with = [](const char* courant) {
    auto simulation =
        make_simulation("dambreak-settling", {{"discretisation.dr", "0.04"},
                                              {"discretisation.courant_number", courant}});
    const std::int64_t steps = std::llround(1.0 / simulation->info().dt);
    const double initial = simulation->energy().total();
    Budget budget;
    for (std::int64_t done = 0; done < steps; done += 25) {
      simulation->advance(std::min<std::int64_t>(25, steps - done));
      budget.drift = std::max(budget.drift, std::abs(simulation->energy().total() - initial));
    }
    budget.dissipated = dissipated(*simulation);
    std::printf("courant number %s: dissipated %.4e J/m, max |E(t) - E(0)| %.4e J/m\n", courant,
                budget.dissipated, budget.drift);
    return budget;
  };
  const Budget coarse = budget_with("0.2");
  const Budget fine = budget_with("0.1");
  EXPECT_GT(coarse.dissipated, 500.0) << "J/m, by t = 1 s";
  EXPECT_LT(coarse.drift, 0.01 * coarse.dissipated);
  EXPECT_GT(coarse.drift / fine.drift, 3.0) << "second order";
}

// The least-squares line p = at_zero + slope y through the pressures of the particles with
// low <= y < high.
struct Line {
  double at_zero = 0.0;
  double slope = 0.0;
};
Line least_squares(const revsph::FieldSnapshot& x, const std::vector<double>& pressure, double low,
                   double high) {
  double n = 0.0, sy = 0.0, sp = 0.0, syy = 0.0, syp = 0.0;
  for (std::size_t i = 0; i < x.count; ++i) {
    const double y = x.real(1, i);
    if (y >= low && y < high) {
      n += 1.0;
      sy += y;
      sp += pressure[i];
      syy += y * y;
      syp += y * pressure[i];
    }
  }
  const double slope = (n * syp - sy * sp) / (n * syy - sy * sy);
  return {(sp - slope * sy) / n, slope};
}

// The settling dam break at dr = 0.04 m (300 particles, 6 s in ~3 s): the flow comes to rest
// (the kinetic energy over the last second below 1e-4 of its peak), the energy released has gone
// to the dissipated account, and the pressure is hydrostatic, H = N dr^2 / width being the depth
// of the fluid's volume: the least-squares line p = p(0) + b y through the pressures of the
// particles between 0.2 H and 0.8 H has p(0) within 10 % of rho0 g H and b within 10 % of
// -rho0 g (measured -2.0 % and +3.5 %); through every particle's, p(0) within 10 % (+7.9 %: the
// row on the floor, pressed into the wall of eq. 7, lies above the line of the rest). Single
// particles' pressures scatter about it (at dr = 0.02 m, RMS 1.8 kPa against rho0 g H = 4.9 kPa):
// the density constants of eq. (5) keep marking the particles that started at the free surface or
// a wall (README).
TEST(WcsphViscosity, DambreakSettlesToHydrostaticPressure) {
  const OneThread one_thread;
  const double dr = 0.04, width = 1.0, rho0 = 1000.0, g = 9.8;
  auto simulation = make_simulation("dambreak-settling", {{"discretisation.dr", "0.04"}});
  const double released_before = named_value(simulation->energy().terms, "gravitational");
  const std::int64_t per_tenth = std::llround(0.1 / simulation->info().dt);
  double peak = 0.0, late = 0.0;
  for (int tenth = 1; tenth <= 60; ++tenth) {
    simulation->advance(per_tenth);
    const double k = kinetic(*simulation);
    peak = std::max(peak, k);
    if (tenth > 50) {
      late = std::max(late, k);
    }
  }
  const revsph::EnergyBudget budget = simulation->energy();
  const double released = released_before - named_value(budget.terms, "gravitational");
  const double taken = named_value(budget.terms, "dissipated");

  const revsph::StateSnapshot state = simulation->capture_state();
  const revsph::FieldSnapshot& x = *state.find("fluid", "position");
  const std::vector<double> pressure =
      revsph::testing::views_named(*simulation, "pressure")["fluid"];
  ASSERT_EQ(pressure.size(), x.count);
  const double depth = static_cast<double>(x.count) * dr * dr / width;
  const Line all = least_squares(x, pressure, 0.0, 1.0);
  const Line middle = least_squares(x, pressure, 0.2 * depth, 0.8 * depth);
  std::printf("kinetic energy: peak %.4e J/m, largest over the last second %.4e J/m; released "
              "%.4e J/m, dissipated %.4e J/m; rho0 g H = %.1f Pa; every particle's line: p(0) = "
              "%.1f Pa, slope %.1f Pa/m; between 0.2 H and 0.8 H: p(0) = %.1f Pa, slope %.1f "
              "Pa/m\n",
              peak, late, released, taken, rho0 * g * depth, all.at_zero, all.slope, middle.at_zero,
              middle.slope);
  EXPECT_LT(late, 1e-4 * peak);
  EXPECT_NEAR(taken / released, 1.0, 0.02);
  EXPECT_NEAR(all.at_zero / (rho0 * g * depth), 1.0, 0.10);
  EXPECT_NEAR(middle.at_zero / (rho0 * g * depth), 1.0, 0.10);
  EXPECT_NEAR(middle.slope / (-rho0 * g), 1.0, 0.10);
}

} // namespace
