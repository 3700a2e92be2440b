// The pair sums of a region's own particles come out bit for bit as in the whole domain when the
// region's layout holds, besides its own particles, the ghosts within the reach of it
// (docs/design/distributed.md, pieces 4-5): one process plays two, cutting a cloud of two
// particle sets at x = 0.5. The ghosts sit in each StateField's ghost segment, the layout takes
// its set sizes from the carrier field, its own slots per set are the region's particles, and
// ghost slots carry their set's index plus the number of sets.

#include "core/arithmetic.hpp"
#include "core/carrier_field.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/slot_layout.hpp"
#include "core/state_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using namespace revsph;
using Field = StateField<std::int64_t>;
constexpr double support = 0.06;

struct WeightSum { // sum_b m_b W(r_ab), the density of a closed-form SPH sum
  static constexpr int width = 1;
  WendlandQuintic<2> kernel{support};
  std::span<const double> mass;
  void pair(const PairGeometry<2>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    const double w = kernel.value(p.r);
    to_a[0] = mass[p.b] * w;
    to_b[0] = mass[p.a] * w;
  }
};

Field position_field(const char* set) {
  Field field(VariableInfo{.name = "position", .unit = "m", .components = 2});
  field.set_particle_set(set);
  field.set_scale(fixedpoint::Scale::covering(2.0, 62));
  return field;
}

// The raw positions of the chosen particles of a set, component-major.
std::vector<std::int64_t> rows(const Field& all, const std::vector<std::size_t>& chosen) {
  std::vector<std::int64_t> values;
  for (int c = 0; c < 2; ++c) {
    for (const std::size_t i : chosen) {
      values.push_back(all.at(c, i));
    }
  }
  return values;
}

// The sums of the layout's own particles, set after set in each set's order.
std::vector<std::int64_t> own_sums(Field& fluid, Field& dummy, std::array<std::size_t, 2>& owned,
                                   std::array<std::size_t, 2>& ghosts) {
  const Box<2> domain{{-0.1, -0.1}, {1.1, 1.1}};
  SlotLayout<2> layout(domain, support, {{"fluid", 0}, {"dummy", 0}});
  const CarrierField<FixedArithmetic> position{&fluid, &dummy};
  std::vector<double> slot_mass;
  // A mass of each particle's own (a rule on its raw x), whatever its carrier number.
  layout.build(position, support,
               Gathered{[&position](std::size_t c) {
                          return 1.0 + 1e-3 * static_cast<double>(position.raw(0, c) % 7);
                        },
                        &slot_mass});
  PairSums<FixedArithmetic, 1> sums(
      SummedQuantity{"density", fixedpoint::Scale::covering(1e4, 62)});
  sum_pairs<FixedArithmetic>(layout, WeightSum{.mass = slot_mass}, sums);
  std::vector<std::int64_t> result;
  for (std::size_t set = 0; set < 2; ++set) {
    owned[set] = layout.slots_of_set(set).size();
    for (const std::uint32_t s : layout.slots_of_set(set)) {
      result.push_back(sums.raw_total(0, s));
    }
  }
  ghosts = {0, 0};
  for (const std::uint8_t part : layout.set_of_slot()) {
    if (part >= 2) {
      ++ghosts[part - 2];
    }
  }
  return result;
}

TEST(GhostLayout, ARegionWithItsGhostsSumsItsOwnParticlesAsTheWholeDomain) {
  std::mt19937_64 generator(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::array<Field, 2> whole{position_field("fluid"), position_field("dummy")};
  whole[0].resize(1500);
  whole[1].resize(400);
  for (Field& field : whole) {
    for (std::size_t i = 0; i < field.count(); ++i) {
      for (int c = 0; c < 2; ++c) {
        ASSERT_TRUE(
            FixedArithmetic::try_from_real(uniform(generator), field.info().scale, field.at(c, i)));
      }
    }
  }
  std::array<std::size_t, 2> owned{}, ghosts{};
  const std::vector<std::int64_t> reference = own_sums(whole[0], whole[1], owned, ghosts);
  EXPECT_EQ(owned, (std::array<std::size_t, 2>{1500, 400}));
  EXPECT_EQ(ghosts, (std::array<std::size_t, 2>{0, 0}));

  // Each half of the domain with the other half's particles within the support as ghosts.
  std::size_t compared = 0;
  for (const bool left : {true, false}) {
    std::array<Field, 2> region{position_field("fluid"), position_field("dummy")};
    std::array<std::vector<std::size_t>, 2> mine, near;
    for (std::size_t set = 0; set < 2; ++set) {
      const Field& all = whole[set];
      for (std::size_t i = 0; i < all.count(); ++i) {
        const double x = FixedArithmetic::real(all.at(0, i), all.info().scale);
        const bool inside = left ? x < 0.5 : x >= 0.5;
        if (inside) {
          mine[set].push_back(i);
        } else if (std::abs(x - 0.5) < support) {
          near[set].push_back(i);
        }
      }
      region[set].resize(mine[set].size());
      const std::vector<std::int64_t> own_rows = rows(all, mine[set]);
      std::copy(own_rows.begin(), own_rows.end(), region[set].all().begin());
      region[set].set_ghosts(near[set].size(), rows(all, near[set]));
    }
    const std::vector<std::int64_t> sums = own_sums(region[0], region[1], owned, ghosts);
    EXPECT_EQ(owned[0], mine[0].size());
    EXPECT_EQ(ghosts[1], near[1].size());
    EXPECT_GT(ghosts[0], 10U);
    std::size_t differing = 0, n = 0;
    for (std::size_t set = 0; set < 2; ++set) {
      for (const std::size_t i : mine[set]) {
        differing += sums[n++] != reference[set * 1500 + i] ? 1 : 0;
      }
    }
    EXPECT_EQ(differing, 0U);
    compared += n;
  }
  EXPECT_EQ(compared, 1900U);
}

} // namespace
