#pragma once
// Mirrored no-slip walls, an option beyond paper 2 (walls.no_slip = "mirrored"). The paper's
// walls pretend their own velocity v_w in L (eq. 10): across the wall the velocity field then
// turns flat, so the one-sided fit of L near the wall sees about half the shear, and the fluid
// slips by about a smoothing length (Taylor-Couette's inner wall, the cavity's lid). Here each
// boundary particle b pretends
//   v_b = 2 v_w,b - sum_a m_a w_ab v_a / sum_a m_a w_ab   (a over the fluid near b),
// the fluid's velocity mirrored about the wall's: the field continues across the wall and its
// value at the wall is v_w (the no-slip wall of Morris, Fox & Zhu, J. Comput. Phys. 1997, and
// Adami, Hu & Adams, J. Comput. Phys. 2012, with Shepard's average in place of their fluid-side
// extrapolation).
//
// Reversible: v_b is linear in the fluid's velocities and v_w (both odd under R); the sums are
// exact in integers (odd-symmetric rounding of odd terms), so they and the quotient change sign
// exactly when the velocities do, for any thread count and cell size. A boundary particle with no
// fluid within reach keeps v_w.

#include "core/arithmetic.hpp"
#include "core/pair_sum.hpp"
#include "models/shtc/kernel_sums.hpp"

#include <span>
#include <tuple>
#include <vector>

namespace revsph::shtc {

// Quantity 0: sum_a m_a w_ab (the Shepard weight), 1..D: sum_a m_a w_ab v_a, for wall slots b.
template <int D>
struct MirrorTerm {
  static constexpr int width = D + 1;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  SlotInSet is_wall; // the boundary particles (SlotLayout::in)
  const CoordinateArrays<D>& velocity;

  // Filled from own particles' state (a distributed run copies the ghosts' in, core/pair_sum.hpp).
  auto slot_inputs() const { return std::tie(velocity); }
  bool receives(std::uint32_t s) const { return is_wall(s); }
  void pair(const PairGeometry<D>& p, std::array<double, D + 1>& to_a,
            std::array<double, D + 1>& to_b) const {
    to_a.fill(0.0);
    to_b.fill(0.0);
    if (is_wall(p.a) == is_wall(p.b)) {
      return; // fluid-fluid or wall-wall
    }
    const std::uint32_t fluid = is_wall(p.a) ? p.b : p.a;
    std::array<double, D + 1>& to_wall = is_wall(p.a) ? to_a : to_b;
    const double weight = mass[fluid] * kernel.value(p.r);
    to_wall[0] = weight;
    for (int k = 0; k < D; ++k) {
      to_wall[k + 1] = weight * velocity[k][fluid];
    }
  }
};

template <int D>
PairSums<FixedArithmetic, D + 1> mirror_sums(const fixedpoint::Scale& weight_scale,
                                             const fixedpoint::Scale& velocity_sum_scale) {
  std::array<SummedQuantity, D + 1> q{};
  q.fill({"mirrored_velocity", velocity_sum_scale});
  q[0] = {"mirror_weight", weight_scale};
  return PairSums<FixedArithmetic, D + 1>(q);
}

// `velocity` (by slot) holds the fluid's velocities and, for wall slots, v_w; on return the
// wall slots hold the mirrored velocities. is_wall(s): whether slot s is a boundary particle.
template <int D>
void mirror_wall_velocities(const WendlandQuintic<D>& kernel, const SlotLayout<D>& layout,
                            std::span<const double> mass, SlotInSet is_wall,
                            CoordinateArrays<D>& velocity, PairSums<FixedArithmetic, D + 1>& sums) {
  sum_pairs<FixedArithmetic>(layout, MirrorTerm<D>{kernel, mass, is_wall, velocity}, sums);
  const std::size_t n = layout.slot_count();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    const double weight = sums.value(0, s);
    if (is_wall(s) && weight > 0.0) {
      for (int k = 0; k < D; ++k) {
        velocity[k][s] = 2.0 * velocity[k][s] - sums.value(k + 1, s) / weight;
      }
    }
  }
}

} // namespace revsph::shtc
