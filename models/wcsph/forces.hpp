#pragma once
// The neighbour loops of symplectic WCSPH: density (eq. 5) and acceleration (eq. 1b + gravity +
// wall force of eq. 7). Every per-particle sum goes through Arith::Sum: exact integers in fixed
// point (the same result for any order, cell size and thread count), plain doubles in FloPA.

#include "core/arithmetic.hpp"
#include "core/fault.hpp"
#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/neighbour_list.hpp"
#include "core/state_field.hpp"
#include "models/wcsph/equations.hpp"

#include <array>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

namespace revsph::wcsph {

// D accumulators at one scale (Sum has no default constructor).
template <class Sum, int D>
std::array<Sum, D> sums_at(const fixedpoint::Scale& scale) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<Sum, D>{((void)K, Sum(scale))...};
  }
  (std::make_index_sequence<D>{});
}

// Paper 1 eq. (5): rho_a = sum_b m_b w(r_ab) + C_a, the sum including b = a.
template <int D, class Arith>
void compute_density(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                     std::span<const double> mass,
                     const StateField<typename Arith::Raw>& density_constant,
                     const NeighbourList& neighbours, const fixedpoint::Scale& density_scale,
                     std::vector<double>& density, FaultRecorder& faults) {
  const std::size_t n = mass.size();
  const double self_weight = kernel.value(0.0);
  const auto constant = density_constant.component(0);
  density.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    typename Arith::Sum sum(density_scale);
    sum.add(mass[a] * self_weight);
    for (const std::uint32_t b : neighbours.of(a)) {
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = x[k][a] - x[k][b];
        r_squared += d * d;
      }
      sum.add(mass[b] * kernel.value(std::sqrt(r_squared)));
    }
    sum.add_raw(constant[a]);
    if (!sum.try_value(density[a]) || !(density[a] > 0.0)) {
      faults.record(a, "fluid", "density", "density overflow, non-finite or not positive");
    }
  }
}

// Paper 1 eq. (1b), with the sign that makes it -grad of eq. (3):
//   a_a = -sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) w'(r_ab) (x_a - x_b) / r_ab
//         + sum_wall F_wall->a / m_a - g e_vertical.
// For equal masses the pair term for (a, b) is the exact negative of the one for (b, a), so
// internal forces conserve momentum in integers.
template <int D, class Arith>
void compute_acceleration(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                          const CoordinateView<D>& wall_x, std::span<const double> mass,
                          std::span<const double> pressure_over_density_squared,
                          const NeighbourList& neighbours, const NeighbourList& wall_neighbours,
                          double gravity, const WallPotential& wall,
                          const fixedpoint::Scale& acceleration_scale,
                          std::array<std::vector<double>, D>& acceleration, FaultRecorder& faults) {
  const std::size_t n = mass.size();
  for (int k = 0; k < D; ++k) {
    acceleration[k].resize(n);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    auto sum = sums_at<typename Arith::Sum, D>(acceleration_scale);
    const double pressure_a = pressure_over_density_squared[a];
    for (const std::uint32_t b : neighbours.of(a)) {
      std::array<double, D> d{};
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        d[k] = x[k][a] - x[k][b];
        r_squared += d[k] * d[k];
      }
      const double factor = -mass[b] * (pressure_a + pressure_over_density_squared[b]) *
                            kernel.derivative_over_r(std::sqrt(r_squared));
      for (int k = 0; k < D; ++k) {
        sum[k].add(factor * d[k]);
      }
    }
    for (const std::uint32_t w : wall_neighbours.of(a)) {
      std::array<double, D> d{};
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        d[k] = x[k][a] - wall_x[k][w];
        r_squared += d[k] * d[k];
      }
      const double factor = wall.acceleration_over_distance(r_squared);
      for (int k = 0; k < D; ++k) {
        sum[k].add(factor * d[k]);
      }
    }
    sum[D - 1].add(-gravity);
    for (int k = 0; k < D; ++k) {
      if (!sum[k].try_value(acceleration[k][a])) {
        faults.record(a, "fluid", "acceleration", "fixed-point overflow or non-finite force");
      }
    }
  }
}

} // namespace revsph::wcsph
