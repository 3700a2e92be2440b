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
#include <tuple>

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
  SlotInSet conducting; // by slot; pairs with another particle add nothing

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    if (!conducting(p.a) || !conducting(p.b)) {
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

// What the dissipation gives the wall particles, mirrored across the wall from the gas near
// them (Adami, Hu and Adams 2012 do the same for the pressure and the no-slip velocity):
//   a thermal wall's temperature T_b = 2 T_w - T~_b, and
//   a no-slip wall particle's velocity v_b = 0 - v~_b,
// with T~_b, v~_b the kernel-weighted means over the gas near b. Walls at a flat T_w (or at
// rest) put a flat profile where the gas's slope should continue: the measured conduction across
// the cavity then falls short by 6 % (pairwise) or 11 % (two-pass) at 40 particles across (4.5 %
// and 3.0 % mirrored, README), and the drag of a wall reaches a kernel radius into the gas. This
// pass sums W_ab T_a, W_ab v_a and W_ab from the gas onto the wall particles.
template <int D>
struct WallMirrorTerm {
  static constexpr int width = D + 2;
  const WendlandQuintic<D>& kernel;
  std::span<const double> temperature; // by slot
  const CoordinateArrays<D>& velocity; // by slot
  SlotInSet gas;                       // by slot
  // Filled from the gas's own momenta: a distributed run copies the ghosts' (core/pair_sum.hpp).
  auto slot_inputs() const { return std::tie(velocity); }

  void pair(const PairGeometry<D>& p, std::array<double, D + 2>& to_a,
            std::array<double, D + 2>& to_b) const {
    to_a.fill(0.0);
    to_b.fill(0.0);
    if (gas(p.a) == gas(p.b)) {
      return;
    }
    const double w = kernel.value(p.r);
    const std::uint32_t from = gas(p.a) ? p.a : p.b;
    std::array<double, D + 2>& onto = gas(p.a) ? to_b : to_a;
    onto[0] = w * temperature[from];
    for (int k = 0; k < D; ++k) {
      onto[1 + k] = w * velocity[k][from];
    }
    onto[D + 1] = w;
  }
};

// The second pass over time tau: per pair, the momentum impulses of the viscous force (60) and
// the heat each particle receives, quantity D:
//   conduction (53)-(56): Q_ab = -V_a V_b (q_a + q_b) . W'_ab e_ab to a, -Q_ab to b (exactly
//     antisymmetric: the heat leaves b as it enters a), between conducting particles (the gas
//     and the thermal walls);
//   viscosity (60): f_ab = 2 (n + 2) mu V_a V_b (v_ab . x_ab) / r2 (W'/r) x_ab on a, -f_ab on b,
//     and its power P_ab = -2 (n + 2) mu V_a V_b (v_ab . x_ab)^2 / r2 (W'/r) >= 0 as heat, half
//     to each particle: eq. (63) with W' in place of its W (the printed W gives the wrong sign
//     and no energy balance, derivations.md §4.3). Between gas particles, and between the gas
//     and the wall particles (at their mirrored velocities) when the walls are no-slip; the
//     heat of a wall pair is the kinetic energy the gas particle lost.
// r2 = r^2 + 0.01 h^2: the regularisation of the authors' code (the paper leaves r -> 0 open),
// the same in the force and in the heat, so that the heat is exactly the force's power.
template <int D>
struct DissipationTerm {
  static constexpr int width = D + 1;
  const WendlandQuintic<D>& kernel;
  double tau;
  double viscosity;      // mu
  double regularisation; // 0.01 h^2
  bool no_slip_walls;
  std::span<const double> volume;
  const CoordinateArrays<D>& velocity;  // by slot; mirrored on no-slip walls
  const CoordinateArrays<D>& heat_flux; // by slot; empty without the two-pass conduction
  SlotInSet gas;                        // by slot
  SlotInSet conducting;                 // by slot
  // The pairwise conduction instead (physics.heat_conduction = "pairwise", lambda_F; else 0):
  //   Q_ab = 2 tau lambda_F V_a V_b (W'/r) (T_a - T_b) to a (Brookshaw's Laplacian; Cleary and
  //   Monaghan 1999), = tau kappa_ab T_a T_b (1/T_a - 1/T_b) with kappa_ab = -2 lambda_F V_a V_b
  //   W'/r >= 0: the gradient dynamics of a pair potential, so it makes entropy,
  //   Q_ab (1/T_a - 1/T_b) >= 0, and with lambda(T) = lambda_F T^2 it is Fourier's law with
  //   conductivity lambda_F, as eq. (54) is. One pass: a wall held at T_w acts at its surface.
  double pairwise_conductivity;
  std::span<const double> temperature; // by slot, for the pairwise conduction
  // The gas's velocities are filled from its own momenta (the rest from per-slot sums, which a
  // distributed run already has on its ghosts).
  auto slot_inputs() const { return std::tie(velocity); }

  void pair(const PairGeometry<D>& p, std::array<double, D + 1>& to_a,
            std::array<double, D + 1>& to_b) const {
    to_a.fill(0.0);
    to_b.fill(0.0);
    const bool both_gas = gas(p.a) && gas(p.b);
    if (!gas(p.a) && !gas(p.b)) {
      return;
    }
    const double slope = kernel.derivative_over_r(p.r);
    const double volumes = volume[p.a] * volume[p.b];
    double exchanged = 0.0;
    if (!heat_flux[0].empty() && conducting(p.a) && conducting(p.b)) {
      double flux_dot = 0.0;
      for (int k = 0; k < D; ++k) {
        flux_dot += (heat_flux[k][p.a] + heat_flux[k][p.b]) * p.x_ab[k];
      }
      exchanged = -tau * volumes * flux_dot * slope;
    } else if (pairwise_conductivity > 0.0 && conducting(p.a) && conducting(p.b)) {
      exchanged = 2.0 * tau * pairwise_conductivity * volumes * slope *
                  (temperature[p.a] - temperature[p.b]);
    }
    to_a[D] = exchanged;
    to_b[D] = -exchanged;
    if (!both_gas && !no_slip_walls) {
      return;
    }
    double approach = 0.0; // v_ab . x_ab
    for (int k = 0; k < D; ++k) {
      approach += (velocity[k][p.a] - velocity[k][p.b]) * p.x_ab[k];
    }
    const double viscous =
        2.0 * (D + 2) * viscosity * volumes * approach / (p.r_squared + regularisation) * slope;
    for (int k = 0; k < D; ++k) {
      to_a[k] = tau * viscous * p.x_ab[k];
      to_b[k] = -to_a[k];
    }
    if (both_gas) {
      const double heat = -tau * viscous * approach;
      to_a[D] += 0.5 * heat;
      to_b[D] += 0.5 * heat;
      return;
    }
    // A wall pair: the gas particle's heat is the kinetic energy its impulse J takes, -J . v
    // (to first order; the update takes the |J|^2 / 2m): the wall's mirrored velocity moves
    // no energy.
    const std::uint32_t g = gas(p.a) ? p.a : p.b;
    double along = 0.0; // v_g . x_ab
    for (int k = 0; k < D; ++k) {
      along += velocity[k][g] * p.x_ab[k];
    }
    if (gas(p.a)) {
      to_a[D] -= tau * viscous * along;
    } else {
      to_b[D] += tau * viscous * along;
    }
  }
};

} // namespace revsph::entropic
