// A carrier field over two particle sets (core/carrier_field.hpp) numbers the sets' own particles
// set after set, then their ghosts set after set (core/state_field.hpp's ghost segment, filled by
// the distributed layer): with no ghosts it is the one-process numbering, and the ghosts never
// show in the sets' own count(), all() or at().

#include "core/arithmetic.hpp"
#include "core/carrier_field.hpp"
#include "core/state_field.hpp"
#include "fixedpoint/scale.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

using revsph::CarrierField;
using revsph::FixedArithmetic;
using revsph::StateField;
using Field = StateField<std::int64_t>;

Field field(const char* set, std::size_t count, std::int64_t first_value) {
  Field f(revsph::VariableInfo{.name = "position", .unit = "m", .components = 2});
  f.set_particle_set(set);
  f.set_scale(revsph::fixedpoint::Scale::covering(1.0, 40));
  f.resize(count);
  for (int c = 0; c < 2; ++c) {
    for (std::size_t i = 0; i < count; ++i) {
      f.at(c, i) = first_value + 100 * c + static_cast<std::int64_t>(i);
    }
  }
  return f;
}

TEST(CarrierField, OwnParticlesFirstThenGhostsSetAfterSet) {
  Field fluid = field("fluid", 5, 1000);
  Field dummy = field("dummy", 3, 2000);
  const CarrierField<FixedArithmetic> alone{&fluid, &dummy};
  EXPECT_EQ(alone.count(), 8U);
  EXPECT_EQ(alone.raw(1, 6), 2101); // dummy 1, component 1
  EXPECT_EQ(alone.raws(0).size(), 8U);

  // Two fluid ghosts and one dummy ghost, component-major like the owned rows.
  fluid.set_ghosts(2, {7000, 7001, 7100, 7101});
  dummy.set_ghosts(1, {8000, 8100});
  const CarrierField<FixedArithmetic> with_ghosts{&fluid, &dummy};
  EXPECT_EQ(with_ghosts.count(), 11U);
  EXPECT_EQ(with_ghosts.raw(0, 4), 1004);  // the last own fluid particle
  EXPECT_EQ(with_ghosts.raw(0, 5), 2000);  // the first own dummy particle
  EXPECT_EQ(with_ghosts.raw(1, 8), 7100);  // fluid ghost 0
  EXPECT_EQ(with_ghosts.raw(0, 9), 7001);  // fluid ghost 1
  EXPECT_EQ(with_ghosts.raw(1, 10), 8100); // dummy ghost 0
  EXPECT_DOUBLE_EQ(with_ghosts.real(0, 10), FixedArithmetic::real(8000, dummy.info().scale));
  const std::vector<std::int64_t> expected{1000, 1001, 1002, 1003, 1004, 2000,
                                           2001, 2002, 7000, 7001, 8000};
  EXPECT_EQ(with_ghosts.raws(0), expected);
  EXPECT_EQ(with_ghosts.reals(0).size(), 11U);
  // The sets themselves still hold their own particles only.
  EXPECT_EQ(fluid.count(), 5U);
  EXPECT_EQ(fluid.all().size(), 10U);
  EXPECT_EQ(fluid.ghost_count(), 2U);
  EXPECT_EQ(fluid.ghost_at(1, 1), 7101);
}

} // namespace
