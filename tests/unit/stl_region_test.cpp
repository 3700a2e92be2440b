// A closed STL surface as a region (core/stl_region.hpp, CGAL): the inside of a cube written
// here, whichever way its triangles face; a surface with a face missing, a file that is no STL
// and a missing file are one-line errors; the obstacle script's box and cylinder read back closed
// with their volumes; an "stl" block fills the inside on the lattice and excludes it from another,
// and as a wall its inside is its region (core/wall_regions.hpp).

#include "core/case_file.hpp"
#include "core/particle_blocks.hpp"
#include "core/stl_region.hpp"
#include "core/wall_regions.hpp"

#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {
namespace {

namespace fs = std::filesystem;

// The box [lo, hi]'s 12 triangles, outward (or inward) facing, `skip` of them left out, as one
// ASCII solid.
std::string box_stl(const Vec<3>& lo, const Vec<3>& hi, bool inward = false, int skip = 0) {
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto corner = [&](int c) {
    return std::to_string(c & 1 ? hi[0] : lo[0]) + " " + std::to_string(c & 2 ? hi[1] : lo[1]) +
           " " + std::to_string(c & 4 ? hi[2] : lo[2]);
  };
  std::string text = "solid box\n";
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
  return text + "endsolid box\n";
}

// The unit cube's.
std::string cube_stl(bool inward = false, int skip = 0) {
  return box_stl({0, 0, 0}, {1, 1, 1}, inward, skip);
}

// The points of a grid of spacing 0.1 over [-0.95, 1.05]^3 that `region` holds (none lies on a
// face of the boxes here).
std::size_t grid_points_inside(const StlRegion& region) {
  std::vector<Vec<3>> grid;
  for (int i = 0; i < 21; ++i) {
    for (int j = 0; j < 21; ++j) {
      for (int k = 0; k < 21; ++k) {
        grid.push_back({-0.95 + 0.1 * i, -0.95 + 0.1 * j, -0.95 + 0.1 * k});
      }
    }
  }
  return region.inside(grid).size();
}

class StlRegionTest : public ::testing::Test {
protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("revsph-stl-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(folder_ / name) << text;
    return (folder_ / name).string();
  }
  InputFile input(const std::string& name, const std::string& text) {
    const std::string path = write(name, text);
    return read_input_file(path, path);
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
    EXPECT_EQ(grid_points_inside(cube), 1000u) << (inward ? "inward" : "outward");
  }
}

TEST_F(StlRegionTest, OpenSurfacesAndOtherFilesAreRefused) {
  EXPECT_NE(refusal(write("open.stl", cube_stl(false, 1))).find("is not closed"),
            std::string::npos);
  EXPECT_NE(refusal(write("text.stl", "hello\n")).find("not an STL file"), std::string::npos);
  const std::string missing = (folder_ / "missing.stl").string();
  EXPECT_EQ(refusal(missing), missing + ": no such file");
}

TEST_F(StlRegionTest, OverlappingShellsAreUnited) {
  // Two boxes of 8 x 4 x 4 grid points sharing 2 x 4 x 4 of them: 128 + 128 - 32 inside, in one
  // solid or two.
  const std::string a = box_stl({-0.6, 0, 0}, {0.2, 0.4, 0.4});
  const std::string b = box_stl({0.0, 0, 0}, {0.8, 0.4, 0.4});
  const std::string one_solid = a.substr(0, a.rfind("endsolid")) + b.substr(b.find('\n') + 1);
  for (const std::string& text : {a + b, one_solid}) {
    const StlRegion both(input("both.stl", text));
    EXPECT_EQ(both.shell_count(), 2u);
    EXPECT_EQ(grid_points_inside(both), 224u);
    EXPECT_TRUE(both.contains({0.1, 0.2, 0.2})); // in both
    EXPECT_TRUE(both.contains({-0.3, 0.2, 0.2}));
    EXPECT_TRUE(both.contains({0.5, 0.2, 0.2}));
  }
}

TEST_F(StlRegionTest, AShellInsideAnotherIsACavityWhenItFacesTheOtherWay) {
  // The unit cube around the box [0.3, 0.7]^3 (4^3 grid points): facing inward, the inner box is
  // the hollow of a hollow body; facing outward as the cube does, it adds nothing to it.
  const std::string inner_in = box_stl({0.3, 0.3, 0.3}, {0.7, 0.7, 0.7}, true);
  const std::string inner_out = box_stl({0.3, 0.3, 0.3}, {0.7, 0.7, 0.7}, false);
  const StlRegion hollow(input("hollow.stl", cube_stl() + inner_in));
  EXPECT_EQ(hollow.shell_count(), 2u);
  EXPECT_EQ(grid_points_inside(hollow), 1000u - 64u);
  EXPECT_FALSE(hollow.contains({0.5, 0.5, 0.5}));
  EXPECT_TRUE(hollow.contains({0.15, 0.5, 0.5}));
  EXPECT_NEAR(hollow.volume(), 1.0 - 0.4 * 0.4 * 0.4, 1e-12);
  // Both turned inside out: the same body.
  const StlRegion turned(input("turned.stl", cube_stl(true) + inner_out));
  EXPECT_EQ(grid_points_inside(turned), 1000u - 64u);
  const StlRegion solid(input("solid.stl", cube_stl() + inner_out));
  EXPECT_EQ(grid_points_inside(solid), 1000u);
  EXPECT_TRUE(solid.contains({0.5, 0.5, 0.5}));
}

TEST_F(StlRegionTest, CrossingShellsFacingOppositeWaysAreRefused) {
  const std::string a = box_stl({-0.6, 0, 0}, {0.2, 0.4, 0.4});
  const std::string b = box_stl({0.0, 0, 0}, {0.8, 0.4, 0.4}, true);
  EXPECT_NE(refusal(write("crossing.stl", a + b))
                .find(": shells 1 and 2 face opposite ways and cross (a cavity must lie inside "
                      "its solid)"),
            std::string::npos);
}

TEST_F(StlRegionTest, ABadLineIsNamedByItsNumber) {
  // Line 1 "solid box", then 7 lines a facet: line 4 is the first facet's first vertex.
  std::string nan_vertex = cube_stl();
  nan_vertex.replace(nan_vertex.find("vertex"),
                     nan_vertex.find('\n', nan_vertex.find("vertex")) - nan_vertex.find("vertex"),
                     "vertex nan 0 0");
  const std::string nan_path = write("nan.stl", nan_vertex);
  EXPECT_EQ(refusal(nan_path), nan_path + ": line 4: expected \"vertex X Y Z\" with three finite "
                                          "numbers (\"vertex nan 0 0\")");
  // A stray word between two facets (line 9), which CGAL's reader would pass over.
  std::string stray = cube_stl();
  stray.insert(stray.find("facet", stray.find("endfacet") + 8), "garbage here\n");
  const std::string stray_path = write("stray.stl", stray);
  EXPECT_EQ(refusal(stray_path), stray_path + ": line 9: expected \"facet normal NX NY NZ\" or "
                                              "\"endsolid\" (\"garbage here\")");
  std::string huge = cube_stl();
  huge.replace(huge.find("0.000000"), 8, "1e999");
  EXPECT_NE(refusal(write("huge.stl", huge)).find(": line 4: expected \"vertex X Y Z\""),
            std::string::npos);
  std::string quad = cube_stl();
  quad.insert(quad.find("endloop"), "vertex 0 0 0\n");
  EXPECT_NE(refusal(write("quad.stl", quad))
                .find(": line 7: a facet of more than 3 vertices: only triangles are read"),
            std::string::npos);
}

TEST_F(StlRegionTest, ANonFiniteCoordinateOfABinaryFileIsNamedByItsTriangle) {
  // 80 bytes of header, the count, then per triangle 12 floats and 2 bytes; triangle 3 has a NaN.
  std::string binary(80, ' ');
  const std::uint32_t count = 4;
  binary.append(reinterpret_cast<const char*>(&count), 4);
  const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (int t = 0; t < 4; ++t) {
    float values[12] = {0, 0, 0};
    for (int v = 0; v < 3; ++v) {
      for (int k = 0; k < 3; ++k) {
        values[3 + 3 * v + k] = corners[faces[t][v]][k];
      }
    }
    if (t == 2) {
      values[4] = std::numeric_limits<float>::quiet_NaN();
    }
    binary.append(reinterpret_cast<const char*>(values), sizeof values);
    binary.append(2, '\0');
  }
  const std::string path = write("nan-binary.stl", binary);
  EXPECT_EQ(refusal(path), path + ": triangle 3: a corner's coordinate is not a finite number");
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

TEST_F(StlRegionTest, AnStlBlockOfTwoOverlappingShellsFillsTheirUnion) {
  write("two.stl", box_stl({-0.6, 0, 0}, {0.2, 0.4, 0.4}) + box_stl({0.0, 0, 0}, {0.8, 0.4, 0.4}));
  const CaseFile case_file =
      CaseFile::parse("[[particles]]\nkind = \"wall\"\nshape = \"stl\"\nfile = \"two.stl\"\n",
                      (folder_ / "case.toml").string());
  const std::string_view kinds[] = {"wall"};
  const auto blocks = read_particle_blocks<3>(case_file, 0.1, Box<3>{{-1, -1, -1}, {1, 1, 1}},
                                              kinds, ParticleBudget{100.0, 1u << 30, 0.0});
  // 14 columns of 4 x 4 points: 8 + 8 less the 2 both boxes hold.
  EXPECT_EQ(blocks[0].positions.size(), 224u);
}

TEST_F(StlRegionTest, TheRunRefusesABadLineInOneLineNamingIt) {
  revsph::testing::Sandbox sandbox;
  std::string text = cube_stl();
  text.replace(text.find("vertex"), text.find('\n', text.find("vertex")) - text.find("vertex"),
               "vertex 0 NaN 0");
  std::ofstream(sandbox.work() / "bad.stl") << text;
  sandbox.write_case(R"(model = "wcsph"
dimension = 3
[physics]
rest_density = 1000.0
sound_speed = 20.0
[discretisation]
dr = 0.1
support_radius_over_dr = 3.0
courant_number = 0.2
[domain]
min = [-1.0, -1.0, -1.0]
max = [2.0, 2.0, 2.0]
[[particles]]
kind = "fluid"
min = [-0.5, -0.5, -0.5]
max = [0.0, 0.0, 0.0]
[[particles]]
kind = "wall"
shape = "stl"
file = "bad.stl"
)");
  const revsph::testing::CommandResult result =
      sandbox.revsph({"run", "case.toml", "--steps", "0", "--out", sandbox.out().string()});
  EXPECT_EQ(result.exit_status, 2) << result;
  EXPECT_EQ(result.err, "revsph: error: case.toml: particles[1].file: bad.stl: line 4: expected "
                        "\"vertex X Y Z\" with three finite numbers (\"vertex 0 NaN 0\")\n")
      << result;
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
