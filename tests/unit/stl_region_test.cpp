// A closed STL surface as a region (core/stl_region.hpp, CGAL): the inside of a cube written
// here, whichever way its triangles face; a surface with a face missing, a file that is no STL
// and a missing file are one-line errors; the obstacle script's box and cylinder read back closed
// with their volumes; an "stl" block fills the inside on the lattice and excludes it from another,
// and as a wall its inside is its region (core/wall_regions.hpp).

#include "core/case_file.hpp"
#include "core/particle_blocks.hpp"
#include "core/stl_region.hpp"
#include "core/wall_regions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {
namespace {

namespace fs = std::filesystem;

// The unit cube's 12 triangles, outward (or inward) facing, `skip` of them left out.
std::string cube_stl(bool inward = false, int skip = 0) {
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto corner = [](int c) {
    return std::to_string(c & 1) + " " + std::to_string((c >> 1) & 1) + " " +
           std::to_string((c >> 2) & 1);
  };
  std::string text = "solid cube\n";
  int written = 0;
  for (const auto& q : quads) {
    for (const auto& t : {std::array{q[0], q[1], q[3]}, std::array{q[1], q[2], q[3]}}) {
      if (written++ < skip) {
        continue;
      }
      text += "facet normal 0 0 0\nouter loop\n";
      for (int v = 0; v < 3; ++v) {
        text += "vertex " + corner(t[inward ? 2 - v : v]) + "\n";
      }
      text += "endloop\nendfacet\n";
    }
  }
  return text + "endsolid cube\n";
}

class StlRegionTest : public testing::Test {
protected:
  void SetUp() override {
    folder_ =
        fs::temp_directory_path() / ("revsph-stl-" + std::to_string(::getpid()) + "-" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(folder_ / name) << text;
    return (folder_ / name).string();
  }
  std::string refusal(const std::string& path) {
    try {
      StlRegion region(read_input_file(path, path));
    } catch (const StlError& error) {
      return error.what();
    } catch (const InputFileError& error) {
      return error.what();
    }
    return "";
  }
  fs::path folder_;
};

TEST_F(StlRegionTest, TheInsideOfACubeWhicheverWayItsTrianglesFace) {
  for (const bool inward : {false, true}) {
    const std::string path = write("cube.stl", cube_stl(inward));
    const StlRegion cube(read_input_file(path, path));
    EXPECT_EQ(cube.triangle_count(), 12u);
    EXPECT_NEAR(cube.volume(), 1.0, 1e-12);
    EXPECT_EQ(cube.bounds().min, (Vec<3>{0, 0, 0}));
    EXPECT_EQ(cube.bounds().max, (Vec<3>{1, 1, 1}));
    EXPECT_TRUE(cube.contains({0.5, 0.5, 0.5}));
    EXPECT_TRUE(cube.contains({0.01, 0.99, 0.5}));
    EXPECT_FALSE(cube.contains({1.01, 0.5, 0.5}));
    EXPECT_FALSE(cube.contains({0.5, -0.01, 0.5}));
    // A grid of spacing 0.1 over [-0.45, 1.55]^3: 10^3 of its points are inside (none on a face).
    std::vector<Vec<3>> grid;
    for (int i = 0; i < 21; ++i) {
      for (int j = 0; j < 21; ++j) {
        for (int k = 0; k < 21; ++k) {
          grid.push_back({-0.95 + 0.1 * i, -0.95 + 0.1 * j, -0.95 + 0.1 * k});
        }
      }
    }
    EXPECT_EQ(cube.inside(grid).size(), 1000u) << (inward ? "inward" : "outward");
  }
}

TEST_F(StlRegionTest, OpenSurfacesAndOtherFilesAreRefused) {
  EXPECT_NE(refusal(write("open.stl", cube_stl(false, 1))).find("is not closed"),
            std::string::npos);
  EXPECT_NE(refusal(write("text.stl", "hello\n")).find("not an STL file"), std::string::npos);
  const std::string missing = (folder_ / "missing.stl").string();
  EXPECT_EQ(refusal(missing), missing + ": no such file");
}

TEST_F(StlRegionTest, TheObstacleScriptsSurfacesAreClosedWithTheirVolumes) {
  const std::string script =
      std::string(REVSPH_SOURCE_DIR) + "/tools/geometry/make_obstacle_stl.py";
  const std::string box = (folder_ / "box.stl").string();
  const std::string pillar = (folder_ / "pillar.stl").string();
  ASSERT_EQ(std::system(("/usr/bin/python3 " + script + " --box 0.6 0.075 0 0.7 0.175 0.15 --out " +
                         box + " > /dev/null")
                            .c_str()),
            0);
  ASSERT_EQ(
      std::system(("/usr/bin/python3 " + script +
                   " --cylinder 0.5 0.5 0.2 0 0.3 --segments 24 --out " + pillar + " > /dev/null")
                      .c_str()),
      0);
  EXPECT_NEAR(StlRegion(read_input_file(box, box)).volume(), 0.1 * 0.1 * 0.15, 1e-12);
  // A 24-sided prism: area n r^2 sin(2 pi / n) / 2.
  EXPECT_NEAR(StlRegion(read_input_file(pillar, pillar)).volume(),
              24 * 0.04 * std::sin(2 * std::numbers::pi / 24) / 2 * 0.3, 1e-12);
}

TEST_F(StlRegionTest, AnStlBlockFillsTheInsideAndExcludesItFromAnother) {
  write("cube.stl", cube_stl());
  const CaseFile case_file = CaseFile::parse(
      "[[particles]]\nkind = \"wall\"\nshape = \"stl\"\nfile = \"cube.stl\"\nscale = 0.5\n"
      "offset = [1.0, 0.0, 0.0]\n"
      "[[particles]]\nkind = \"fluid\"\nmin = [0, 0, 0]\nmax = [2, 1, 1]\nexclude_blocks = [0]\n",
      (folder_ / "case.toml").string());
  const std::string_view kinds[] = {"fluid", "wall"};
  const auto blocks = read_particle_blocks<3>(case_file, 0.1, Box<3>{{-1, -1, -1}, {3, 2, 2}},
                                              kinds, ParticleBudget{100.0, 1u << 30, 0.0});
  // The cube scaled to 0.5 m and moved to x = 1: 5^3 lattice points of spacing 0.1 inside.
  EXPECT_EQ(blocks[0].positions.size(), 125u);
  for (const Vec<3>& p : blocks[0].positions) {
    EXPECT_GT(p[0], 1.0);
    EXPECT_LT(p[0], 1.5);
  }
  EXPECT_EQ(blocks[1].positions.size(), 20u * 10u * 10u - 125u);
}

TEST_F(StlRegionTest, AnStlWallBlocksRegionIsItsInside) {
  write("cube.stl", cube_stl());
  const CaseFile case_file = CaseFile::parse(
      "[[particles]]\nkind = \"wall\"\nshape = \"stl\"\nfile = \"cube.stl\"\nscale = 0.5\n"
      "offset = [1.0, 0.0, 0.0]\n",
      (folder_ / "case.toml").string());
  const std::vector<std::string> fixed{"wall"};
  const auto regions = read_wall_regions<3>(case_file, 0.1, fixed);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(regions[0].contains({1.25, 0.25, 0.25}));
  EXPECT_TRUE(regions[0].contains({1.01, 0.49, 0.01}));
  EXPECT_FALSE(regions[0].contains({0.75, 0.25, 0.25}));
  EXPECT_FALSE(regions[0].contains({1.25, 0.25, 0.55}));
}

} // namespace
} // namespace revsph
