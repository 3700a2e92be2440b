#pragma once
// The neighbour loops of symplectic WCSPH: density (eq. 5), acceleration (eq. 1b + anti-clump
// force of App. A + gravity + wall force of eq. 7) and the Shepard filter (App. A).
//
// Density carriers are the fluid particles followed by the dummy particles (App. A walls): both
// have a density and a pressure, so one pair list and one loop serve both; only fluid particles
// move. The loops run over the carriers in cell order ("slots", core/pair_list.hpp): every array
// passed in is indexed by slot, and carrier_of_slot[s] names the carrier (fluid index, or
// fluid_count + dummy index) for the fluid test and for fault reports. Each pair is visited once
// and its term added to both particles. Every per-particle sum goes through Arith::Sum(s): exact
// integers in fixed point (the same result for any order, cell size and thread count), doubles in
// FloPA (summed in the order fixed by the pair list, the same for any thread count).

#include "core/arithmetic.hpp"
#include "core/fault.hpp"
#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/neighbour_list.hpp"
#include "core/pair_list.hpp"
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
                     const HalfPairList& pairs, std::span<const std::uint32_t> carrier_of_slot,
                     std::size_t fluid_count, typename Arith::Sums& sums,
                     std::vector<double>& density, FaultRecorder& faults) {
  const std::size_t n = mass.size();
  sums.reset(n);
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    typename Arith::Sum own(sums.scale());
    for (const std::uint32_t b : partners) {
      const double r_squared = squared_distance<D>(x, a, b);
      const double w = kernel.value(std::sqrt(r_squared));
      own.add(mass[b] * w);
      sums.add(b, mass[a] * w);
    }
    sums.add_sum(a, own);
  });
  const double self_weight = kernel.value(0.0);
  density.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    sums.add(a, mass[a] * self_weight);
    sums.add_raw(a, density_constant[a]);
    if (!sums.try_value(a, density[a]) || !(density[a] > 0.0)) {
      const std::size_t carrier = carrier_of_slot[a];
      faults.record(index_in_set(carrier, fluid_count), carrier_set(carrier, fluid_count),
                    "density", "density overflow, non-finite or not positive");
    }
  }
}

// Paper 1 eq. (1b), with the sign that makes it -grad of eq. (3), over carrier neighbours b:
//   a_a = -sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) w'(r_ab) (x_a - x_b) / r_ab
//         - sum_b m_b p0 (1 / rho_a^2 + 1 / rho_b^2) w~'(r_ab) (x_a - x_b) / r_ab   (App. A)
//         + sum_wall F_wall->a / m_a - g e_vertical                               (eq. 7)
// for the fluid slots, written to acceleration[k][carrier] (canonical fluid order). The term b
// receives from a pair is computed as if b were the query (its own mass factor, x_b - x_a =
// -(x_a - x_b) exactly), so the sums are those of a per-particle loop; for equal masses it is
// the exact negative of a's term, so internal forces conserve momentum in integers.
// wall_neighbours lists, per slot, the wall particles within the wall radius.
template <int D, class Arith>
void compute_acceleration(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                          const CoordinateView<D>& wall_x, std::span<const double> mass,
                          std::span<const double> pressure_over_density_squared,
                          std::span<const double> inverse_density_squared,
                          const HalfPairList& pairs, const NeighbourList& wall_neighbours,
                          std::span<const std::uint32_t> carrier_of_slot, std::size_t fluid_count,
                          double gravity, const WallPotential& wall,
                          const WendlandQuintic<D>* anti_clump_kernel, double anti_clump_pressure,
                          std::array<typename Arith::Sums, D>& sums,
                          std::array<std::vector<double>, D>& acceleration, FaultRecorder& faults) {
  const std::size_t n = mass.size();
  for (int k = 0; k < D; ++k) {
    sums[k].reset(n);
    acceleration[k].resize(fluid_count);
  }
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    auto own = sums_at<typename Arith::Sum, D>(sums[0].scale());
    const double pressure_a = pressure_over_density_squared[a];
    for (const std::uint32_t b : partners) {
      std::array<double, D> d{};
      const double r_squared = squared_distance<D>(x, a, b, d);
      const double r = std::sqrt(r_squared);
      const double pressure_sum = pressure_a + pressure_over_density_squared[b];
      const double slope = kernel.derivative_over_r(r);
      double factor_a = -mass[b] * pressure_sum * slope;
      double factor_b = -mass[a] * pressure_sum * slope;
      if (anti_clump_kernel != nullptr) {
        const double inverse_sum = inverse_density_squared[a] + inverse_density_squared[b];
        const double anti_clump_slope = anti_clump_kernel->derivative_over_r(r);
        factor_a -= mass[b] * anti_clump_pressure * inverse_sum * anti_clump_slope;
        factor_b -= mass[a] * anti_clump_pressure * inverse_sum * anti_clump_slope;
      }
      for (int k = 0; k < D; ++k) {
        own[k].add(factor_a * d[k]);
        sums[k].add(b, factor_b * -d[k]);
      }
    }
    if (carrier_of_slot[a] < fluid_count) {
      for (const std::uint32_t w : wall_neighbours.of(a)) {
        std::array<double, D> d{};
        const double r_squared = squared_distance<D>(x, a, wall_x, w, d);
        const double factor = wall.acceleration_over_distance(r_squared);
        for (int k = 0; k < D; ++k) {
          own[k].add(factor * d[k]);
        }
      }
    }
    for (int k = 0; k < D; ++k) {
      sums[k].add_sum(a, own[k]);
    }
  });
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    if (carrier_of_slot[a] >= fluid_count) {
      continue;
    }
    sums[D - 1].add(a, -gravity);
    for (int k = 0; k < D; ++k) {
      if (!sums[k].try_value(a, acceleration[k][carrier_of_slot[a]])) {
        faults.record(carrier_of_slot[a], "fluid", "acceleration",
                      "fixed-point overflow or non-finite force");
      }
    }
  }
}

// App. A Shepard filter of the fluid velocity, u~_a = sum_b V_b u_b w_ab / sum_b V_b w_ab over
// fluid b (including b = a), V_b = m_b / rho_b; in double (a diagnostic, or the irreversible
// active filter). Slot-indexed like the loops above; dummy slots get no value.
template <int D>
void shepard_filter(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                    std::span<const double> mass, std::span<const double> density,
                    const std::array<std::vector<double>, D>& velocity, const HalfPairList& pairs,
                    std::span<const std::uint32_t> carrier_of_slot, std::size_t fluid_count,
                    std::array<std::vector<double>, D>& filtered) {
  const std::size_t n = mass.size();
  const double self_weight = kernel.value(0.0);
  std::vector<double> weight(n, 0.0);
  for (int k = 0; k < D; ++k) {
    filtered[k].assign(n, 0.0);
  }
  auto is_fluid = [&](std::uint32_t slot) { return carrier_of_slot[slot] < fluid_count; };
  for (std::size_t a = 0; a < n; ++a) {
    if (is_fluid(static_cast<std::uint32_t>(a))) {
      weight[a] = mass[a] / density[a] * self_weight;
      for (int k = 0; k < D; ++k) {
        filtered[k][a] = weight[a] * velocity[k][a];
      }
    }
  }
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    if (!is_fluid(a)) {
      return;
    }
    for (const std::uint32_t b : partners) {
      if (!is_fluid(b)) {
        continue;
      }
      const double r_squared = squared_distance<D>(x, a, b);
      const double w = kernel.value(std::sqrt(r_squared));
      const double to_a = mass[b] / density[b] * w;
      const double to_b = mass[a] / density[a] * w;
      weight[a] += to_a;
      weight[b] += to_b;
      for (int k = 0; k < D; ++k) {
        filtered[k][a] += to_a * velocity[k][b];
        filtered[k][b] += to_b * velocity[k][a];
      }
    }
  });
  for (std::size_t a = 0; a < n; ++a) {
    if (is_fluid(static_cast<std::uint32_t>(a))) {
      for (int k = 0; k < D; ++k) {
        filtered[k][a] /= weight[a];
      }
    }
  }
}

} // namespace revsph::wcsph
