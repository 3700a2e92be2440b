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
// Reversible: v_b is linear in the fluid's velocities and v_w (both odd under R), every term
// and the quotient change sign exactly when they do, and the sums run in the pair list's order,
// the same for any thread count. A boundary particle with no fluid within reach keeps v_w.

#include "models/shtc/kernel_sums.hpp"

#include <span>
#include <vector>

namespace revsph::shtc {

// `velocity` (by slot) holds the fluid's velocities and, for wall slots, v_w; on return the
// wall slots hold the mirrored velocities. is_wall[s]: whether slot s is a boundary particle.
template <int D>
void mirror_wall_velocities(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                            std::span<const double> mass, std::span<const std::uint8_t> is_wall,
                            const HalfPairList& pairs, CoordinateArrays<D>& velocity,
                            std::vector<Vec<D>>& fluid_sum, std::vector<double>& weight_sum) {
  const std::size_t n = mass.size();
  fluid_sum.assign(n, Vec<D>{});
  weight_sum.assign(n, 0.0);
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      if (is_wall[a] == is_wall[b]) {
        continue; // fluid-fluid or wall-wall
      }
      Eigen::Matrix<double, D, 1> x_ab;
      const double w = kernel.value(std::sqrt(separation<D>(x, a, b, x_ab)));
      const std::uint32_t wall = is_wall[a] ? a : b;
      const std::uint32_t fluid = is_wall[a] ? b : a;
      const double weight = mass[fluid] * w;
      weight_sum[wall] += weight;
      for (int k = 0; k < D; ++k) {
        fluid_sum[wall][k] += weight * velocity[k][fluid];
      }
    }
  });
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    if (is_wall[s] && weight_sum[s] > 0.0) {
      for (int k = 0; k < D; ++k) {
        velocity[k][s] = 2.0 * velocity[k][s] - fluid_sum[s][k] / weight_sum[s];
      }
    }
  }
}

} // namespace revsph::shtc
