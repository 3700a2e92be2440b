// Tsuzuki's two-fluid helium (paper 5), the wall-grip options of the rotating cylinder (README,
// "Wall grip"): the mutual friction against wall particles held at C_L(0) while the fluid's
// follows Vinen's L(t); wall blocks that turn rigidly, exactly reversible, their particles on the
// rotated initial positions to rounding, the energy budget closed with the work they do. (The undiluted viscosity's shear-wave test is beside the
// interpenetrating one in two_fluid_dissipation_test.cpp.)

#include "cylinder_budget.hpp"
#include "reversibility_expectations.hpp"
#include "simulation_fixture.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace {

using revsph::testing::hash_of;
using revsph::testing::make_simulation;
using revsph::testing::Override;

// The z angular momentum of a set about the origin (the vessel's centre), sum x p_y - y p_x.
double angular_momentum(revsph::Simulation& simulation, const char* set) {
  const revsph::StateSnapshot state = simulation.capture_state();
  const revsph::FieldSnapshot& x = *state.find(set, "position");
  const revsph::FieldSnapshot& p = *state.find(set, "momentum");
  double total = 0.0;
  for (std::size_t i = 0; i < x.count; ++i) {
    total += x.real(0, i) * p.real(1, i) - x.real(1, i) * p.real(0, i);
  }
  return total;
}

// The small cylinder from rest, viscosity and spin off and the pressure nearly so (c = 1e-5 m/s,
// no background pressure: else the superfluid the walls set moving pushes the normal particles
// within the step), so that only the friction moves angular momentum between the walls and the
// fluid; one step of the full case's 1e-4 s (courant_number 5.3333e-5 at this c) taken at
// `time`.
struct OneStep {
  double superfluid = 0.0;
  double normal = 0.0;
};
OneStep one_step_at(double time, std::vector<Override> more) {
  more.insert(more.end(), {{"physics.normal_viscosity", "0"},
                           {"spin.coefficient", "0"},
                           {"physics.sound_speed", "1.0e-5"},
                           {"physics.background_pressure", "0"},
                           {"discretisation.courant_number", "5.3333e-5"}});
  auto simulation = make_simulation("rotating-cylinder-small", more);
  simulation->continue_from(std::llround(time / simulation->info().dt), time);
  simulation->advance(1);
  return {angular_momentum(*simulation, "superfluid"), angular_momentum(*simulation, "normal")};
}

// With beta_v = 1e-6 m^2/s, L(10 s) = L0 / (1 + 1e5): at t = 10 s the fluid's friction has all
// but gone. In one step from rest the walls give the superfluid the angular momentum of the
// friction against them (the opening dissipate: the fluid at rest has no counterflow), and the
// normal fluid receives it only through the fluid's friction (the closing one; viscosity off).
// Each is measured against the same step without friction (what is left of the pressure's
// share), and against the step with L = L0 throughout (beta_v = 0), where the superfluid passes
// a little of its gain on to the normal fluid in the closing dissipate: so the held wall friction
// gives the locked run's gain to 1e-2 (measured 5e-4), the decaying one about 1e-5 of it, and the
// normal fluid, with the walls held, about 1e-5 of what the locked run gives it.
TEST(TwoFluidWallGrip, FrictionAgainstWallsKeepsItsInitialLineDensity) {
  const std::vector<Override> decaying{{"mutual_friction.vinen_beta", "1.0e-6"}};
  const std::vector<Override> initial{{"mutual_friction.vinen_beta", "1.0e-6"},
                                      {"mutual_friction.wall_line_density", "\"initial\""}};
  const OneStep none = one_step_at(10.0, {{"mutual_friction.alpha", "0"}});
  const OneStep locked = one_step_at(10.0, {{"mutual_friction.vinen_beta", "0"}});
  const OneStep held = one_step_at(10.0, initial);
  const OneStep decayed = one_step_at(10.0, decaying);
  const double wall_share =
      (held.superfluid - none.superfluid) / (locked.superfluid - none.superfluid);
  const double decayed_share =
      (decayed.superfluid - none.superfluid) / (locked.superfluid - none.superfluid);
  const double fluid_share = (held.normal - none.normal) / (locked.normal - none.normal);
  std::printf("superfluid's gain against L = L0: held at the walls %.6f, decaying %.3e; normal "
              "fluid's (through the fluid's friction) with the walls held %.3e\n",
              wall_share, decayed_share, fluid_share);
  EXPECT_GT(locked.superfluid - none.superfluid, 0.0);
  EXPECT_NEAR(wall_share, 1.0, 1e-2);
  EXPECT_LT(std::abs(decayed_share), 1e-3);
  EXPECT_LT(std::abs(fluid_share), 1e-3);
}

// At t = 0 (and whenever beta_v = 0) the two readings are one: the same bits.
TEST(TwoFluidWallGrip, HeldWallFrictionChangesNothingWhileLStaysAtL0) {
  auto hash_with = [](const char* reading) {
    auto simulation = make_simulation(
        "rotating-cylinder-small",
        {{"mutual_friction.vinen_beta", "0"}, {"mutual_friction.wall_line_density", reading}});
    simulation->advance(50);
    return hash_of(*simulation);
  };
  EXPECT_EQ(hash_with("\"initial\""), hash_with("\"decaying\""));
}

const std::vector<Override> rigid_core{{"physics.normal_viscosity", "0"},
                                       {"mutual_friction.alpha", "0"},
                                       {"discretisation.courant_number", "0.0266"},
                                       {"particles[1].wall_motion", "\"rigid\""}};

// The conservative core with the vessel's wall turning rigidly: forward, reversed, forward,
// reversed returns every raw integer, walls' positions and velocities included.
TEST(TwoFluidWallGrip, RigidWallCoreReturnsBitwiseOnOneAndTwoThreads) {
  revsph::testing::expect_returns_on_one_and_two_threads("rotating-cylinder-small", 1000,
                                                         rigid_core);
}

// Each sub-step undone by itself, the drift with the walls' turn among them.
TEST(TwoFluidWallGrip, RigidWallDriftIsUndoneByItself) {
  auto simulation = make_simulation("rotating-cylinder-small", rigid_core);
  simulation->advance(20);
  for (const auto& check : revsph::check_substeps(*simulation, simulation->info().dt)) {
    EXPECT_TRUE(check.comparison.identical) << check.name << ": " << check.comparison.verdict();
  }
}

// After N steps (every term on) each wall particle sits at its initial position turned by
// Omega N dt about the centre, and moves at Omega x r, to rounding: the lifting steps' rounding
// walks by about a unit a step (positions: 3e-20 m, velocities 9e-16 m/s).
TEST(TwoFluidWallGrip, RigidWallParticlesFollowTheRotation) {
  auto simulation =
      make_simulation("rotating-cylinder-small", {{"particles[1].wall_motion", "\"rigid\""}});
  const revsph::StateSnapshot start = simulation->capture_state();
  const std::int64_t steps = 300;
  simulation->advance(steps);
  const revsph::StateSnapshot end = simulation->capture_state();
  const double omega = 5.0;
  const double angle = omega * static_cast<double>(steps) * simulation->info().dt;
  const revsph::FieldSnapshot& x0 = *start.find("wall", "position");
  const revsph::FieldSnapshot& x = *end.find("wall", "position");
  const revsph::FieldSnapshot& v = *end.find("wall", "velocity");
  // A few units a step's rounding, walking: 8 sqrt(steps) units bounds the largest of ~600.
  const double units = 8.0 * std::sqrt(static_cast<double>(steps));
  const double x_unit = std::ldexp(1.0, x.info.scale.exponent());
  const double v_unit = std::ldexp(1.0, v.info.scale.exponent());
  double position_error = 0.0, velocity_error = 0.0, moved = 0.0;
  for (std::size_t i = 0; i < x.count; ++i) {
    const double ex = std::cos(angle) * x0.real(0, i) - std::sin(angle) * x0.real(1, i);
    const double ey = std::sin(angle) * x0.real(0, i) + std::cos(angle) * x0.real(1, i);
    position_error = std::max(position_error, std::hypot(x.real(0, i) - ex, x.real(1, i) - ey));
    velocity_error = std::max(velocity_error, std::hypot(v.real(0, i) + omega * x.real(1, i),
                                                         v.real(1, i) - omega * x.real(0, i)));
    moved = std::max(moved, std::hypot(x.real(0, i) - x0.real(0, i), x.real(1, i) - x0.real(1, i)));
  }
  std::printf("turned by %.4f rad: largest move %.3e m, position error %.3e m (%.0f units), "
              "velocity error %.3e m/s (%.0f units)\n",
              angle, moved, position_error, position_error / x_unit, velocity_error,
              velocity_error / v_unit);
  EXPECT_GT(moved, 1.0e-6);
  EXPECT_LT(position_error, units * x_unit);
  EXPECT_LT(velocity_error, units * v_unit);
}

// The energy budget with the wall turning rigidly (every term on): the walls' work now includes
// what they do through the pressure as they move (-J_w . v_w per kick, Model::rigid_wall_work),
// and the budget closes as with frozen walls (two_fluid_dissipation_test.cpp): within 1 % of the
// work put in, its error second order in dt.
TEST(TwoFluidWallGrip, EnergyBudgetClosesWithRigidWalls) {
  revsph::testing::expect_cylinder_budget_closes({{"particles[1].wall_motion", "\"rigid\""}});
}

} // namespace
