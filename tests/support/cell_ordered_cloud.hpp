#pragma once
// A small disordered particle cloud in cell order with its half pair list, for tests of pair
// loops: a jittered square (2D) or cubic (3D) lattice of spacing 0.1 with unequal masses.

#include "core/cell_list.hpp"
#include "core/geometry.hpp"
#include "core/pair_list.hpp"

#include <cstdint>
#include <random>
#include <vector>

namespace revsph::testing {

// The points, which `cells` was built from, in the cell list's slot order.
template <int D>
CoordinateArrays<D> in_cell_order(const CellList<D>& cells, const CoordinateArrays<D>& points) {
  CoordinateArrays<D> slot_points;
  for (int k = 0; k < D; ++k) {
    for (const std::uint32_t p : cells.sorted_points()) {
      slot_points[k].push_back(points[k][p]);
    }
  }
  return slot_points;
}

template <int D>
struct Cloud {
  CellList<D> cells;
  CoordinateArrays<D> x; // slot order
  std::vector<double> mass;
  HalfPairList pairs;
  double support = 0.0;
};

// A jittered square (2D) or cubic (3D) lattice of spacing dr, in cell order with its pair list.
template <int D>
Cloud<D> jittered_lattice(int per_axis, std::uint64_t seed) {
  const double dr = 0.1;
  const double support = 3.0 * dr;
  Box<D> box;
  for (int k = 0; k < D; ++k) {
    box.min[k] = -dr;
    box.max[k] = (per_axis + 1) * dr;
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2 * dr, 0.2 * dr);
  CoordinateArrays<D> points;
  int total = 1;
  for (int k = 0; k < D; ++k) {
    total *= per_axis;
  }
  for (int i = 0; i < total; ++i) {
    int rest = i;
    for (int k = 0; k < D; ++k) {
      points[k].push_back((rest % per_axis) * dr + jitter(rng));
      rest /= per_axis;
    }
  }
  Cloud<D> cloud{CellList<D>(box, support, 1 << 20), {}, {}, {}, support};
  cloud.cells.build(view_of<D>(points));
  cloud.x = in_cell_order<D>(cloud.cells, points);
  std::uniform_real_distribution<double> mass(0.8, 1.2); // unequal masses: a and b differ
  for (int i = 0; i < total; ++i) {
    cloud.mass.push_back(mass(rng));
  }
  cloud.pairs.template build<D>(cloud.cells, view_of<D>(cloud.x), support);
  return cloud;
}

// Two points at (1, 1) and (8, 8), unit masses, kernel support 1: out of each other's reach.
inline Cloud<2> two_isolated_points() {
  const double support = 1.0;
  Cloud<2> cloud{CellList<2>(Box<2>{{0.0, 0.0}, {10.0, 10.0}}, support, 1000),
                 CoordinateArrays<2>{std::vector<double>{1.0, 8.0}, std::vector<double>{1.0, 8.0}},
                 {1.0, 1.0},
                 {},
                 support};
  cloud.cells.build(view_of<2>(cloud.x));
  cloud.pairs.build<2>(cloud.cells, view_of<2>(cloud.x), support);
  return cloud;
}

} // namespace revsph::testing
