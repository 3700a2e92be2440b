#pragma once
// Monaghan's artificial viscosity as a pair term of core's one pair loop (core/pair_sum.hpp): the
// optional irreversible operator of the WCSPH model (artificial_viscosity.cpp), not part of
// paper 1. Monaghan, Annu. Rev. Astron. Astrophys. 30 (1992) 543, and Rep. Prog. Phys. 68 (2005)
// 1703, with the linear term only (beta = 0):
//   dv_a/dt = -sum_b m_b Pi_ab grad_a W_ab,
//   Pi_ab = -alpha c h mu_ab / rho_ab,   mu_ab = v_ab . x_ab / (r_ab^2 + eps h^2),   eps = 0.01,
// for approaching pairs (v_ab . x_ab < 0), else Pi_ab = 0; rho_ab = (rho_a + rho_b) / 2, c the
// constant sound speed of the Tait equation. h is Monaghan's smoothing length, half the support
// radius of the Wendland kernel (his kernels reach 2h), so that alpha means what it means in the
// literature's dam breaks.
//
// Over a time tau the term is the velocity increment tau dv/dt, summed at the velocity's scale.
// Pi_ab = Pi_ba and grad_b W_ba = -grad_a W_ab: the increment b receives is computed from the
// same product with its own mass factor, the exact negative of a's for equal masses, so the
// fluid's momentum is exact in integers (dummy partners take their share away: they stay at
// rest). The kinetic energy changes by -tau sum_pairs m_a m_b Pi_ab v_ab . grad_a W_ab <= 0 to
// first order in tau (w' < 0 and v_ab . x_ab < 0 where Pi_ab > 0).
//
// Carriers are the fluid and the dummy particles; dummies (App. A walls) have zero velocity and
// take part as partners, so fluid approaching a dummy wall is damped too; they receive nothing.
// The wall particles of eq. (7) are not carriers: that wall stays conservative and frictionless.

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

namespace revsph::wcsph {

template <int D>
struct ArtificialViscosityTerm {
  static constexpr int width = D;
  static constexpr double epsilon = 0.01; // eps of mu_ab: keeps it finite as r_ab -> 0
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  std::span<const double> density;
  const std::array<std::vector<double>, D>& velocity; // by slot; zero for dummies
  SlotInSet fluid;
  double alpha;
  double sound_speed;
  double smoothing_length; // Monaghan's h: the support radius / 2
  double tau;

  // Filled from the fluid's own velocities: a distributed run copies the ghosts' in.
  auto slot_inputs() const { return std::tie(velocity); }
  bool receives(std::uint32_t s) const { return fluid(s); }
  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    double approach = 0.0; // v_ab . x_ab
    for (int k = 0; k < D; ++k) {
      approach += (velocity[k][p.a] - velocity[k][p.b]) * p.x_ab[k];
    }
    if (!(approach < 0.0) || (!fluid(p.a) && !fluid(p.b))) {
      to_a.fill(0.0);
      to_b.fill(0.0);
      return;
    }
    const double h = smoothing_length;
    const double mu = h * approach / (p.r_squared + epsilon * h * h);
    const double pi = -alpha * sound_speed * mu / (0.5 * (density[p.a] + density[p.b]));
    // tau Pi_ab w'(r) / r: grad_a W_ab = (w'(r) / r) x_ab.
    const double common = tau * pi * kernel.derivative_over_r(p.r);
    const double factor_a = -mass[p.b] * common;
    const double factor_b = -mass[p.a] * common;
    for (int k = 0; k < D; ++k) {
      to_a[k] = factor_a * p.x_ab[k];
      to_b[k] = factor_b * -p.x_ab[k];
    }
  }
};

} // namespace revsph::wcsph
