// The interaction reach (core/interaction_reach.hpp): the largest radius any list was built for,
// and the refusal of a list beyond the limit a distributed run sets.

#include "core/cell_list.hpp"
#include "core/interaction_reach.hpp"
#include "core/pair_list.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace revsph {
namespace {

TEST(InteractionReach, RecordsTheLargestListRadiusAndRefusesOneBeyondTheLimit) {
  const Box<2> domain{{0.0, 0.0}, {1.0, 1.0}};
  CellList<2> cells(domain, 0.5, 100);
  const CoordinateArrays<2> points{std::vector<double>{0.1, 0.2, 0.7},
                                   std::vector<double>{0.1, 0.3, 0.8}};
  cells.build(view_of<2>(points));
  HalfPairList pairs;
  pairs.build<2>(cells, view_of<2>(points), 0.25);
  EXPECT_GE(largest_interaction_radius(), 0.25);
  limit_interaction_radius(0.3);
  EXPECT_NO_THROW(pairs.build<2>(cells, view_of<2>(points), 0.3));
  EXPECT_THROW(pairs.build<2>(cells, view_of<2>(points), 0.4), std::logic_error);
  limit_interaction_radius(0.0);
  EXPECT_NO_THROW(pairs.build<2>(cells, view_of<2>(points), 0.4));
  EXPECT_GE(largest_interaction_radius(), 0.4);
}

} // namespace
} // namespace revsph
