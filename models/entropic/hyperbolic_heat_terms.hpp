#pragma once
// The pair terms of the Lagrangian hyperbolic heat conduction (paper 4 §5.5, eqs. 64-74), run by
// core's pair loop (core/pair_sum.hpp). Each particle carries its entropy S (even) and the
// entropy-flux variable w (odd, eq. 66b) with the energy E_w = c_w sum_a V_a |w_a|^2 (Fig. 13:
// c_w = 0.05), so E_wa = dE/dw_a = 2 c_w V_a w_a and E_Sa = T_a. The reversible part, eq. (68):
//   (68b) w_a' = sum_b V_b (T_a - T_b) W'_ab e_ab            (driven by S and x only)
//   (68a) S_a' = -sum_b V_a V_b (E_wa / V_a + E_wb / V_b) . W'_ab e_ab
//              = -2 c_w sum_b V_a V_b (w_a + w_b) . W'_ab e_ab  (driven by w and x only)
// Each is a shear (one group updated from the others), so a rounded update is undone exactly by
// the same update backwards; the S exchange is odd in w and exactly antisymmetric per pair, so
// sum_a S_a is kept bit for bit. Pairs with a particle that does not conduct add nothing: an
// adiabatic wall. Derivations: models/entropic/derivations.md §5.1 (with the slips of (70a) and
// (72)-(74)).

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <tuple>

namespace revsph::entropic {

// Eq. (68b) over time tau: what w_a and w_b gain from the pair, W'_ab e_ab = (W'(r) / r) x_ab.
// Both gains point along x_ab with the same sign: the pair pushes w down the temperature slope.
template <int D>
struct FluxExchangeTerm {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  double tau;
  std::span<const double> volume;
  std::span<const double> temperature;
  SlotInSet conducting; // by slot

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    if (!conducting(p.a) || !conducting(p.b)) {
      to_a.fill(0.0);
      to_b.fill(0.0);
      return;
    }
    const double common =
        tau * (temperature[p.a] - temperature[p.b]) * kernel.derivative_over_r(p.r);
    for (int k = 0; k < D; ++k) {
      to_a[k] = volume[p.b] * common * p.x_ab[k];
      to_b[k] = volume[p.a] * common * p.x_ab[k];
    }
  }
};

// Eq. (68a) over time tau: the entropy J_ab that b hands to a (a gains J_ab, b loses it).
template <int D>
struct EntropyExchangeTerm {
  static constexpr int width = 1;
  const WendlandQuintic<D>& kernel;
  double tau;
  double flux_energy_coefficient; // c_w
  std::span<const double> volume;
  const CoordinateArrays<D>& flux; // w by slot
  SlotInSet conducting;
  // Filled from the gas's own entropy fluxes.
  auto slot_inputs() const { return std::tie(flux); }

  void pair(const PairGeometry<D>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    if (!conducting(p.a) || !conducting(p.b)) {
      to_a[0] = 0.0;
      to_b[0] = 0.0;
      return;
    }
    double projection = 0.0; // (w_a + w_b) . x_ab
    for (int k = 0; k < D; ++k) {
      projection += (flux[k][p.a] + flux[k][p.b]) * p.x_ab[k];
    }
    to_a[0] = -2.0 * tau * flux_energy_coefficient * volume[p.a] * volume[p.b] * projection *
              kernel.derivative_over_r(p.r);
    to_b[0] = -to_a[0];
  }
};

} // namespace revsph::entropic
