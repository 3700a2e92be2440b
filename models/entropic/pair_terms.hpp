#pragma once
// The pair terms of entropic SPH (paper 4), run by core's one pair loop (core/pair_sum.hpp).
// Every array a term holds is indexed by slot (the gas particles in cell order).

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/wall_potential.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace revsph::entropic {

// Eq. (32a), rho_a = sum_b m_b W_ab with b = a included and no integration constant (unlike
// paper 1's eq. 5): core's SummationDensityTerm without constants.

// The three kernel sums the other particle volumes need (the sums include b = a):
//   sum_b m_b W_ab (28a, 32a), sum_b S_b W_ab (28b, 36a), sum_b W_ab (39).
template <int D>
struct KernelSumsTerm {
  static constexpr int width = 3;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  std::span<const double> entropy;

  void pair(const PairGeometry<D>& p, std::array<double, 3>& to_a,
            std::array<double, 3>& to_b) const {
    const double w = kernel.value(p.r);
    to_a = {mass[p.b] * w, entropy[p.b] * w, w};
    to_b = {mass[p.a] * w, entropy[p.a] * w, w};
  }
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    const double w = kernel.value(0.0);
    add(0, mass[s] * w);
    add(1, entropy[s] * w);
    add(2, w);
  }
};

// The momentum a kick of length dt gives, in pair impulses. Every particle volume's reversible
// force is a pair sum f_ab = -Phi_ab W'_ab e_ab with Phi_ab = Phi_ba (digest of §4):
//   mass     (34c)  Phi = m_a m_b (p_a / rho_a^2 + p_b / rho_b^2):  alpha = m p / rho^2, beta = m
//   entropic (38b)  Phi = S_a S_b (p_a / s_a^2 + p_b / s_b^2):      alpha = S p / s^2,   beta = S
//   direct   (42c)  Phi = p_a V_a^2 + p_b V_b^2:                    alpha = p V^2,       beta = 1
//   implicit (45b)  Phi = y_a V_b + y_b V_a (W y = p):              alpha = y,           beta = V
//   mixed    (47c)  Phi = m_b A_a + m_a A_b + S_b B_a + S_a B_b:    alpha = A, beta = m,
//                                                                   gamma = B, delta = S
// so Phi_ab = alpha_a beta_b + alpha_b beta_a (+ gamma_a delta_b + gamma_b delta_a). The impulse
// dt f_ab is rounded once (to the momentum scale) and b receives its exact negative: internal
// forces change the total momentum by exactly zero. Walls (paper 1 eq. 7) and gravity act on
// each particle one-sidedly.
template <int D>
struct ImpulseTerm {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  double dt;
  std::span<const double> mass;
  std::span<const double> alpha, beta;
  std::span<const double> gamma, delta; // empty but for the mixed volume
  WallPotential wall;
  double gravity;
  // The Boussinesq body force m g (T - T0) / T0 instead of m g downwards (physics.buoyancy):
  // by slot, empty for "density".
  std::span<const double> temperature;
  double reference_temperature = 0.0;

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    double phi = alpha[p.a] * beta[p.b] + alpha[p.b] * beta[p.a];
    if (!gamma.empty()) {
      phi += gamma[p.a] * delta[p.b] + gamma[p.b] * delta[p.a];
    }
    // W'_ab e_ab = (W'(r) / r) x_ab: finite for coincident particles.
    const double factor = -dt * phi * kernel.derivative_over_r(p.r);
    for (int k = 0; k < D; ++k) {
      to_a[k] = factor * p.x_ab[k];
      to_b[k] = -to_a[k];
    }
  }
  // Paper 1 eq. (7): wall particle w pushes gas particle a.
  void cross_pair(const PairGeometry<D>& p, std::array<double, D>& to_a) const {
    const double factor = dt * mass[p.a] * wall.acceleration_over_distance(p.r_squared);
    for (int k = 0; k < D; ++k) {
      to_a[k] = factor * p.x_ab[k];
    }
  }
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    if (gravity == 0.0) {
      return;
    }
    if (temperature.empty()) {
      add(D - 1, -dt * mass[s] * gravity);
    } else {
      add(D - 1, dt * mass[s] * gravity * (temperature[s] - reference_temperature) /
                     reference_temperature);
    }
  }
};

} // namespace revsph::entropic
