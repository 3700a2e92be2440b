// The solid regions of a case's fixed particle blocks (core/wall_regions.hpp), shape by shape: a
// box strictly inside [min, max], a container's walls (open at the top or not), an annulus, an
// outline filled or as its shell, a block's exclude_blocks left out; blocks of other kinds and
// points blocks give none. (An stl block's: tests/unit/stl_region_test.cpp.)

#include "core/wall_regions.hpp"

#include "core/case_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace revsph {
namespace {

const std::vector<std::string> fixed_kinds{"wall", "dummy"};

template <int D>
std::vector<WallRegion<D>> regions_of(const std::string& blocks) {
  const CaseFile case_file = CaseFile::parse(blocks, "walls.toml");
  return read_wall_regions<D>(case_file, 0.1, fixed_kinds);
}

TEST(WallRegions, ABoxIsStrictlyInsideItsMinAndMax) {
  const auto regions = regions_of<2>("[[particles]]\nkind = \"wall\"\nmin = [0.0, -0.3]\n"
                                     "max = [1.0, 0.0]\n");
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].key(), "particles[0]");
  EXPECT_EQ(regions[0].kind(), "wall");
  EXPECT_TRUE(regions[0].contains({0.5, -0.1}));
  EXPECT_TRUE(regions[0].contains({0.001, -0.299}));
  EXPECT_FALSE(regions[0].contains({0.5, 0.0})); // on the face: the fluid's side
  EXPECT_FALSE(regions[0].contains({0.5, 0.01}));
  EXPECT_FALSE(regions[0].contains({1.2, -0.1}));
  EXPECT_FALSE(regions[0].contains({NAN, -0.1}));
  const auto cube = regions_of<3>("[[particles]]\nkind = \"dummy\"\nmin = [0, 0, 0]\n"
                                  "max = [1, 1, 1]\n");
  EXPECT_TRUE(cube[0].contains({0.5, 0.5, 0.5}));
  EXPECT_FALSE(cube[0].contains({0.5, 0.5, 1.5}));
}

TEST(WallRegions, AContainerIsItsWallsAroundTheHollow) {
  // Two layers of 0.1: the walls fill [-0.2, 1.2] x [-0.2, 2.2] outside (0, 1) x (0, 2).
  const std::string container = "[[particles]]\nkind = \"wall\"\nshape = \"container\"\n"
                                "min = [0.0, 0.0]\nmax = [1.0, 2.0]\nlayers = 2\n";
  const auto closed = regions_of<2>(container);
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_FALSE(closed[0].contains({0.5, 1.0}));   // the hollow
  EXPECT_TRUE(closed[0].contains({-0.1, 1.0}));   // the left wall
  EXPECT_TRUE(closed[0].contains({0.5, -0.15}));  // the floor
  EXPECT_TRUE(closed[0].contains({0.5, 2.1}));    // the lid
  EXPECT_TRUE(closed[0].contains({1.1, 2.1}));    // a corner
  EXPECT_FALSE(closed[0].contains({-0.25, 1.0})); // outside the walls
  EXPECT_FALSE(closed[0].contains({0.5, 2.3}));
  const auto open = regions_of<2>(container + "open_top = true\n");
  EXPECT_FALSE(open[0].contains({0.5, 2.1}));  // no lid
  EXPECT_FALSE(open[0].contains({-0.1, 2.1})); // the side walls end at the top
  EXPECT_TRUE(open[0].contains({-0.1, 1.9}));
  EXPECT_TRUE(open[0].contains({0.5, -0.1}));
  EXPECT_FALSE(open[0].contains({0.5, 1.0}));
}

TEST(WallRegions, AnAnnulusIsBetweenItsRadii) {
  const auto regions =
      regions_of<2>("[[particles]]\nkind = \"wall\"\nshape = \"annulus\"\ncentre = [1.0, 1.0]\n"
                    "inner_radius = 0.5\nouter_radius = 0.7\n");
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(regions[0].contains({1.6, 1.0}));
  EXPECT_TRUE(regions[0].contains({1.0 - 0.6 / std::sqrt(2.0), 1.0 - 0.6 / std::sqrt(2.0)}));
  EXPECT_FALSE(regions[0].contains({1.0, 1.0}));
  EXPECT_FALSE(regions[0].contains({1.45, 1.0}));
  EXPECT_FALSE(regions[0].contains({1.75, 1.0}));
  EXPECT_FALSE(regions[0].contains({1.6, 1.6})); // in its bounding box, outside the ring
}

TEST(WallRegions, AnOutlineIsFilledOrItsShell) {
  const std::string square = "[[particles]]\nkind = \"wall\"\nshape = \"outline\"\n"
                             "vertices = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0]\n";
  const auto filled = regions_of<2>(square);
  ASSERT_EQ(filled.size(), 1u);
  EXPECT_TRUE(filled[0].contains({0.5, 0.5}));
  EXPECT_TRUE(filled[0].contains({0.05, 0.5}));
  EXPECT_FALSE(filled[0].contains({1.05, 0.5}));
  // Two layers of 0.1: the 0.2 next to the boundary, not the body inside.
  const auto shell = regions_of<2>(square + "layers = 2\n");
  EXPECT_FALSE(shell[0].contains({0.5, 0.5}));
  EXPECT_TRUE(shell[0].contains({0.05, 0.5}));
  EXPECT_TRUE(shell[0].contains({0.5, 0.85}));
  EXPECT_FALSE(shell[0].contains({0.5, 0.75}));
  EXPECT_FALSE(shell[0].contains({1.05, 0.5}));
}

TEST(WallRegions, ExcludedBlocksAreLeftOut) {
  // A wall slab with a square hole where an outline of fluid sits (a channel around a body).
  const auto regions =
      regions_of<2>("[[particles]]\nkind = \"wall\"\nmin = [0.0, 0.0]\nmax = [2.0, 1.0]\n"
                    "exclude_blocks = [1]\n"
                    "[[particles]]\nkind = \"fluid\"\nshape = \"outline\"\n"
                    "vertices = [0.5, 0.25, 1.0, 0.25, 1.0, 0.75, 0.5, 0.75]\n");
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(regions[0].contains({0.25, 0.5}));
  EXPECT_FALSE(regions[0].contains({0.75, 0.5}));
  EXPECT_TRUE(regions[0].contains({1.5, 0.5}));
}

TEST(WallRegions, OnlyBlocksOfTheGivenKindsWithARegion) {
  // A moving kind's block has no wall region; a points block has none either, and its file is
  // not read (there is none here).
  const auto regions =
      regions_of<2>("[[particles]]\nkind = \"fluid\"\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n"
                    "[[particles]]\nkind = \"wall\"\nshape = \"points\"\nfile = \"missing.csv\"\n"
                    "[[particles]]\nkind = \"dummy\"\nmin = [0.0, -0.2]\nmax = [1.0, 0.0]\n");
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].key(), "particles[2]");
  EXPECT_EQ(regions[0].kind(), "dummy");
}

} // namespace
} // namespace revsph
