#pragma once
// The irreversible pair terms of paper 3 (eqs. 19, 23, B27-B28) over one sub-step tau, from the
// mean of the two copies, run by core's pair loop: quantities 0..D-1 sum the velocity increments
// (at the velocity's scale), quantity D the heat each particle receives (energy).
//
// Normal-fluid viscosity, Monaghan's form (B22), on the coflow velocity v, with the difference of
// the normal velocities:
//   dv_a/dt = sum_b m_b (w'_ab / r_ab) 2 (d + 2) mu / (rho_a rho_b)
//             (v_n,ab . x_ab) / (r_ab^2 + eta^2) x_ab,     eta = h / 10 (h: the support radius)
// a's and b's increments are m_b c x_ab and -m_a c x_ab: momentum is kept exactly for equal
// masses. The pair's dissipated power (B24), -m_a m_b c (v_n,ab . x_ab) / tau >= 0, heats a and b
// by half each (B28 splits it so: each particle's zeta carries its half).
//
// Heat conduction (B21, B23, B27-B28): ds_a/dt = (beta / rho_a) {Delta T}_a + zeta_a / (T_a rho_a)
// with zeta's conduction part beta {|grad T|^2}_a. Multiplied by m_a T_a it is the pairwise heat
//   Q_a<-b = beta m_a m_b (w'_ab / r_ab) (T_a^2 - T_b^2) / (rho_a rho_b)  (= -Q_b<-a),
// (the Laplacian's 2 T_a T_ab plus the dual's -T_ab^2 is T_a^2 - T_b^2): heat flows from hot
// to cold (w' <= 0), so energy is kept and entropy grows.
//
// Dummy particles take no part (adiabatic, free-slip walls), or, with no_slip_dummies, drag the
// normal fluid toward rest through the viscosity alone (adiabatic no-slip glass, as the authors'
// fountain code has it): the whole dissipated power then heats the fluid particle, since
// de/dv = v_n at fixed v_s, s makes its kinetic loss m_a v_n,a . dv_a exactly that power.
// Wall particles (no-slip, cooler) act on the fluid with their own velocity as v_n and T0 as
// temperature: what they give or take is the model's wall_exchange energy. Conducting walls
// receive nothing. Absorbing walls (the authors' cooler, v held, v_s free, v_n = -(chi_s /
// chi_n) v_s) receive the viscous increment with its sign turned, for their v_s: the holding
// force that keeps v takes it out of v_s too, as in the authors' fountain_2d.jl (the cooler's
// v_s gains dt (a_s - a), a holding the viscous force): a drag on the wall's v_s.

#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <tuple>

namespace revsph::superfluid {

template <int D>
struct DissipationTerm {
  static constexpr int width = D + 1;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  SlotInSet fluid, dummy, wall; // the slots of each set (SlotLayout::in)
  std::span<const double> inverse_density;
  std::span<const double> temperature;        // of the mean state; T0 on walls
  const CoordinateArrays<D>& normal_velocity; // of the mean state; a wall's own velocity
  double viscosity;                           // mu
  double conductivity;                        // beta
  double eta_squared;
  double tau;
  // +1 / -1: the side of the superleak's mid-plane a slot lies on within its width (0: outside);
  // no heat crosses between the two sides (sec. III.C).
  std::span<const std::int8_t> side;
  // Filled from own particles' state: a distributed run copies the ghosts' in.
  auto slot_inputs() const { return std::tie(inverse_density, temperature, normal_velocity, side); }
  bool no_slip_dummies = false;
  bool absorbing_walls = false;
  bool receives(std::uint32_t s) const { return fluid(s) || (absorbing_walls && wall(s)); }

  void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
            std::array<double, width>& to_b) const {
    to_a.fill(0.0);
    to_b.fill(0.0);
    const bool fluid_a = fluid(p.a);
    const bool fluid_b = fluid(p.b);
    const bool wall_a = wall(p.a);
    // A fluid particle's partner: fluid, a wall, or a no-slip dummy (glass: v_n = 0, adiabatic).
    const bool glass = no_slip_dummies && ((fluid_a && dummy(p.b)) || (dummy(p.a) && fluid_b));
    const bool partners = fluid_a ? !dummy(p.b) : fluid_b && wall_a;
    if (!glass && !partners) {
      return;
    }
    const std::uint32_t a = p.a;
    const std::uint32_t b = p.b;
    const double slope = kernel.derivative_over_r(p.r);
    const double inverse_densities = inverse_density[a] * inverse_density[b];
    double vn_dot_x = 0.0;
    for (int k = 0; k < D; ++k) {
      vn_dot_x += (normal_velocity[k][a] - normal_velocity[k][b]) * p.x_ab[k];
    }
    const double c = tau * 2.0 * (D + 2) * viscosity * slope * inverse_densities * vn_dot_x /
                     (p.r_squared + eta_squared);
    for (int k = 0; k < D; ++k) {
      to_a[k] = mass[b] * c * p.x_ab[k];
      to_b[k] = -mass[a] * c * p.x_ab[k];
    }
    const double dissipated = -mass[a] * mass[b] * c * vn_dot_x;
    if (glass) { // no conduction; the glass receives nothing, so its fluid particle takes it all
      (fluid_a ? to_a : to_b)[D] = dissipated;
      return;
    }
    const double t_a = temperature[a];
    const double t_b = temperature[b];
    const bool cut = side[a] * side[b] < 0;
    const double heat = cut ? 0.0
                            : tau * conductivity * mass[a] * mass[b] * slope * inverse_densities *
                                  (t_a * t_a - t_b * t_b);
    to_a[D] = 0.5 * dissipated + heat;
    to_b[D] = 0.5 * dissipated - heat;
    // Past the test above the pair is fluid-fluid or fluid-wall: the kinds differ where the
    // fluid flags do.
    if (absorbing_walls && fluid_a != fluid_b) { // the wall's share goes to its v_s, turned
      std::array<double, width>& to_wall = wall_a ? to_a : to_b;
      for (int k = 0; k < D; ++k) {
        to_wall[k] = -to_wall[k];
      }
      to_wall[D] = 0.0;
    }
  }
};

} // namespace revsph::superfluid
