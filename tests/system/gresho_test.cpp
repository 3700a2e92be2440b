// The Gresho vortex of paper 1 App. A: dummy-particle walls, anti-clump force, Gresho initial
// fields, Shepard filter (passive and active) and the error norm of eq. (11).

#include "core/case_file.hpp"
#include "core/energy_log.hpp"
#include "core/kernel_wendland.hpp"
#include "core/run_loop.hpp"
#include "models/wcsph/gresho.hpp"
#include "models/wcsph/model.hpp"
#include "simulation_fixture.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

using revsph::FixedArithmetic;
using revsph::testing::make_simulation;
using Wcsph2D = revsph::wcsph::Model<2, FixedArithmetic>;

Wcsph2D& model_of(revsph::Simulation& simulation) {
  return dynamic_cast<revsph::ModelSimulation<Wcsph2D>&>(simulation).model();
}

// RMS of (SPH acceleration - exact centripetal acceleration -u^2/r e_r) over RMS of the latter,
// at t = 0: how well the initial state is in equilibrium.
double equilibrium_error(const std::string& dr) {
  auto simulation = make_simulation("gresho", {{"discretisation.dr", dr}});
  Wcsph2D& model = model_of(*simulation);
  const auto& acceleration = model.acceleration();
  const auto& state = model.state();
  double error = 0.0;
  double reference = 0.0;
  for (std::size_t a = 0; a < state.fluid.position.count(); ++a) {
    const double x = revsph::fixedpoint::to_real(state.fluid.position.at(0, a),
                                                 state.fluid.position.info().scale);
    const double y = revsph::fixedpoint::to_real(state.fluid.position.at(1, a),
                                                 state.fluid.position.info().scale);
    const double r = std::hypot(x, y);
    const double u = revsph::wcsph::gresho::azimuthal_velocity(r);
    const double exact_x = r > 0 ? -u * u / r * x / r : 0.0;
    const double exact_y = r > 0 ? -u * u / r * y / r : 0.0;
    error += std::pow(acceleration[0][a] - exact_x, 2) + std::pow(acceleration[1][a] - exact_y, 2);
    reference += exact_x * exact_x + exact_y * exact_y;
  }
  return std::sqrt(error / reference);
}

TEST(Gresho, InitialPressureForceBalancesTheCentripetalAcceleration) {
  // The density is set from the vortex's pressure (inverse Tait), so the SPH pressure force
  // (eq. 1b, with dummy walls) must approximate -u^2/r e_r. Measured 13.4 %, 4.3 %, 1.6 % at
  // dr = 0.04, 0.02, 0.01: it converges with resolution.
  const double coarse = equilibrium_error("0.04");
  const double fine = equilibrium_error("0.02");
  EXPECT_LT(fine, 0.08);
  EXPECT_LT(fine, coarse / 2.0);
}

TEST(Gresho, ErrorNormStartsAtZeroAndCountsTheZeroFieldAsOne) {
  auto simulation = make_simulation("gresho", {{"discretisation.dr", "0.02"}});
  const auto diagnostics = simulation->diagnostics();
  ASSERT_EQ(diagnostics.size(), 2u);
  EXPECT_EQ(diagnostics[0].name, "velocity_error");
  EXPECT_LT(diagnostics[0].value, 1e-10) << "the initial velocity is the exact field";
  // Eq. (11) is normalised so that a fluid at rest has error 1 (up to the quadrature of the
  // particle volumes).
  auto resting = make_simulation("gresho", {{"discretisation.dr", "0.02"}});
  auto state = resting->capture_state();
  for (auto& bits : state.find("fluid", "velocity")->bits) {
    bits = 0;
  }
  resting->restore_state(state);
  EXPECT_NEAR(resting->diagnostics()[0].value, 1.0, 0.02);
}

TEST(Gresho, DummyWallsAndAntiClumpForceAreBitwiseReversible) {
  auto simulation = make_simulation("gresho", {{"discretisation.dr", "0.04"}});
  EXPECT_TRUE(simulation->info().irreversible_terms.empty());
  revsph::VerifyOptions options;
  options.steps = 300;
  const auto report = revsph::verify_reversibility(*simulation, options);
  EXPECT_TRUE(report.identical()) << report.comparison.verdict();
}

TEST(Gresho, ActiveFilterIsDeclaredIrreversibleAndDoesNotReturn) {
  auto simulation =
      make_simulation("gresho", {{"discretisation.dr", "0.04"}, {"filter.mode", "active"}});
  ASSERT_EQ(simulation->info().irreversible_terms.size(), 1u);
  EXPECT_NE(simulation->info().irreversible_terms[0].find("Shepard"), std::string::npos);
  revsph::VerifyOptions options;
  options.steps = 90;
  EXPECT_FALSE(revsph::verify_reversibility(*simulation, options).identical());
}

TEST(Gresho, DummyWallsConserveEnergyWithoutTheAntiClumpForce) {
  // Pressure forces between fluid and fixed dummy particles derive from the compressional
  // energy of both (dummies included in eq. 3), so the total energy is conserved up to the
  // O(dt^2) error of the integrator; the anti-clump force has no such energy.
  auto simulation = make_simulation(
      "gresho", {{"discretisation.dr", "0.04"}, {"physics.anti_clump_pressure", "0.0"}});
  revsph::EnergyLog log(std::nullopt);
  revsph::RunHooks hooks;
  hooks.energy_log = &log;
  hooks.energy_every = 10;
  revsph::run_steps(*simulation, 600, hooks);
  EXPECT_LT(log.max_relative_error(), 1e-6);
}

} // namespace

namespace isc_case {

using revsph::CaseError;

// Kernel density (eq. 4) of every fluid particle with fluid and dummy neighbours, all pairs, from
// the double views of the fixed-point state: independent of the correction's own sums.
double max_density_deviation(Wcsph2D& model, double support_radius, double rest_density) {
  const auto& state = model.state();
  const auto coordinates = [](const auto& field, std::size_t i) {
    return std::array<double, 2>{revsph::fixedpoint::to_real(field.at(0, i), field.info().scale),
                                 revsph::fixedpoint::to_real(field.at(1, i), field.info().scale)};
  };
  const revsph::WendlandQuintic<2> kernel(support_radius);
  double largest = 0.0;
  for (std::size_t a = 0; a < state.fluid.position.count(); ++a) {
    const auto xa = coordinates(state.fluid.position, a);
    double density = 0.0;
    for (std::size_t b = 0; b < state.fluid.position.count(); ++b) {
      const auto xb = coordinates(state.fluid.position, b);
      density +=
          revsph::fixedpoint::to_real(state.fluid.mass.at(0, b), state.fluid.mass.info().scale) *
          kernel.value(std::hypot(xa[0] - xb[0], xa[1] - xb[1]));
    }
    for (std::size_t f = 0; f < state.dummy.position.count(); ++f) {
      const auto xf = coordinates(state.dummy.position, f);
      density +=
          revsph::fixedpoint::to_real(state.dummy.mass.at(0, f), state.dummy.mass.info().scale) *
          kernel.value(std::hypot(xa[0] - xf[0], xa[1] - xf[1]));
    }
    largest = std::max(largest, std::abs(density - rest_density) / rest_density);
  }
  return largest;
}

TEST(GreshoInitialStateCorrection, CaseSwitchMakesTheFluidDensityUniformAndReportsTheSeed) {
  const std::vector<revsph::testing::Override> overrides = {
      {"discretisation.dr", "0.04"},
      {"particles[0].lattice", "\"vogel\""},
      {"initial_state_correction.enabled", "true"},
      {"initial_state_correction.seed", "42"}};
  auto simulation = make_simulation("gresho", overrides);
  const auto& report = simulation->info().setup_report;
  const auto value = [&](const std::string& name) {
    for (const auto& [key, text] : report) {
      if (key == name) {
        return text;
      }
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(value("initial_state_correction.seed"), "42");
  EXPECT_LE(std::stoi(value("initial_state_correction.iterations")), 20);
  EXPECT_LT(std::stod(value("initial_state_correction.final_residual")), 1e-10);
  // Positions are rounded to the 2^-52-relative position scale after the correction, far below
  // the tolerance; checked by an all-pairs sum.
  EXPECT_LT(max_density_deviation(model_of(*simulation), 0.12, 1.0), 1e-9);

  auto without = make_simulation(
      "gresho", {{"discretisation.dr", "0.04"}, {"particles[0].lattice", "\"vogel\""}});
  EXPECT_GT(max_density_deviation(model_of(*without), 0.12, 1.0), 0.05);
  EXPECT_TRUE(without->info().setup_report.empty());
}

TEST(GreshoInitialStateCorrection, NonConvergenceIsACaseErrorNamingTheResidual) {
  try {
    make_simulation("gresho", {{"discretisation.dr", "0.04"},
                               {"particles[0].lattice", "\"vogel\""},
                               {"initial_state_correction.enabled", "true"},
                               {"initial_state_correction.max_iterations", "1"}});
    FAIL() << "expected a CaseError";
  } catch (const CaseError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("initial_state_correction"), std::string::npos) << message;
    EXPECT_NE(message.find("did not converge: max |rho - rho0| / rho0 = "), std::string::npos)
        << message;
    EXPECT_NE(message.find("after 1 Newton iterations"), std::string::npos) << message;
  }
}

} // namespace isc_case
