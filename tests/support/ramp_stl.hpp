#pragma once
// A sloped stl wall for the particles-in-walls tests: an ASCII STL wedge 0.4 m long (x) and
// 0.1 m wide (y) on z = 0 whose top rises from z = 0.04 at x = 0 with slope 0.3.

#include <array>
#include <string>

namespace revsph::testing {

// Filled on the lattice of dr = 0.02 from its corner (0, 0, 0), its particles are the points
// (0.01 + 0.02 i, 0.01 + 0.02 j, 0.01 + 0.02 k) under z = 0.04 + 0.3 x.
inline std::string ramp_stl() {
  auto corner = [](double x, double y, bool top) {
    return std::to_string(x) + " " + std::to_string(y) + " " +
           std::to_string(top ? 0.04 + 0.3 * x : 0.0);
  };
  // The corners (x, y, on the top or not) and the faces as quads of them (CGAL turns them one
  // way).
  const struct {
    double x, y;
    bool top;
  } c[8] = {{0, 0, false},   {0.4, 0, false},   {0.4, 0, true},   {0, 0, true},
            {0, 0.1, false}, {0.4, 0.1, false}, {0.4, 0.1, true}, {0, 0.1, true}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  std::string text = "solid ramp\n";
  for (const auto& q : quads) {
    for (const auto& t : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
      text += "facet normal 0 0 0\nouter loop\n";
      for (const int v : t) {
        text += "vertex " + corner(c[v].x, c[v].y, c[v].top) + "\n";
      }
      text += "endloop\nendfacet\n";
    }
  }
  return text + "endsolid ramp\n";
}

// A wcsph case: the fluid of a tank [0, 0.4] x [0, 0.1] x [0, 0.4] whose floor is the ramp, read
// from `stl_file`.
inline std::string ramp_case(const std::string& stl_file) {
  return R"(model = "wcsph"
dimension = 3
name = "ramp"

[physics]
rest_density = 1000.0
sound_speed = 20.0
gravity = 9.8

[discretisation]
dr = 0.02
support_radius_over_dr = 3.0
courant_number = 0.2

[wall]
radius_over_dr = 0.95
energy_per_mass = 20.0

[domain]
min = [-0.1, -0.1, -0.1]
max = [0.5, 0.2, 0.5]

[[particles]]
kind = "fluid"
min = [0.0, 0.0, 0.0]
max = [0.4, 0.1, 0.2]
exclude_blocks = [2]

[[particles]]
kind = "wall"
shape = "container"
min = [0.0, 0.0, 0.0]
max = [0.4, 0.1, 0.4]

[[particles]]
kind = "wall"
shape = "stl"
file = ")" +
         stl_file + R"("

[output]
energy_every = 50
)";
}

} // namespace revsph::testing
