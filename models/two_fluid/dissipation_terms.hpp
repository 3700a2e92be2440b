#pragma once
// The velocity-dependent pair terms of the two-fluid model (paper 5): its irreversible part, run
// by core's one pair loop (core/pair_sum.hpp) in the dissipate sub-step. Arrays are indexed by
// slot (every particle, walls included, in cell order).
//
// Every term is a pair exchange f_a = -K_ab (v_a - v_b) (or its part along x_ab), f_b = -f_a
// with K_ab >= 0, so that total momentum is exact in integers (one rounded impulse, its exact
// negative for the partner) and the pair's energy changes by -K_ab |v_a - v_b|^2 to first
// order. The model counts what the sub-step removed exactly, from the momenta (dissipation.cpp).

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

namespace revsph::two_fluid {

// The denominator of eq. (29): w_a = sum over the normal particles j near a of W_aj, the weight of
// the normal-velocity average a superfluid particle feels. Walls are frozen normal fluid and
// count (sec. V.3: "both normal and superfluid components have frictional forces against the
// normal fluid particles forming the wall").
template <int D>
struct NormalWeightTerm {
  static constexpr int width = 1;
  const WendlandQuintic<D>& kernel;
  SlotInSet superfluid; // SlotLayout::in

  bool receives(std::uint32_t s) const { return superfluid(s); }
  void pair(const PairGeometry<D>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    const double w = kernel.value(p.r);
    to_a[0] = !superfluid(p.b) ? w : 0.0;
    to_b[0] = !superfluid(p.a) ? w : 0.0;
  }
};

// Per-slot inputs of the dissipation.
struct DissipationInputs {
  SlotInSet superfluid, wall;                  // the slots of these sets (SlotLayout::in)
  std::array<std::vector<double>, 3> velocity; // p / m, or the wall's velocity
};

// The two stabilising pair terms of sec. IV.1 for pairs closer than the initial spacing d, both
// acting only on approaching pairs, along n = x_ab / r (parameters.hpp, Contact):
//   collision ([40], Shakibaeinia & Jin 2012): the impulse -(1 + e) mu (v_ab . n) n, mu the
//     reduced mass (the fluid particle's own against a wall), which turns the normal approach
//     of an isolated pair into a separation at e times its speed;
//   Riemann ([41], Zhang, Hu & Adams 2017): the dissipative part of their low-dissipation
//     pair pressure, P_d = beta rho_a rho_b / (rho_a + rho_b) (U_L - U_R), U_L - U_R =
//     -v_ab . n, beta = min(limiter (U_L - U_R), c), in the pair force -2 V_a V_b P_d grad W:
//     K_ab = -2 tau V_a V_b beta rho~ W'(r) >= 0 and the impulse -K_ab (v_ab . n) n.
struct ContactInputs {
  double distance = 0.0; // d; 0: both off
  bool collision = false;
  double restitution = 0.0;
  bool riemann = false;
  double limiter = 0.0;
  double sound_speed = 0.0;
  std::span<const double> mass;
  std::span<const double> density;
};

// The impulses of the dissipate sub-step over tau, and what they dissipate:
//   viscosity (34, times 2: README), normal-normal and normal-wall pairs:
//     K_ab = -2 tau (eta + eta_r) V_a V_b W'(r) / r   (eq. 39's eta_bar + eta_r on the Laplacian;
//     V the normal phase's volumes V rho / rho_n with interpenetrating phases, walls' V)
//     or, in the central form (Monaghan's, README), the impulse -(D + 2) K_ab (v_ab . n) n along
//     n = x_ab / r, which keeps angular momentum (2 (D + 2) sum_b V_b (v_ab . x_ab) x_ab W' / r^3
//     is the Laplacian of a divergence-free v)
//     with the normal-normal pairs' K times N / N_n in a separate phases' mixture whose
//     viscosity is undiluted (normal_pair_factor)
//   mutual friction (29, 35 with the reaction's sign fixed: README), superfluid a - normal or
//   wall b:
//     K_ab = tau C_L V_a W_ab / w_a   (V_a the superfluid phase's volume with interpenetrating
//     phases: the friction per unit volume C_L (v_s - v_n) over the superfluid's share of it;
//     against walls C_L may be held at C_L(0), wall_friction)
//   and the contact terms above.
// Components 0..D-1: the impulse; D: the work the wall did on the fluid particle, f_a . v_wall
// (walls move nothing but give no-slip).
template <int D>
struct DissipationTerm {
  static constexpr int width = D + 1;
  const WendlandQuintic<D>& kernel;
  const DissipationInputs& in;
  std::span<const double> volume;        // V = 1 / n (eq. 36)
  std::span<const double> phase_volume;  // V_k = V rho / rho_k, interpenetrating phases (else V)
  std::span<const double> normal_weight; // w of eq. (29), superfluid slots
  double viscosity;                      // eta + eta_r, Pa s
  // Times the normal-normal (not normal-wall) pairs' viscous coefficient: N / N_n for a separate
  // phases' mixture whose viscosity is undiluted (Model::normal_pair_factor, README), else 1.
  double normal_pair_factor;
  bool central_viscosity; // the central form instead of eq. (34)'s
  double friction;        // C_L of eq. (29) at this time, kg/(m^3 s)
  double wall_friction;   // C_L against wall partners: C_L(t), or C_L(0) (README, "Wall grip")
  ContactInputs contact;
  double tau;

  // The per-slot inputs pair() reads at a partner: a distributed run copies the ghosts' from
  // their owners (core/pair_sum.hpp).
  auto slot_inputs() const {
    return std::tie(in.velocity, volume, phase_volume, normal_weight, contact.mass,
                    contact.density);
  }
  bool receives(std::uint32_t s) const { return !in.wall(s); }

  // K_ab of the exchange along v_a - v_b (eq. 34's viscosity, or the friction), and that of the
  // central viscosity along n.
  std::pair<double, double> coupling(std::uint32_t a, std::uint32_t b, double r) const {
    const bool a_wall = in.wall(a);
    const bool b_wall = in.wall(b);
    const bool a_normal = !in.superfluid(a); // normal or wall
    const bool b_normal = !in.superfluid(b);
    if (a_normal && b_normal) {
      if (viscosity == 0.0 || (a_wall && b_wall)) {
        return {0.0, 0.0};
      }
      const double pair_factor = a_wall || b_wall ? 1.0 : normal_pair_factor;
      const double k = -2.0 * tau * viscosity * pair_factor * phase_volume[a] * phase_volume[b] *
                       kernel.derivative_over_r(r);
      return central_viscosity ? std::pair{0.0, (D + 2) * k} : std::pair{k, 0.0};
    }
    if (a_normal == b_normal) {
      return {0.0, 0.0}; // superfluid pairs: no viscosity (the superfluid is inviscid)
    }
    const double c_l = a_wall || b_wall ? wall_friction : friction;
    if (c_l == 0.0) {
      return {0.0, 0.0};
    }
    const std::uint32_t s = a_normal ? b : a;
    if (!(normal_weight[s] > 0.0)) {
      return {0.0, 0.0}; // every normal neighbour on the kernel's edge: W = 0 there
    }
    return {tau * c_l * phase_volume[s] * kernel.value(r) / normal_weight[s], 0.0};
  }

  // The contact terms' impulse added to f.
  void add_contact(const PairGeometry<D>& p, const std::array<double, D>& relative,
                   std::array<double, D + 1>& f) const {
    const std::uint32_t a = p.a;
    const std::uint32_t b = p.b;
    double approach = 0.0; // v_ab . n, negative when approaching
    for (int k = 0; k < D; ++k) {
      approach += relative[k] * p.x_ab[k] / p.r;
    }
    if (!(approach < 0.0) || (in.wall(a) && in.wall(b))) {
      return;
    }
    double impulse = 0.0; // along n, on a
    if (contact.riemann) {
      const double beta = std::min(contact.limiter * -approach, contact.sound_speed);
      const double rho_a = contact.density[a];
      const double rho_b = contact.density[b];
      const double k_ab = -2.0 * tau * volume[a] * volume[b] * beta * rho_a * rho_b /
                          (rho_a + rho_b) * kernel.derivative(p.r);
      impulse -= k_ab * approach;
    }
    if (contact.collision) {
      const double m_a = contact.mass[a];
      const double m_b = contact.mass[b];
      const double reduced = in.wall(b) ? m_a : in.wall(a) ? m_b : m_a * m_b / (m_a + m_b);
      impulse -= (1.0 + contact.restitution) * reduced * approach;
    }
    for (int k = 0; k < D; ++k) {
      f[k] += impulse * p.x_ab[k] / p.r;
    }
  }

  void pair(const PairGeometry<D>& p, std::array<double, D + 1>& to_a,
            std::array<double, D + 1>& to_b) const {
    const std::uint32_t a = p.a;
    const std::uint32_t b = p.b;
    const auto [k_ab, k_central] = coupling(a, b, p.r);
    std::array<double, D> relative{};
    for (int k = 0; k < D; ++k) {
      relative[k] = in.velocity[k][a] - in.velocity[k][b];
      to_a[k] = -k_ab * relative[k];
    }
    if (k_central != 0.0) {
      double along = 0.0; // (v_a - v_b) . x_ab / r^2
      for (int k = 0; k < D; ++k) {
        along += relative[k] * p.x_ab[k];
      }
      along /= p.r_squared;
      for (int k = 0; k < D; ++k) {
        to_a[k] -= k_central * along * p.x_ab[k];
      }
    }
    if (p.r < contact.distance && p.r > 0.0) {
      add_contact(p, relative, to_a);
    }
    to_a[D] = to_b[D] = 0.0;
    for (int k = 0; k < D; ++k) {
      to_b[k] = -to_a[k];
      if (in.wall(b)) {
        to_a[D] += to_a[k] * in.velocity[k][b];
      } else if (in.wall(a)) {
        to_b[D] += to_b[k] * in.velocity[k][a];
      }
    }
  }
};

} // namespace revsph::two_fluid
