#pragma once
// Small disordered particle clouds for tests of pair loops (a jittered square or cubic lattice of
// spacing 0.1 with unequal masses), the slot layout over them, and conversions between the
// points' order and the layout's slot order.

#include "core/cell_list.hpp"
#include "core/geometry.hpp"
#include "core/pair_list.hpp"
#include "core/slot_layout.hpp"

#include <algorithm>

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
  CoordinateArrays<D> x;
  std::vector<double> mass;
  double support = 0.0;
};

// A jittered square (2D) or cubic (3D) lattice of spacing dr with unequal masses.
template <int D>
Cloud<D> jittered_lattice(int per_axis, std::uint64_t seed) {
  const double dr = 0.1;
  const double support = 3.0 * dr;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2 * dr, 0.2 * dr);
  Cloud<D> cloud{{}, {}, support};
  int total = 1;
  for (int k = 0; k < D; ++k) {
    total *= per_axis;
  }
  for (int i = 0; i < total; ++i) {
    int rest = i;
    for (int k = 0; k < D; ++k) {
      cloud.x[k].push_back((rest % per_axis) * dr + jitter(rng));
      rest /= per_axis;
    }
  }
  std::uniform_real_distribution<double> mass(0.8, 1.2); // unequal masses: a and b differ
  for (int i = 0; i < total; ++i) {
    cloud.mass.push_back(mass(rng));
  }
  return cloud;
}

// Two points at (1, 1) and (8, 8), unit masses, kernel support 1: out of each other's reach.
inline Cloud<2> two_isolated_points() {
  return {CoordinateArrays<2>{std::vector<double>{1.0, 8.0}, std::vector<double>{1.0, 8.0}},
          {1.0, 1.0},
          1.0};
}

// A slot layout (one particle set, "cloud") over points, with the pairs closer than `support`.
template <int D>
SlotLayout<D> layout_over(const CoordinateArrays<D>& x, double support) {
  Box<D> box;
  for (int k = 0; k < D; ++k) {
    box.min[k] = *std::min_element(x[k].begin(), x[k].end()) - support;
    box.max[k] = *std::max_element(x[k].begin(), x[k].end()) + support;
  }
  SlotLayout<D> layout(box, support, {{"cloud", x[0].size()}});
  layout.build([&](int axis, std::size_t i) { return x[axis][i]; }, support);
  return layout;
}

// Per-point values into the layout's slot order, and back.
template <int D, class T>
std::vector<T> to_slots(const SlotLayout<D>& layout, const std::vector<T>& by_point) {
  std::vector<T> by_slot;
  layout.gather(std::span<const T>(by_point), by_slot);
  return by_slot;
}
template <int D, class T>
std::vector<T> to_points(const SlotLayout<D>& layout, const std::vector<T>& by_slot) {
  std::vector<T> by_point;
  layout.scatter(std::span<const T>(by_slot), by_point);
  return by_point;
}
// `convert` applied to each axis of `arrays`.
template <int D, class Convert>
CoordinateArrays<D> each_axis(const CoordinateArrays<D>& arrays, Convert convert) {
  CoordinateArrays<D> converted;
  for (int k = 0; k < D; ++k) {
    converted[k] = convert(arrays[k]);
  }
  return converted;
}
template <int D>
CoordinateArrays<D> to_slots(const SlotLayout<D>& layout, const CoordinateArrays<D>& by_point) {
  return each_axis<D>(by_point,
                      [&](const std::vector<double>& axis) { return to_slots<D>(layout, axis); });
}
template <int D>
CoordinateArrays<D> to_points(const SlotLayout<D>& layout, const CoordinateArrays<D>& by_slot) {
  return each_axis<D>(by_slot,
                      [&](const std::vector<double>& axis) { return to_points<D>(layout, axis); });
}

} // namespace revsph::testing
