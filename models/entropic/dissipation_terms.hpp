#pragma once
// The pair terms of the dissipation of entropic SPH (paper 4 §5.1-5.2), run by core's pair loop
// (core/pair_sum.hpp) over the gas slots. Building blocks for every model whose particles carry
// entropy (the superfluid model reuses them): Fourier heat conduction with lambda(T) =
// lambda_F T^2 and the viscous force of eq. (60) with the heat it makes (eq. 63, corrected).

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace revsph::entropic {

// Eq. (54), the first of the two passes of the heat conduction: the heat flux
//   q_a = lambda(T_a) G~0_a(1/T) = -sum_b V_b lambda_F (T_a - T_a^2 / T_b) W'_ab e_ab,
// with W'_ab e_ab = (W'(r) / r) x_ab.
template <int D>
struct HeatFluxTerm {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  double conductivity; // lambda_F
  std::span<const double> volume;
  std::span<const double> temperature;
  std::span<const std::uint8_t> conducting; // by slot; pairs with another particle add nothing

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    if (!conducting[p.a] || !conducting[p.b]) {
      to_a.fill(0.0);
      to_b.fill(0.0);
      return;
    }
    const double slope = kernel.derivative_over_r(p.r);
    const double t_a = temperature[p.a];
    const double t_b = temperature[p.b];
    const double factor_a = -volume[p.b] * conductivity * (t_a - t_a * t_a / t_b) * slope;
    const double factor_b = -volume[p.a] * conductivity * (t_b - t_b * t_b / t_a) * slope;
    for (int k = 0; k < D; ++k) {
      to_a[k] = factor_a * p.x_ab[k];
      to_b[k] = -factor_b * p.x_ab[k]; // x_ba = -x_ab
    }
  }
};

// The second pass over time tau: per pair, the momentum impulses of the viscous force (60) and
// the heat each particle receives, quantity D:
//   conduction (53)-(56): Q_ab = -V_a V_b (q_a + q_b) . W'_ab e_ab to a, -Q_ab to b (exactly
//     antisymmetric: the heat leaves b as it enters a);
//   viscosity (60): f_ab = 2 (n + 2) mu V_a V_b (v_ab . x_ab) / r2 (W'/r) x_ab on a, -f_ab on b,
//     and its power P_ab = -2 (n + 2) mu V_a V_b (v_ab . x_ab)^2 / r2 (W'/r) >= 0 as heat, half
//     to each particle: eq. (63) with W' in place of its W (the printed W gives the wrong sign
//     and no energy balance, derivations.md §4.3).
// r2 = r^2 + 0.01 h^2: the regularisation of the authors' code (the paper leaves r -> 0 open),
// the same in the force and in the heat, so that the heat is exactly the force's power.
template <int D>
struct DissipationTerm {
  static constexpr int width = D + 1;
  const WendlandQuintic<D>& kernel;
  double tau;
  double viscosity;      // mu
  double regularisation; // 0.01 h^2
  std::span<const double> volume;
  const CoordinateArrays<D>& velocity;  // by slot
  const CoordinateArrays<D>& heat_flux; // by slot; empty without conduction
  std::span<const std::uint8_t> active; // by slot: pairs with another particle add nothing
                                        // (dummy particles: adiabatic and free-slip)

  void pair(const PairGeometry<D>& p, std::array<double, D + 1>& to_a,
            std::array<double, D + 1>& to_b) const {
    if (!active[p.a] || !active[p.b]) {
      to_a.fill(0.0);
      to_b.fill(0.0);
      return;
    }
    const double slope = kernel.derivative_over_r(p.r);
    const double volumes = volume[p.a] * volume[p.b];
    double exchanged = 0.0;
    if (!heat_flux[0].empty()) {
      double flux_dot = 0.0;
      for (int k = 0; k < D; ++k) {
        flux_dot += (heat_flux[k][p.a] + heat_flux[k][p.b]) * p.x_ab[k];
      }
      exchanged = -tau * volumes * flux_dot * slope;
    }
    double approach = 0.0; // v_ab . x_ab
    for (int k = 0; k < D; ++k) {
      approach += (velocity[k][p.a] - velocity[k][p.b]) * p.x_ab[k];
    }
    const double viscous =
        2.0 * (D + 2) * viscosity * volumes * approach / (p.r_squared + regularisation) * slope;
    const double half_heat = -0.5 * tau * viscous * approach;
    for (int k = 0; k < D; ++k) {
      to_a[k] = tau * viscous * p.x_ab[k];
      to_b[k] = -to_a[k];
    }
    to_a[D] = exchanged + half_heat;
    to_b[D] = -exchanged + half_heat;
  }
};

} // namespace revsph::entropic
