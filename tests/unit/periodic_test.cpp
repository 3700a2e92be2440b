// Periodic boundaries (core/periodic_box.hpp, core/periodic_wrap.hpp, core/periodic_images.hpp):
// the wrap is addition modulo the period, so a drift across a face is undone bit for bit by the
// reversed drift; the images a particle needs at faces, edges and corners; images placed as
// ghosts with their positions shifted by exactly one period.

#include "core/arithmetic.hpp"
#include "core/fault.hpp"
#include "core/periodic_images.hpp"
#include "core/periodic_wrap.hpp"
#include "core/state_field.hpp"
#include "core/verlet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using revsph::FaultRecorder;
using revsph::FixedArithmetic;
using revsph::ImageShift;
using revsph::PeriodicBox;
using revsph::StateField;
using Raw = std::int64_t;

PeriodicBox unit_box(bool x, bool y) {
  PeriodicBox box;
  box.periodic = {x, y, false};
  box.min = {0.0, -0.5, 0.0};
  box.max = {1.0, 0.75, 0.0};
  return box;
}

TEST(PeriodicWrap, IsTheResidueModuloThePeriod) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<Raw> any(-(Raw{1} << 60), Raw{1} << 60);
  for (int trial = 0; trial < 10000; ++trial) {
    const Raw lower = any(random) / 4;
    const Raw period = 1 + std::abs(any(random)) / 8;
    const Raw x = any(random);
    const Raw wrapped = revsph::wrapped(x, lower, period);
    ASSERT_GE(wrapped, lower);
    ASSERT_LT(wrapped, lower + period);
    // x - wrapped is a whole number of periods (computed without overflow: both are below 2^62).
    ASSERT_EQ((static_cast<__int128>(x) - wrapped) % period, 0);
  }
}

TEST(PeriodicWrap, DriftAcrossTheFacesReversesBitForBit) {
  const PeriodicBox box = unit_box(true, true);
  StateField<Raw> position({.name = "position", .unit = "m", .components = 2});
  StateField<Raw> velocity(
      {.name = "velocity", .unit = "m/s", .parity = revsph::Parity::odd, .components = 2});
  position.set_scale(revsph::fixedpoint::Scale(-50));
  velocity.set_scale(revsph::fixedpoint::Scale(-40));
  position.set_period(box);
  const std::size_t n = 2000;
  position.resize(n);
  velocity.resize(n);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 2; ++k) {
      const double x = box.min[k] + unit(random) * box.length(k);
      ASSERT_TRUE(FixedArithmetic::try_from_real(std::min(x, box.max[k] - 1e-9),
                                                 position.info().scale, position.at(k, i)));
      ASSERT_TRUE(FixedArithmetic::try_from_real(40.0 * (unit(random) - 0.5), velocity.info().scale,
                                                 velocity.at(k, i)));
    }
  }
  const std::vector<Raw> start(position.all().begin(), position.all().end());
  const revsph::RawPeriod<Raw> raw = revsph::raw_period<Raw>(position.info());
  FaultRecorder faults;
  std::size_t crossed = 0;
  // Steps long enough to cross a face (|v| dt up to 0.6 of a period) and several periods.
  for (int step = 0; step < 50; ++step) {
    const std::vector<Raw> before(position.all().begin(), position.all().end());
    revsph::drift<FixedArithmetic>(position, velocity, 0.03, faults);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 2; ++k) {
        const Raw x = position.at(k, i);
        ASSERT_GE(x, raw.lower[k]);
        ASSERT_LT(x, raw.lower[k] + raw.period[k]);
        const Raw was = before[static_cast<std::size_t>(k) * n + i];
        crossed += (x - was > raw.period[k] / 2 || was - x > raw.period[k] / 2) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(crossed, n); // the test crosses faces, many times
  for (int step = 0; step < 50; ++step) {
    revsph::drift<FixedArithmetic>(position, velocity, -0.03, faults);
  }
  EXPECT_TRUE(std::equal(start.begin(), start.end(), position.all().begin()));
}

TEST(PeriodicImages, ShiftsAtFacesEdgesAndCorners) {
  const PeriodicBox box = unit_box(true, true);
  const double centre[] = {0.5, 0.1};
  EXPECT_TRUE(revsph::image_shifts(centre, 2, box, 0.1).empty());
  const double near_low_x[] = {0.05, 0.1};
  EXPECT_EQ(revsph::image_shifts(near_low_x, 2, box, 0.1), (std::vector<ImageShift>{{1, 0, 0}}));
  const double corner[] = {0.95, -0.45};
  EXPECT_EQ(revsph::image_shifts(corner, 2, box, 0.1),
            (std::vector<ImageShift>{{-1, 0, 0}, {0, 1, 0}, {-1, 1, 0}}));
  // Only the periodic axes have images.
  EXPECT_EQ(revsph::image_shifts(corner, 2, unit_box(false, true), 0.1),
            (std::vector<ImageShift>{{0, 1, 0}}));
}

struct OneSet {
  StateField<Raw> position{{.name = "position", .unit = "m", .components = 2}};
  StateField<Raw> mass{{.name = "mass", .unit = "kg"}};
  auto fields() { return std::tie(position, mass); }
  static constexpr revsph::SetInfo set{.name = "fluid", .motion = revsph::Motion::moving};
};
struct OneSetState {
  OneSet fluid;
  auto sets() { return std::tie(fluid); }
};

TEST(PeriodicImages, AttachedAsGhostsShiftedByOnePeriod) {
  OneSetState state;
  state.fluid.position.set_scale(revsph::fixedpoint::Scale(-50));
  state.fluid.mass.set_scale(revsph::fixedpoint::Scale(-40));
  state.fluid.position.set_period(unit_box(true, false));
  const double points[][2] = {{0.02, 0.0}, {0.5, 0.0}, {0.97, 0.7}};
  state.fluid.position.resize(3);
  state.fluid.mass.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    for (int k = 0; k < 2; ++k) {
      FixedArithmetic::try_from_real(points[i][k], state.fluid.position.info().scale,
                                     state.fluid.position.at(k, i));
    }
    state.fluid.mass.at(0, i) = static_cast<Raw>(i + 1);
  }
  EXPECT_TRUE(revsph::has_periodic_positions(state));
  revsph::attach_periodic_images(state, 0.1);
  const auto& position = state.fluid.position;
  ASSERT_EQ(position.ghost_count(), 2U);
  const revsph::RawPeriod<Raw> raw = revsph::raw_period<Raw>(position.info());
  EXPECT_EQ(position.ghost_at(0, 0), position.at(0, 0) + raw.period[0]);
  EXPECT_EQ(position.ghost_at(1, 0), position.at(1, 0));
  EXPECT_EQ(position.ghost_at(0, 1), position.at(0, 2) - raw.period[0]);
  EXPECT_EQ(state.fluid.mass.ghost_at(0, 0), 1);
  EXPECT_EQ(state.fluid.mass.ghost_at(0, 1), 3);
}

} // namespace
