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
// them. So do wall particles, unless they absorb (physics.cooler = "absorbing", the authors'
// fountain code): then a fluid-wall pair is a fluid-fluid pair whose wall side has s = s0,
// T = T0, v its own velocity and its own v_s. The wall's v and s receive nothing; its v_s
// receives the thermomechanical force alone, -m_b (w'/r) (s0 / rho_a) T_ab x_ab: the fountain
// pressure that drives the superflow into the cooler. The authors' code gives it what a fluid
// particle would receive on v_s less what it would receive on v, which adds the counterflow
// terms (v_n,ab . u_a) / rho_a - (chi_s/chi_n) u (u . x_ab) / rho, quadratic in the wall's own
// v_s; over a wall particle's support (fluid on one side, a fixed lattice on the other) they do
// not cancel as they do inside the fluid, and push its v_s on ever faster (dv_s/dt ~ v_s^2): the
// fountain at d/6 overflowed at t = 0.205 s that way, with or without the wall-wall pairs, while
// with the thermomechanical force alone it runs (README, "Fountain").
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
#include <tuple>

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
  SlotInSet is_fluid;
  // The slots that interact as fluid: the fluid's, and the absorbing walls' (else is_fluid).
  SlotInSet interacts;
  const RateInputs<D>& in;
  double tau; // the sub-step's length
  // What fill_rate_inputs computes from own particles' state (the rest follows from per-slot
  // sums): a distributed run copies the ghosts' in (core/pair_sum.hpp).
  auto slot_inputs() const {
    return std::tie(in.flux_factor, in.entropy_over_density, in.temperature, in.relative,
                    in.entropy_flux, in.normal_velocity);
  }
  double gravity; // g along minus the last axis, on v and v_s (eq. 29)
  // chi_s = 0 everywhere (chi_n0 = 1, chi' = 0): v_s then enters nothing, and its own equation
  // amplifies u = v - v_s without bound in a shear flow (the classical cavity overflowed at step
  // 94 708); it is held at its initial value.
  bool classical = false;

  bool receives(std::uint32_t s) const { return interacts(s); }

  // Gravity (eq. 29): the same increment for every fluid particle, even under time reversal (a
  // wall's holding force cancels it on v and so on v_s).
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    if (gravity != 0.0 && is_fluid(s)) {
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
    if (!interacts(a) || !interacts(b)) {
      // A dummy neighbour: the pressure force only (only the fluid one receives).
      std::array<double, width>& to = is_fluid(a) ? to_a : to_b;
      const double sign = is_fluid(a) ? 1.0 : -1.0;
      const double factor = -(is_fluid(a) ? mass[b] : mass[a]) * slope * pressure * sign;
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
    if (!is_fluid(a)) {
      hold(to_a, -m_b_slope * in.entropy_over_density[a] * temperature_ab, p.x_ab);
    } else if (!is_fluid(b)) {
      hold(to_b, -m_a_slope * in.entropy_over_density[b] * temperature_ab, p.x_ab);
    }
  }

  // An absorbing wall's share: v held, s held at s0, v_s driven by the thermomechanical force.
  void hold(std::array<double, width>& to_wall, double thermomechanical, const Vec<D>& x_ab) const {
    for (int k = 0; k < D; ++k) {
      to_wall[D + k] = thermomechanical * x_ab[k];
      to_wall[k] = 0.0;
    }
    to_wall[2 * D] = 0.0;
  }
};

// The energy (15) an absorbing wall's pair gives its fluid particle f in one sub-step, to first
// order in tau: m_f (v_n . dv - (chi_s / chi_n) u . dv_s + T ds) with de/dv = v_n, de/dv_s =
// -(chi_s / chi_n) u, de/ds = T at fixed rho (App. B), less the pressure part, whose work is the
// compressional energy's change (the walls are static). Quantity 0, fluid slots only.
template <int D>
struct WallWorkTerm {
  static constexpr int width = 1;
  RateTerm<D> rate;

  auto slot_inputs() const { return rate.slot_inputs(); }
  bool receives(std::uint32_t s) const { return rate.is_fluid(s); }

  void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
            std::array<double, width>& to_b) const {
    std::array<double, RateTerm<D>::width> increment_a;
    std::array<double, RateTerm<D>::width> increment_b;
    rate.pair(p, increment_a, increment_b);
    const bool a_is_fluid = rate.is_fluid(p.a);
    const std::uint32_t f = a_is_fluid ? p.a : p.b;
    const std::uint32_t w = a_is_fluid ? p.b : p.a;
    const std::array<double, RateTerm<D>::width>& d = a_is_fluid ? increment_a : increment_b;
    const RateInputs<D>& in = rate.in;
    const double sign = a_is_fluid ? 1.0 : -1.0; // x_fw = sign x_ab
    const double pressure_part =
        -rate.mass[w] * rate.tau * rate.kernel.derivative_over_r(p.r) *
        (in.pressure_over_density_squared[p.a] + in.pressure_over_density_squared[p.b]);
    const double ratio = in.flux_factor[f] / in.inverse_density[f]; // chi_s / chi_n
    double work = in.temperature[f] * d[2 * D];
    for (int k = 0; k < D; ++k) {
      const double u = in.relative[k][f];
      const double v_n = in.normal_velocity[k][f];
      const double v = v_n - ratio * u;
      work += v_n * d[k] - ratio * u * d[D + k] - v * pressure_part * sign * p.x_ab[k];
    }
    (a_is_fluid ? to_a : to_b)[0] = rate.mass[f] * work;
    (a_is_fluid ? to_b : to_a)[0] = 0.0;
  }
};

} // namespace revsph::superfluid
