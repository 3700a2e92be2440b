#pragma once
// The neighbour loops of symplectic WCSPH: density (eq. 5), acceleration (eq. 1b + anti-clump
// force of App. A + gravity + wall force of eq. 7) and the Shepard filter (App. A).
//
// Density carriers are the fluid particles followed by the dummy particles (App. A walls) in one
// array: both have a density and a pressure, so one neighbour list and one loop serve both; only
// fluid particles move. Every per-particle sum goes through Arith::Sum: exact integers in fixed
// point (the same result for any order, cell size and thread count), doubles in FloPA.

#include "core/arithmetic.hpp"
#include "core/fault.hpp"
#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/neighbour_list.hpp"
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

inline const char* carrier_set(std::size_t a, std::size_t fluid_count) {
  return a < fluid_count ? "fluid" : "dummy";
}

inline std::size_t index_in_set(std::size_t a, std::size_t fluid_count) {
  return a < fluid_count ? a : a - fluid_count;
}

// Paper 1 eq. (5): rho_a = sum_b m_b w(r_ab) + C_a over carriers b, the sum including b = a.
template <int D, class Arith>
void compute_density(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                     std::span<const double> mass,
                     std::span<const typename Arith::Raw> density_constant,
                     const NeighbourList& neighbours, const fixedpoint::Scale& density_scale,
                     std::size_t fluid_count, std::vector<double>& density, FaultRecorder& faults) {
  const std::size_t n = mass.size();
  const double self_weight = kernel.value(0.0);
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
    sum.add_raw(density_constant[a]);
    if (!sum.try_value(density[a]) || !(density[a] > 0.0)) {
      faults.record(index_in_set(a, fluid_count), carrier_set(a, fluid_count), "density",
                    "density overflow, non-finite or not positive");
    }
  }
}

// Paper 1 eq. (1b), with the sign that makes it -grad of eq. (3), over carrier neighbours b:
//   a_a = -sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) w'(r_ab) (x_a - x_b) / r_ab
//         - sum_b m_b p0 (1 / rho_a^2 + 1 / rho_b^2) w~'(r_ab) (x_a - x_b) / r_ab   (App. A)
//         + sum_wall F_wall->a / m_a - g e_vertical                               (eq. 7)
// for the fluid particles a < fluid_count. For equal masses the pair term for (a, b) is the exact
// negative of the one for (b, a), so internal forces conserve momentum in integers.
template <int D, class Arith>
void compute_acceleration(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                          const CoordinateView<D>& wall_x, std::span<const double> mass,
                          std::span<const double> pressure_over_density_squared,
                          std::span<const double> inverse_density_squared,
                          const NeighbourList& neighbours, const NeighbourList& wall_neighbours,
                          std::size_t fluid_count, double gravity, const WallPotential& wall,
                          const WendlandQuintic<D>* anti_clump_kernel, double anti_clump_pressure,
                          const fixedpoint::Scale& acceleration_scale,
                          std::array<std::vector<double>, D>& acceleration, FaultRecorder& faults) {
  for (int k = 0; k < D; ++k) {
    acceleration[k].resize(fluid_count);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < fluid_count; ++a) {
    auto sum = sums_at<typename Arith::Sum, D>(acceleration_scale);
    const double pressure_a = pressure_over_density_squared[a];
    for (const std::uint32_t b : neighbours.of(a)) {
      std::array<double, D> d{};
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        d[k] = x[k][a] - x[k][b];
        r_squared += d[k] * d[k];
      }
      const double r = std::sqrt(r_squared);
      double factor =
          -mass[b] * (pressure_a + pressure_over_density_squared[b]) * kernel.derivative_over_r(r);
      if (anti_clump_kernel != nullptr) {
        factor -= mass[b] * anti_clump_pressure *
                  (inverse_density_squared[a] + inverse_density_squared[b]) *
                  anti_clump_kernel->derivative_over_r(r);
      }
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

// App. A Shepard filter of the fluid velocity: u~_a = sum_b V_b u_b w_ab / sum_b V_b w_ab over
// fluid particles b (a included), V_b = m_b / rho_b. Dummy particles do not take part: the
// filter smooths the flow, it is not a wall condition. Plain doubles: the result is either a
// view for people (passive) or an irreversible replacement of the velocities (active).
template <int D>
void shepard_filter(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                    std::span<const double> mass, std::span<const double> density,
                    const std::array<std::vector<double>, D>& velocity,
                    const NeighbourList& neighbours, std::size_t fluid_count,
                    std::array<std::vector<double>, D>& filtered) {
  for (int k = 0; k < D; ++k) {
    filtered[k].resize(fluid_count);
  }
  const double self_weight = kernel.value(0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < fluid_count; ++a) {
    double weight = mass[a] / density[a] * self_weight;
    std::array<double, D> sum{};
    for (int k = 0; k < D; ++k) {
      sum[k] = weight * velocity[k][a];
    }
    for (const std::uint32_t b : neighbours.of(a)) {
      if (b >= fluid_count) {
        continue;
      }
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = x[k][a] - x[k][b];
        r_squared += d * d;
      }
      const double w = mass[b] / density[b] * kernel.value(std::sqrt(r_squared));
      weight += w;
      for (int k = 0; k < D; ++k) {
        sum[k] += w * velocity[k][b];
      }
    }
    for (int k = 0; k < D; ++k) {
      filtered[k][a] = sum[k] / weight;
    }
  }
}

} // namespace revsph::wcsph
