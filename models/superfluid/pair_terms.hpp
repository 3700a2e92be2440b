#pragma once
// The reversible rates of paper 3 eq. (19) as one pair term run by core's pair loop
// (core/pair_sum.hpp), as increments over a sub-step tau: quantities 0..D-1 sum tau dv/dt,
// D..2D-1 tau dv_s/dt, 2D tau ds/dt, for the fluid slots, all read from one copy of the state
// (model.hpp). Summed at the state's scales, each pair's share is rounded once; for equal masses
// the shares of v and s that a and b receive are exact negatives, so the update keeps sum m v
// and sum m s bit for bit. With w'_ab = dw/dr (r_ab) and
// x_ab = x_a - x_b (C_a constant, so the density of eq. 24 is a function of the positions):
//   ds_a/dt   = -sum_b m_b (w'_ab / r_ab) (J_a + J_b) . x_ab,   J = j / rho^2 = s chi_s v_ns / rho
//   dv_a/dt   = -sum_b m_b (w'_ab / r_ab) (Pi_a / rho_a^2 + Pi_b / rho_b^2) x_ab
//   dv_s,a/dt = -sum_b m_b (w'_ab / r_ab) [(v_n,ab . u_a) / rho_a + p_a / rho_a^2 + p_b / rho_b^2
//                                          + (s_a / rho_a) T_ab] x_ab
// where u = v - v_s = chi_n v_ns, so chi_n,a v_ns,a / rho_a = u_a / rho_a (eq. 22), and
// Pi / rho^2 = (p / rho^2) I + (chi_s / chi_n) u (x) u / rho (eq. 21).
// Dummy particles (adiabatic walls, sec. III.C) take part in the pressure terms only: no entropy
// flux, no momentum flux of the counterflow, no thermomechanical or v_n-gradient term crosses
// them.
//
// Time reversal: every odd input (v, v_s and with them u, v_n, J) enters the entropy rate
// linearly and the velocity rates in pairs, each as a product with even factors, so negating the
// velocities negates ds/dt and keeps dv/dt and dv_s/dt bit for bit (IEEE negation is exact).

#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace revsph::superfluid {

// Per-slot inputs of the rates, from one copy (fluid slots) and the density (all carriers).
template <int D>
struct RateInputs {
  std::vector<double> pressure_over_density_squared; // p / rho^2, every carrier
  std::vector<double> inverse_density;               // 1 / rho, fluid
  std::vector<double> flux_factor;                   // (chi_s / chi_n) / rho, fluid
  std::vector<double> entropy_over_density;          // s / rho, fluid
  std::vector<double> temperature;                   // T, fluid
  CoordinateArrays<D> relative;                      // u = v - v_s, fluid
  CoordinateArrays<D> entropy_flux;                  // J = s (chi_s / chi_n) u / rho, fluid
  CoordinateArrays<D> normal_velocity;               // v_n = v + (chi_s / chi_n) u, fluid
};

template <int D>
struct RateTerm {
  static constexpr int width = 2 * D + 1;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  std::span<const std::uint8_t> is_fluid;
  const RateInputs<D>& in;
  double tau;     // the sub-step's length
  double gravity; // g along minus the last axis, on v and v_s (eq. 29)
  // chi_s = 0 everywhere (chi_n0 = 1, chi' = 0): v_s then enters nothing, and its own equation
  // amplifies u = v - v_s without bound in a shear flow (the classical cavity overflowed at step
  // 94 708); it is held at its initial value.
  bool classical = false;

  bool receives(std::uint32_t s) const { return is_fluid[s] != 0; }

  // Gravity (eq. 29): the same increment for every particle, even under time reversal.
  template <class Add>
  void self(std::uint32_t, Add& add) const {
    if (gravity != 0.0) {
      add(D - 1, -tau * gravity);
      add(2 * D - 1, classical ? 0.0 : -tau * gravity);
    }
  }

  // The pressure part, shared by v and v_s: -(p_a / rho_a^2 + p_b / rho_b^2) w'/r x_ab.
  void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
            std::array<double, width>& to_b) const {
    const std::uint32_t a = p.a;
    const std::uint32_t b = p.b;
    const double slope = tau * kernel.derivative_over_r(p.r);
    const double pressure =
        in.pressure_over_density_squared[a] + in.pressure_over_density_squared[b];
    to_a.fill(0.0);
    to_b.fill(0.0);
    if (!is_fluid[a] || !is_fluid[b]) {
      // A dummy neighbour: the pressure force only (only the fluid one receives).
      std::array<double, width>& to = is_fluid[a] ? to_a : to_b;
      const double sign = is_fluid[a] ? 1.0 : -1.0;
      const double factor = -(is_fluid[a] ? mass[b] : mass[a]) * slope * pressure * sign;
      for (int k = 0; k < D; ++k) {
        to[k] = factor * p.x_ab[k];
        to[D + k] = classical ? 0.0 : factor * p.x_ab[k];
      }
      return;
    }
    double u_a_dot_x = 0.0;
    double u_b_dot_x = 0.0;
    double flux_dot_x = 0.0;
    double vn_ab_dot_u_a = 0.0;
    double vn_ab_dot_u_b = 0.0;
    for (int k = 0; k < D; ++k) {
      u_a_dot_x += in.relative[k][a] * p.x_ab[k];
      u_b_dot_x += in.relative[k][b] * p.x_ab[k];
      flux_dot_x += (in.entropy_flux[k][a] + in.entropy_flux[k][b]) * p.x_ab[k];
      const double vn_ab = in.normal_velocity[k][a] - in.normal_velocity[k][b];
      vn_ab_dot_u_a += vn_ab * in.relative[k][a];
      vn_ab_dot_u_b += vn_ab * in.relative[k][b];
    }
    const double m_a_slope = mass[a] * slope;
    const double m_b_slope = mass[b] * slope;
    const double temperature_ab = in.temperature[a] - in.temperature[b];
    // Superflow (x_ba = -x_ab for b's share).
    const double superflow_a = -m_b_slope * (vn_ab_dot_u_a * in.inverse_density[a] + pressure +
                                             in.entropy_over_density[a] * temperature_ab);
    const double superflow_b = m_a_slope * (-vn_ab_dot_u_b * in.inverse_density[b] + pressure -
                                            in.entropy_over_density[b] * temperature_ab);
    for (int k = 0; k < D; ++k) {
      // Momentum flux: (p_a/rho_a^2 + p_b/rho_b^2) x_ab + k_a/rho_a u_a (u_a.x_ab) + same for b.
      const double flux = pressure * p.x_ab[k] + in.flux_factor[a] * in.relative[k][a] * u_a_dot_x +
                          in.flux_factor[b] * in.relative[k][b] * u_b_dot_x;
      to_a[k] = -m_b_slope * flux;
      to_b[k] = m_a_slope * flux;
      to_a[D + k] = classical ? 0.0 : superflow_a * p.x_ab[k];
      to_b[D + k] = classical ? 0.0 : superflow_b * p.x_ab[k];
    }
    to_a[2 * D] = -m_b_slope * flux_dot_x;
    to_b[2 * D] = m_a_slope * flux_dot_x;
  }
};

} // namespace revsph::superfluid
