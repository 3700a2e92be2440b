#pragma once
// The pair terms of symplectic WCSPH (paper 1), run by core's one pair loop (core/pair_sum.hpp):
// density (eq. 5), acceleration (eq. 1b + the anti-clump force of App. A + the wall force of
// eq. 7 + gravity), the wall energy (eq. 7) and the Shepard filter (App. A).
//
// Density carriers are the fluid and the dummy particles (App. A walls): both have a density and
// a pressure; only fluid particles move. Every array a term holds is indexed by slot; fluid(s)
// tells whether slot s holds a fluid particle (SlotLayout::in). The term b receives from a pair is computed as if
// b were the query (its own mass factor, x_b - x_a = -(x_a - x_b) exactly), so the sums equal
// those of a per-particle loop; for equal masses it is the exact negative of a's term, so
// internal forces conserve momentum in integers.

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/summation_density.hpp"
#include "models/wcsph/equations.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <tuple>

namespace revsph::wcsph {

// Paper 1 eq. (5): rho_a = sum_b m_b w(r_ab) + C_a over carriers b, the sum including b = a.
template <int D, class Arith>
using DensityTerm = SummationDensityTerm<D, Arith>;

// Paper 1 eq. (1b), with the sign that makes it -grad of eq. (3), over carrier neighbours b:
//   a_a = -sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) w'(r_ab) (x_a - x_b) / r_ab
//         - sum_b m_b p0 (1 / rho_a^2 + 1 / rho_b^2) w~'(r_ab) (x_a - x_b) / r_ab   (App. A)
//         + sum_wall F_wall->a / m_a - g e_vertical                               (eq. 7)
// for the fluid slots (the wall particles are cross pairs).
template <int D>
struct AccelerationTerm {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  std::span<const double> pressure_over_density_squared;
  std::span<const double> inverse_density_squared; // with the anti-clump force only
  SlotInSet fluid;
  const WendlandQuintic<D>* anti_clump_kernel; // null without the anti-clump force
  double anti_clump_pressure;
  WallPotential wall;
  double gravity;

  bool receives(std::uint32_t s) const { return fluid(s); }
  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    const double pressure_sum =
        pressure_over_density_squared[p.a] + pressure_over_density_squared[p.b];
    const double slope = kernel.derivative_over_r(p.r);
    double factor_a = -mass[p.b] * pressure_sum * slope;
    double factor_b = -mass[p.a] * pressure_sum * slope;
    if (anti_clump_kernel != nullptr) {
      const double inverse_sum = inverse_density_squared[p.a] + inverse_density_squared[p.b];
      const double anti_clump_slope = anti_clump_kernel->derivative_over_r(p.r);
      factor_a -= mass[p.b] * anti_clump_pressure * inverse_sum * anti_clump_slope;
      factor_b -= mass[p.a] * anti_clump_pressure * inverse_sum * anti_clump_slope;
    }
    for (int k = 0; k < D; ++k) {
      to_a[k] = factor_a * p.x_ab[k];
      to_b[k] = factor_b * -p.x_ab[k];
    }
  }
  // Eq. (7): the wall particle w pushes fluid particle a.
  void cross_pair(const PairGeometry<D>& p, std::array<double, D>& to_a) const {
    const double factor = wall.acceleration_over_distance(p.r_squared);
    for (int k = 0; k < D; ++k) {
      to_a[k] = factor * p.x_ab[k];
    }
  }
  template <class Add>
  void self(std::uint32_t, Add& add) const {
    add(D - 1, -gravity);
  }
};

// The wall energy of eq. (7): WallEnergyTerm in core/wall_potential.hpp.

// App. A Shepard filter of the fluid velocity, u~_a = sum_b V_b u_b w_ab / sum_b V_b w_ab over
// fluid b (including b = a), V_b = m_b / rho_b: quantity 0 is the denominator, 1..D the
// numerator. Dummy particles take no part.
template <int D>
struct ShepardTerm {
  static constexpr int width = D + 1;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  std::span<const double> density;
  const CoordinateArrays<D>& velocity; // by slot
  SlotInSet fluid;

  // Filled from the fluid's own velocities: a distributed run copies the ghosts' in.
  auto slot_inputs() const { return std::tie(velocity); }
  bool receives(std::uint32_t s) const { return fluid(s); }
  void pair(const PairGeometry<D>& p, std::array<double, D + 1>& to_a,
            std::array<double, D + 1>& to_b) const {
    if (!fluid(p.a) || !fluid(p.b)) {
      to_a.fill(0.0);
      to_b.fill(0.0);
      return;
    }
    const double w = kernel.value(p.r);
    const double weight_a = mass[p.b] / density[p.b] * w;
    const double weight_b = mass[p.a] / density[p.a] * w;
    to_a[0] = weight_a;
    to_b[0] = weight_b;
    for (int k = 0; k < D; ++k) {
      to_a[k + 1] = weight_a * velocity[k][p.b];
      to_b[k + 1] = weight_b * velocity[k][p.a];
    }
  }
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    const double weight = mass[s] / density[s] * kernel.value(0.0);
    add(0, weight);
    for (int k = 0; k < D; ++k) {
      add(k + 1, weight * velocity[k][s]);
    }
  }
};

} // namespace revsph::wcsph
