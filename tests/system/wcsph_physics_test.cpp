// Properties of the WCSPH equations as implemented (paper 1 §2–3).

#include "fixedpoint/exact_sum.hpp"
#include "models/wcsph/model.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

namespace {

using revsph::FixedArithmetic;
using revsph::ModelSimulation;
using Wcsph2D = revsph::wcsph::Model<2, FixedArithmetic>;
using revsph::testing::make_simulation;

Wcsph2D& model_of(revsph::Simulation& simulation) {
  auto* adapted = dynamic_cast<ModelSimulation<Wcsph2D>*>(&simulation);
  if (adapted == nullptr) {
    throw std::logic_error("not a 2D fixed-point WCSPH simulation");
  }
  return adapted->model();
}

TEST(Wcsph, IntegrationConstantMakesTheInitialDensityTheRestDensity) {
  // Eq. (5) with C_a = rho0 - rho_a(0): free-surface particles, which have few neighbours, start
  // at rho0 like interior ones.
  auto simulation = make_simulation("dambreak-small");
  Wcsph2D& model = model_of(*simulation);
  const double unit = model.parameters().density_scale.unit();
  for (const double rho : model.density()) {
    ASSERT_NEAR(rho, 1000.0, unit);
  }
  // Interior particles at rest feel gravity only: the pressure is zero everywhere.
  const auto& acceleration = model.acceleration();
  EXPECT_EQ(acceleration[0][2000], 0.0);
  // -g itself is rounded to the acceleration scale, like every force term.
  EXPECT_NEAR(acceleration[1][2000], -9.8, model.parameters().acceleration_scale.unit());
}

TEST(Wcsph, InternalForcesCancelExactlyInIntegers) {
  // Move the fluid (gravity and walls), then look at the same positions without gravity and
  // with a wall of zero energy: the remaining accelerations are the pair terms of eq. (1b),
  // each the exact negative of its partner for equal masses. Their total, rounded term by term
  // to the acceleration scale and summed exactly, is zero: momentum is conserved bit for bit.
  auto moving = make_simulation("dambreak-small");
  moving->advance(400);
  auto internal = make_simulation("dambreak-small",
                                  {{"physics.gravity", "0.0"}, {"wall.energy_per_mass", "0.0"}});
  internal->restore_state(moving->capture_state());
  Wcsph2D& model = model_of(*internal);
  const auto& acceleration = model.acceleration();
  const auto scale = model.parameters().acceleration_scale;
  double largest = 0.0;
  for (int k = 0; k < 2; ++k) {
    revsph::fixedpoint::ExactSum total(scale);
    for (const double a : acceleration[k]) {
      total.add(a);
      largest = std::max(largest, std::abs(a));
    }
    std::int64_t raw = 1;
    ASSERT_TRUE(total.try_raw(raw));
    EXPECT_EQ(raw, 0) << "axis " << k;
  }
  EXPECT_GT(largest, 1.0) << "the fluid is compressed, so there are pressure forces to cancel";
}

} // namespace
