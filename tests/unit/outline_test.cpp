// The rounded-corner outline of core/outline.hpp: areas against closed forms (a square with
// rounded corners, a semicircle-ended column, an L with a fillet), the inside test, the distance
// to the boundary, the mirror image, and refused radii.

#include "core/outline.hpp"

#include "core/case_file.hpp"
#include "core/particle_blocks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace {

using revsph::Box;
using revsph::Outline;
using revsph::Vec;

constexpr double pi = std::numbers::pi;
// Chords of at most 2 degrees: a quarter arc's area falls short of the circle's by about
// (2 degrees)^2 / 6 of the sector's, 2e-4 of it.
constexpr double arc_tolerance = 3e-4;

TEST(Outline, RoundedSquareHasTheAreaOfItsClosedForm) {
  const double r = 0.3;
  const Outline square({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {r, r, r, r});
  EXPECT_NEAR(square.area(), 4.0 - (4.0 - pi) * r * r, arc_tolerance * pi * r * r);
  EXPECT_TRUE(square.contains({1.0, 1.0}));
  EXPECT_FALSE(square.contains({0.02, 0.02})); // cut off by the rounded corner
  EXPECT_TRUE(square.contains({0.5, 0.02}));
  EXPECT_FALSE(square.contains({2.5, 1.0}));
  EXPECT_NEAR(square.distance_to_boundary({1.0, 0.25}), 0.25, 1e-12);
  // From the corner's arc centre (0.3, 0.3), the boundary is r away, less the chords' sagitta
  // r (1 - cos 1 degree) = 1.5e-4 r.
  EXPECT_NEAR(square.distance_to_boundary({r, r}), r, 2e-4 * r);
}

TEST(Outline, ColumnWithBothBottomCornersRoundedEndsInASemicircle) {
  // The fountain's glass column: width 9.9, bottom corners rounded by 4.95.
  const Outline column({{0, 0}, {0, 20}, {9.9, 20}, {9.9, 0}}, {4.95, 0, 0, 4.95});
  const double r = 4.95;
  EXPECT_NEAR(column.area(), 9.9 * (20 - r) + 0.5 * pi * r * r, arc_tolerance * pi * r * r);
  EXPECT_TRUE(column.contains({4.95, 0.1})); // the bottom of the semicircle
  EXPECT_FALSE(column.contains({0.2, 0.2})); // outside it
}

TEST(Outline, ConcaveCornerGetsAFillet) {
  // An L: the inner corner (1, 1) filled with radius 0.5 adds (1 - pi/4) r^2.
  const std::vector<Vec<2>> l{{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  const Outline sharp(l, {});
  const Outline filleted(l, {0, 0, 0, 0.5, 0, 0});
  EXPECT_NEAR(sharp.area(), 3.0, 1e-12);
  EXPECT_NEAR(filleted.area() - sharp.area(), (1.0 - pi / 4.0) * 0.25, arc_tolerance);
  EXPECT_FALSE(sharp.contains({1.05, 1.05}));
  EXPECT_TRUE(filleted.contains({1.05, 1.05}));
}

TEST(Outline, MirrorImageAndOffset) {
  const Outline l({{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}}, {});
  const Outline mirrored = l.transformed(true, {10.0, 0.0});
  EXPECT_TRUE(mirrored.contains({9.5, 1.5}));  // the image of (0.5, 1.5)
  EXPECT_FALSE(mirrored.contains({8.5, 1.5})); // the image of (1.5, 1.5), outside the L
  EXPECT_NEAR(mirrored.area(), 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(mirrored.bounds().min[0], 8.0);
  EXPECT_DOUBLE_EQ(mirrored.bounds().max[0], 10.0);
}

TEST(Outline, RefusesRadiiThatDoNotFitAndDegeneratePolygons) {
  EXPECT_THROW(Outline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0.6, 0.6, 0, 0}), std::invalid_argument);
  // One rounded end may take more than half an edge when the other end is sharp.
  EXPECT_NO_THROW(Outline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0.8, 0, 0, 0}));
  EXPECT_THROW(Outline({{0, 0}, {1, 0}}, {}), std::invalid_argument);
  EXPECT_THROW(Outline({{0, 0}, {1, 0}, {2, 0}}, {}), std::invalid_argument);
  EXPECT_THROW(Outline({{0, 0}, {1, 0}, {1, 1}}, {0, 0}), std::invalid_argument);
}

} // namespace

namespace {

// A box of fluid around a rounded obstacle, the obstacle's wall a shell of three layers on the
// fluid's own lattice: the fluid leaves the obstacle out (exclude_blocks), the shell lies within
// three spacings inside its boundary, and fluid and shell never share a lattice point.
TEST(OutlineBlock, FluidAroundAShellOnOneLattice) {
  const revsph::CaseFile case_file = revsph::CaseFile::parse(R"([[particles]]
kind = "fluid"
min = [0.0, 0.0]
max = [4.0, 3.0]
exclude_blocks = [1]

[[particles]]
kind = "wall"
shape = "outline"
vertices = [0.0, 0.0, 0.0, 1.5, 1.2, 1.5, 1.2, 0.0]
corner_radii = [0.0, 0.5, 0.5, 0.0]
offset = [1.0, 0.5]
lattice_origin = [0.0, 0.0]
layers = 3
)",
                                                             "outline block test");
  const double spacing = 0.05;
  const std::string_view kinds[] = {"fluid", "wall"};
  const auto blocks = revsph::read_particle_blocks<2>(case_file, spacing, Box<2>{{-1, -1}, {5, 4}},
                                                      kinds, {100, 0});
  ASSERT_EQ(blocks.size(), 2u);
  const Outline obstacle = Outline({{0, 0}, {0, 1.5}, {1.2, 1.5}, {1.2, 0}}, {0, 0.5, 0.5, 0})
                               .transformed(false, {1.0, 0.5});
  for (const Vec<2>& p : blocks[0].positions) {
    ASSERT_FALSE(obstacle.contains(p)) << p[0] << ", " << p[1];
  }
  for (const Vec<2>& p : blocks[1].positions) {
    ASSERT_TRUE(obstacle.contains(p));
    ASSERT_LT(obstacle.distance_to_boundary(p), 3.0 * spacing);
  }
  // The fluid fills the box less the obstacle: one particle per spacing^2, to a boundary row.
  const double fluid_area = 12.0 - obstacle.area();
  EXPECT_NEAR(static_cast<double>(blocks[0].positions.size()) * spacing * spacing, fluid_area,
              obstacle.bounds().max[0] * 4.0 * spacing);
  // One lattice: every shell point is a lattice point of the fluid's box (origin [0, 0]).
  for (const Vec<2>& p : blocks[1].positions) {
    for (int k = 0; k < 2; ++k) {
      const double index = p[k] / spacing - 0.5;
      ASSERT_NEAR(index, std::round(index), 1e-9);
    }
  }
}

} // namespace
