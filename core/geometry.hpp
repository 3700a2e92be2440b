#pragma once
// Plain geometric types shared by 2D and 3D code: the dimension D is a template parameter
// everywhere, so one code path serves both.

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace revsph {

template <int D>
using Vec = std::array<double, D>;

// Per-particle coordinates as structure of arrays: coordinate[k][i] is axis k of particle i.
template <int D>
using CoordinateArrays = std::array<std::vector<double>, D>;

template <int D>
using CoordinateView = std::array<std::span<const double>, D>;

template <int D>
CoordinateView<D> view_of(const CoordinateArrays<D>& arrays) {
  CoordinateView<D> view;
  for (int k = 0; k < D; ++k) {
    view[k] = arrays[k];
  }
  return view;
}

// Particle i of structure-of-arrays coordinates (CoordinateArrays or CoordinateView) as a point.
template <int D, class Coordinates>
Vec<D> point_of(const Coordinates& points, std::size_t i) {
  Vec<D> point{};
  for (int k = 0; k < D; ++k) {
    point[k] = points[k][i];
  }
  return point;
}

// |x_a - x_b|^2, summed over the axes in order (the same bits wherever it is used), for points
// of two coordinate sets or of one.
template <int D>
double squared_distance(const CoordinateView<D>& a_points, std::size_t a,
                        const CoordinateView<D>& b_points, std::size_t b) {
  double sum = 0.0;
  for (int k = 0; k < D; ++k) {
    const double d = a_points[k][a] - b_points[k][b];
    sum += d * d;
  }
  return sum;
}
template <int D>
double squared_distance(const CoordinateView<D>& x, std::size_t a, std::size_t b) {
  return squared_distance<D>(x, a, x, b);
}

// The same, also giving the separation d = x_a - x_b.
template <int D>
double squared_distance(const CoordinateView<D>& a_points, std::size_t a,
                        const CoordinateView<D>& b_points, std::size_t b,
                        std::array<double, D>& d) {
  double sum = 0.0;
  for (int k = 0; k < D; ++k) {
    d[k] = a_points[k][a] - b_points[k][b];
    sum += d[k] * d[k];
  }
  return sum;
}
template <int D>
double squared_distance(const CoordinateView<D>& x, std::size_t a, std::size_t b,
                        std::array<double, D>& d) {
  return squared_distance<D>(x, a, x, b, d);
}

template <int D>
struct Box {
  Vec<D> min{};
  Vec<D> max{};

  bool contains(const Vec<D>& point) const {
    for (int k = 0; k < D; ++k) {
      // Written so that NaN is outside.
      if (!(point[k] >= min[k] && point[k] <= max[k])) {
        return false;
      }
    }
    return true;
  }
  // Largest |coordinate| of any point in the box: what a position scale must cover.
  double max_abs_coordinate() const {
    double largest = 0.0;
    for (int k = 0; k < D; ++k) {
      largest = std::max({largest, min[k] < 0 ? -min[k] : min[k], max[k] < 0 ? -max[k] : max[k]});
    }
    return largest;
  }
};

} // namespace revsph
