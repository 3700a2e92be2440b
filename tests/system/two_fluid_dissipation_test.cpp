// Tsuzuki's two-fluid helium (paper 5), the irreversible part: viscosity (34, 39) and mutual
// friction (29, 35) exchange momentum in pairs, so the total is exact in integers; the energy
// they take is counted, and with it the budget closes to the time integrator's error; the
// friction relaxes the counterflow at the rate eq. (29) gives; the conservative core of the
// rotating cylinder returns bit for bit; and a run continued from a snapshot takes the same
// L(t) and accounts as one never cut.

#include "core/threads.hpp"
#include "reversibility_expectations.hpp"
#include "simulation_fixture.hpp"

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using revsph::testing::make_simulation;
using revsph::testing::named_value;
using revsph::testing::Override;

// The mixture as a free block (walls moved out of reach) with the irreversible terms on and the
// non-antisymmetric thermomechanical force off.
std::vector<Override> free_block_with(std::vector<Override> more) {
  std::vector<Override> overrides{
      {"thermomechanical.entropy_scale", "0"},  {"physics.background_pressure", "0"},
      {"particles[1].min", "[3.0e-4, 3.0e-4]"}, {"particles[1].max", "[3.2e-4, 3.2e-4]"},
      {"domain.min", "[-1.0e-4, -1.0e-4]"},     {"domain.max", "[4.0e-4, 4.0e-4]"}};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return overrides;
}

const std::vector<Override> friction_on{{"mutual_friction.alpha", "0.0968"},
                                        {"mutual_friction.circulation_quantum", "9.9693e-8"},
                                        {"mutual_friction.initial_line_density", "1.0e10"},
                                        {"mutual_friction.vinen_beta", "4.76e-9"}};

std::vector<boost::multiprecision::int128_t> momentum_totals(revsph::Simulation& simulation) {
  const revsph::StateSnapshot state = simulation.capture_state();
  std::vector<boost::multiprecision::int128_t> sums(2, 0);
  for (int k = 0; k < 2; ++k) {
    for (const char* set : {"superfluid", "normal"}) {
      const revsph::FieldSnapshot& f = *state.find(set, "momentum");
      for (std::size_t i = 0; i < f.count; ++i) {
        sums[k] += f.at(k, i);
      }
    }
  }
  return sums;
}

TEST(TwoFluidDissipation, ViscosityFrictionAndContactsKeepMomentumInIntegers) {
  std::vector<Override> more = friction_on;
  more.push_back({"physics.normal_viscosity", "1.306e-6"});
  more.push_back({"collision.on", "true"});
  more.push_back({"riemann.on", "true"});
  more.push_back({"initial.random_velocity", "0.002"});
  auto simulation = make_simulation("two-fluid-mixture-small", free_block_with(more));
  ASSERT_EQ(simulation->info().irreversible_terms.size(), 1u);
  const auto before = momentum_totals(*simulation);
  const double kinetic_before = named_value(simulation->energy().terms, "kinetic");
  simulation->advance(300);
  const auto after = momentum_totals(*simulation);
  EXPECT_TRUE(before == after) << "total momentum changed";
  EXPECT_GT(named_value(simulation->energy().terms, "dissipated"), 0.01 * kinetic_before);
}

// The budget (kinetic + internal + dissipated - wall work - force work) against the work the
// turning walls put in: the rotating cylinder, spin term, viscosity and friction on. The
// dissipated account (what each dissipate sub-step took beyond the walls' work) only grows, and
// it is close to the exchanges' first-order rate sum K |v_a - v_b|^2: the budget then drifts
// only by the Verlet kick and drift's error, second order in dt (halving dt at a fixed end time
// divides it by about four).
TEST(TwoFluidDissipation, EnergyBudgetClosesInTheRotatingCylinder) {
  auto budget_error = [](const char* viscous_number, std::int64_t steps) {
    auto simulation = make_simulation("rotating-cylinder-small",
                                      {{"discretisation.viscous_number", viscous_number}});
    const double initial = simulation->energy().total();
    double worst = 0.0, dissipated = 0.0, wall_work = 0.0;
    for (std::int64_t s = 0; s < steps; s += steps / 10) {
      simulation->advance(steps / 10);
      const revsph::EnergyBudget budget = simulation->energy();
      const double now = named_value(budget.terms, "dissipated");
      EXPECT_GE(now, dissipated) << "the dissipated energy fell";
      dissipated = now;
      wall_work = -named_value(budget.terms, "wall_work");
      worst = std::max(worst, std::abs(budget.total() - initial));
    }
    std::printf("viscous number %s: %lld steps, dissipated %.4e, wall work %.4e, worst budget "
                "error %.4e\n",
                viscous_number, static_cast<long long>(steps), dissipated, wall_work, worst);
    EXPECT_GT(wall_work, 0.0) << "the turning wall drives the fluid";
    return std::pair{worst, wall_work};
  };
  const auto [coarse, work] = budget_error("0.125", 200);
  const auto [fine, fine_work] = budget_error("0.0625", 400);
  EXPECT_LT(coarse, 0.01 * work) << "the budget misses more than 1 % of the work put in";
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.5);
}

// Angular momentum about the origin, sum x p_y - y p_x over the moving particles.
double angular_momentum(revsph::Simulation& simulation) {
  const revsph::StateSnapshot state = simulation.capture_state();
  double total = 0.0;
  for (const char* set : {"superfluid", "normal"}) {
    const revsph::FieldSnapshot& x = *state.find(set, "position");
    const revsph::FieldSnapshot& p = *state.find(set, "momentum");
    for (std::size_t i = 0; i < x.count; ++i) {
      total += x.real(0, i) * p.real(1, i) - x.real(1, i) * p.real(0, i);
    }
  }
  return total;
}

// The viscous pair force of eq. (34) is parallel to v_a - v_b, not to x_ab: each pair feels a
// torque, and a free block (pressure and viscosity only, both forms) loses angular momentum;
// the central form keeps it to the rounding of its impulses.
TEST(TwoFluidDissipation, CentralViscosityKeepsAngularMomentum) {
  auto change_with = [](const char* form) {
    auto simulation = make_simulation("two-fluid-mixture-small",
                                      free_block_with({{"physics.normal_viscosity", "1e-4"},
                                                       {"physics.viscosity_form", form},
                                                       {"spin.coefficient", "0"},
                                                       {"initial.random_velocity", "0.01"}}));
    const double before = angular_momentum(*simulation);
    simulation->advance(200);
    const double change = std::abs(angular_momentum(*simulation) - before);
    std::printf("%s: angular momentum %.4e, its change in 200 steps %.4e\n", form, before, change);
    return change / std::abs(before);
  };
  const double laplacian = change_with("\"laplacian\"");
  const double central = change_with("\"central\"");
  EXPECT_LT(central, 1e-9);
  EXPECT_GT(laplacian, 1e3 * central);
}

// The contact terms alone (sec. IV.1, r < dr, approaching pairs): with random velocities some
// pairs come closer than dr; each term takes energy, and the budget's drift (the kick and
// drift's error: 3.5 % of the energy taken at courant_number 0.25, so dt is a fifth of that
// here) stays below 1 % of it.
TEST(TwoFluidDissipation, ContactTermsTakeEnergyThatTheBudgetCounts) {
  for (const char* term : {"collision.on", "riemann.on"}) {
    auto simulation = make_simulation("two-fluid-mixture-small",
                                      free_block_with({{term, "true"},
                                                       {"spin.coefficient", "0"},
                                                       {"initial.random_velocity", "0.05"},
                                                       {"discretisation.courant_number", "0.05"}}));
    const double initial = simulation->energy().total();
    simulation->advance(1000);
    const revsph::EnergyBudget budget = simulation->energy();
    const double dissipated = named_value(budget.terms, "dissipated");
    std::printf("%s: dissipated %.4e, budget drift %.4e\n", term, dissipated,
                budget.total() - initial);
    EXPECT_GT(dissipated, 0.0) << term;
    EXPECT_LT(std::abs(budget.total() - initial), 0.01 * dissipated) << term;
  }
}

// A free block whose superfluid moves at +u and normal fluid at -u m_s N_s / (m_n N_n) (zero
// total momentum): eq. (29) pulls each superfluid particle toward the average normal velocity
// at the rate C_L / rho_s (V rho_s / m = 1 on the lattice), and eq. (35) gives the normal fluid
// the reaction, so the counterflow w starts to decay at the rate
// gamma = (C_L / rho_s) (1 + N_s m_s / (N_n m_n)): checked over the first 20 steps (gamma t =
// 0.21) to 5 % (the block's rim, a sixth of its particles, has a smaller number density, larger
// volumes and a faster pull). Later the decay slows (1.2e3 1/s by gamma t = 2): a normal
// particle among many superfluid ones takes a larger share of their reactions than one among
// normal ones, so the velocities spread and the mean counterflow is a sum of modes.
TEST(TwoFluidDissipation, MutualFrictionRelaxesTheCounterflowAtItsRate) {
  std::vector<Override> more = friction_on;
  more.push_back({"mutual_friction.vinen_beta", "0"});
  more.push_back({"spin.coefficient", "0"});
  // The pressure off, nearly: c = 1e-4 m/s makes the block's own pressure waves (its rim is at
  // a lower number density) a thousand times slower than the counterflow; dt stays 6e-6 s.
  more.push_back({"physics.sound_speed", "1.0e-4"});
  more.push_back({"discretisation.courant_number", "5.0e-5"});
  auto simulation = make_simulation("two-fluid-mixture-small", free_block_with(more));
  revsph::StateSnapshot state = simulation->capture_state();
  const revsph::FieldSnapshot& superfluid_mass = *state.find("superfluid", "mass");
  const revsph::FieldSnapshot& normal_mass = *state.find("normal", "mass");
  const std::size_t n_s = superfluid_mass.count;
  const std::size_t n_n = normal_mass.count;
  const double m_s = superfluid_mass.real(0, 0);
  const double m_n = normal_mass.real(0, 0);
  const double u = 1.0e-4;
  const double u_normal = -u * m_s * static_cast<double>(n_s) / (m_n * static_cast<double>(n_n));
  auto set_velocity = [&](const char* set, double mass, double v) {
    revsph::FieldSnapshot& p = *state.find(set, "momentum");
    const double unit = std::ldexp(1.0, p.info.scale.exponent());
    for (std::size_t i = 0; i < p.count; ++i) {
      p.bits[i] = std::llround(mass * v / unit);
      p.bits[p.count + i] = 0;
    }
  };
  set_velocity("superfluid", m_s, u);
  set_velocity("normal", m_n, u_normal);
  simulation->restore_state(state);
  auto counterflow = [&] {
    const revsph::StateSnapshot now = simulation->capture_state();
    auto mean_velocity = [&](const char* set) {
      const revsph::FieldSnapshot& p = *now.find(set, "momentum");
      const revsph::FieldSnapshot& m = *now.find(set, "mass");
      double sum = 0.0;
      for (std::size_t i = 0; i < p.count; ++i) {
        sum += p.real(0, i) / m.real(0, i);
      }
      return sum / static_cast<double>(p.count);
    };
    return mean_velocity("superfluid") - mean_velocity("normal");
  };
  const double w0 = counterflow();
  const double c_l = 2.0 / 3.0 * 121.102 * 0.0968 * 9.9693e-8 * 1.0e10;
  const double gamma =
      c_l / 121.102 * (1.0 + m_s * static_cast<double>(n_s) / (m_n * static_cast<double>(n_n)));
  const std::int64_t steps = 20;
  simulation->advance(steps);
  const double t = static_cast<double>(steps) * simulation->info().dt;
  const double measured = -std::log(counterflow() / w0) / t;
  std::printf("counterflow decay rate %.4e 1/s, eq. (29) on the lattice %.4e 1/s (gamma t = "
              "%.2f)\n",
              measured, gamma, gamma * t);
  EXPECT_NEAR(measured / gamma, 1.0, 0.05);
}

// Without viscosity and friction, at the full case's dt (its viscous limit, 1e-4 s: without
// viscosity the CFL limit alone would allow 9e-4 s, where the undamped spin torque spins the
// vessel's rim beyond the sound speed within 1.4 s).
TEST(TwoFluidDissipation, RotatingCylinderCoreReturnsBitwiseOnOneAndTwoThreads) {
  revsph::testing::expect_returns_on_one_and_two_threads(
      "rotating-cylinder-small", 2000,
      {{"physics.normal_viscosity", "0"},
       {"mutual_friction.alpha", "0"},
       {"discretisation.courant_number", "0.0266"}});
}

// The irreversible part sums over pairs too, through the exact accumulators: the full cylinder's
// bits do not depend on the cell size; and they are kept as a golden hash.
TEST(TwoFluidDissipation, HashDoesNotDependOnTheCellSize) {
  auto hash_with_cells = [](const char* factor) {
    auto simulation =
        make_simulation("rotating-cylinder-small", {{"discretisation.cell_size_factor", factor}});
    simulation->advance(200);
    return revsph::testing::hash_of(*simulation);
  };
  EXPECT_EQ(hash_with_cells("1.0"), hash_with_cells("1.7"));
}

// On 1 and 2 threads.
TEST(GoldenHash, TwoFluidRotatingCylinderSmallAfter200Steps) {
  const int previous = revsph::thread_count();
  for (const int threads : {1, 2}) {
    revsph::set_thread_count(threads);
    auto simulation = make_simulation("rotating-cylinder-small");
    simulation->advance(200);
    EXPECT_EQ(revsph::testing::hash_of(*simulation),
              "76af32227f0930404b41ae8d7793e924d0f863a7ba27d4ab34ceb912a2c5db0e")
        << threads << " threads";
  }
  revsph::set_thread_count(previous);
}

} // namespace
