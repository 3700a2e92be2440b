#pragma once
// The position-only pair terms of the two-fluid model (paper 5), run by core's one pair loop
// (core/pair_sum.hpp): the number density (36) and the kick's impulses (pressure 26 / 37-38 /
// variational, thermomechanical 27-28, spin 40, gravity). Arrays are indexed by slot (every
// particle, walls included, in cell order).

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "models/two_fluid/parameters.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <tuple>

namespace revsph::two_fluid {

// Eq. (36) without the mass: n_i = sum_j W_ij (j = i included), so that rho_i = m_i n_i and the
// particle's volume is V_i = 1 / n_i.
template <int D>
struct NumberDensityTerm {
  static constexpr int width = 1;
  const WendlandQuintic<D>& kernel;

  void pair(const PairGeometry<D>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    to_a[0] = to_b[0] = kernel.value(p.r);
  }
  template <class Add>
  void self(std::uint32_t, Add& add) const {
    add(0, kernel.value(0.0));
  }
};

// Per-slot inputs of the impulses, from the number density.
struct ImpulseInputs {
  std::vector<double> mass;             // m
  std::vector<double> volume;           // V = 1 / n
  std::vector<double> phase_volume;     // V_k = V rho / rho_k, interpenetrating phases (else V)
  std::vector<double> density;          // rho = m n
  std::vector<double> pressure;         // Tait + background
  std::vector<double> temperature_term; // T / rho^2
  std::vector<double> thermomechanical; // theta' = rho sigma, times -rho_s / rho_n if normal
  std::vector<double> spin;             // omega (about z; 2D)
  SlotInSet viscous;                    // normal and wall particles: the spin term's pairs
  SlotInSet moves;                      // not walls: they receive nothing
};

// The impulse tau f_ab of one pair, rounded once per particle at the momentum scale:
//   pressure   f_a = -Phi_ab grad_a W_ab, f_b = -f_a, with Phi_ab
//                hu_adams (37-38): (V_a^2 + V_b^2) (rho_a p_b + rho_b p_a) / (rho_a + rho_b)
//                standard (26):    m_a m_b (p_a / rho_a^2 + p_b / rho_b^2)
//                variational:      V_a^2 p_a + V_b^2 p_b
//   thermomechanical (27): f_a = m_a theta'_a m_b (T_a / rho_a^2 + T_b / rho_b^2) grad_a W_ab,
//                or in the difference form f_a = m_a (theta'_a / rho_a) V_b (T_b - T_a) grad_a W_ab
//                (zero for a uniform T, README),
//                f_b likewise with theta'_b (not antisymmetric, README);
//   spin (39-40): f_a = 2 eta_r V_a V_b grad_a W_ab x (omega_a + omega_b) z, f_b = -f_a (V the
//                normal phase's volumes with interpenetrating phases), on
//                normal-normal and normal-wall pairs (it extends the normal fluid's viscosity,
//                sec. IV.2; the superfluid is inviscid);
//   gravity: -tau m g along the last axis (self).
// The antisymmetric parts are summed before the rounding, so b's share is the exact negative of
// a's where the thermomechanical term is off.
template <int D, bool Accounted = false>
struct ImpulseTerm {
  // Accounted: components D..2D-1 carry the thermomechanical and spin impulses alone, whose work
  // the model counts (they are no gradient of an energy it knows).
  static constexpr int width = Accounted ? 2 * D : D;
  const WendlandQuintic<D>& kernel;
  const ImpulseInputs& in;
  PressureForm form;
  double rotational_viscosity;
  double gravity;
  double tau;
  bool thermomechanical_on;
  bool spin_on;
  bool thermomechanical_difference = false;
  std::span<const double> temperature = {}; // T by slot, for the difference form
  // The per-slot inputs pair() reads at a partner: a distributed run copies the ghosts' from
  // their owners (core/pair_sum.hpp; those a per-slot sum made are there already, the rest the
  // model fills from own particles' state).
  auto slot_inputs() const {
    return std::tie(in.mass, in.volume, in.phase_volume, in.density, in.pressure,
                    in.temperature_term, in.thermomechanical, in.spin, temperature);
  }
  // Rigid walls (rigid_walls.hpp) take their impulses too, never applied: the model counts the
  // work the turning walls do on the fluid through them.
  bool walls_receive = false;

  bool receives(std::uint32_t s) const { return in.moves(s) || walls_receive; }

  double pressure_factor(std::uint32_t a, std::uint32_t b) const {
    switch (form) {
    case PressureForm::hu_adams: {
      const double reduced = (in.density[a] * in.pressure[b] + in.density[b] * in.pressure[a]) /
                             (in.density[a] + in.density[b]);
      return (in.volume[a] * in.volume[a] + in.volume[b] * in.volume[b]) * reduced;
    }
    case PressureForm::standard:
      return in.mass[a] * in.mass[b] *
             (in.pressure[a] / (in.density[a] * in.density[a]) +
              in.pressure[b] / (in.density[b] * in.density[b]));
    case PressureForm::variational:
      return in.volume[a] * in.volume[a] * in.pressure[a] +
             in.volume[b] * in.volume[b] * in.pressure[b];
    }
    return 0.0;
  }

  void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
            std::array<double, width>& to_b) const {
    const std::uint32_t a = p.a;
    const std::uint32_t b = p.b;
    // grad_a W_ab = (W'(r) / r) x_ab, finite for coincident particles.
    const double slope = tau * kernel.derivative_over_r(p.r);
    std::array<double, D> gradient{};
    for (int k = 0; k < D; ++k) {
      gradient[k] = slope * p.x_ab[k];
    }
    const double phi = pressure_factor(a, b);
    for (int k = 0; k < D; ++k) {
      to_a[k] = -phi * gradient[k];
    }
    std::array<double, D> other_a{}, other_b{};
    if (spin_on && in.viscous(a) && in.viscous(b)) {
      const double factor = 2.0 * rotational_viscosity * in.phase_volume[a] * in.phase_volume[b] *
                            (in.spin[a] + in.spin[b]);
      if constexpr (D == 2) {
        other_a[0] = factor * gradient[1]; // grad W x omega z = (g_y, -g_x) omega
        other_a[1] = -factor * gradient[0];
        to_a[0] += other_a[0];
        to_a[1] += other_a[1];
      }
    }
    for (int k = 0; k < D; ++k) {
      to_b[k] = -to_a[k];
      other_b[k] = -other_a[k];
    }
    if (thermomechanical_on) {
      double on_a = 0.0, on_b = 0.0;
      if (thermomechanical_difference) {
        const double rise = temperature[b] - temperature[a];
        on_a = in.mass[a] * in.thermomechanical[a] / in.density[a] * in.volume[b] * rise;
        on_b = in.mass[b] * in.thermomechanical[b] / in.density[b] * in.volume[a] * rise;
      } else {
        const double pair_factor =
            in.mass[a] * in.mass[b] * (in.temperature_term[a] + in.temperature_term[b]);
        on_a = pair_factor * in.thermomechanical[a];
        on_b = -pair_factor * in.thermomechanical[b]; // grad_b W_ba = -grad_a W_ab
      }
      for (int k = 0; k < D; ++k) {
        to_a[k] += on_a * gradient[k];
        to_b[k] += on_b * gradient[k];
        other_a[k] += on_a * gradient[k];
        other_b[k] += on_b * gradient[k];
      }
    }
    if constexpr (Accounted) {
      for (int k = 0; k < D; ++k) {
        to_a[D + k] = other_a[k];
        to_b[D + k] = other_b[k];
      }
    }
  }

  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    if (gravity != 0.0 && in.moves(s)) {
      add(D - 1, -tau * in.mass[s] * gravity);
    }
  }
};

} // namespace revsph::two_fluid
