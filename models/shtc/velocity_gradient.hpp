#pragma once
// The renormalised SPH velocity gradient of SHTC-SPH (paper 2, eq. 10):
//   L_a = (sum_b m_b v_ab (x) grad w_ab) H_a^-1,      grad w_ab = w'(r_ab) / r_ab x_ab (eq. 6),
// over the pairs of a HalfPairList (arrays indexed by slot), with H_a^-1 from kernel_sums.hpp.
// L_a is exact for a linear velocity field whenever a has d linearly independent neighbours
// (Statement 2), and zero where H_a is singular.
//
// Each pair term is computed once and added to both particles: the tensor product for (b, a)
// equals that for (a, b) (both factors change sign), only the mass factor differs. The sums are
// in double, in the order fixed by the pair list (the same for any thread count), and every term
// is odd in v: negating all velocities negates L bit for bit — what the reversible step (eq. 49)
// needs of it.

#include "models/shtc/kernel_sums.hpp"

#include <span>
#include <vector>

namespace revsph::shtc {

// The velocities each slot sees its partners move with: `seen_by_material` for every slot, or,
// with mirrored walls (mirrored_walls.hpp), `seen_by_walls` for the slots where is_wall is set
// (empty is_wall: one view for all).
template <int D>
struct SeenVelocities {
  CoordinateView<D> seen_by_material;
  CoordinateView<D> seen_by_walls;
  std::span<const std::uint8_t> is_wall;
};

template <int D>
void velocity_gradients(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                        const SeenVelocities<D>& v, std::span<const double> mass,
                        const HalfPairList& pairs, std::span<const GradientMatrix<D>> h_inverse,
                        std::vector<GradientMatrix<D>>& velocity_sum,
                        std::vector<GradientMatrix<D>>& gradient) {
  const std::size_t n = mass.size();
  velocity_sum.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    velocity_sum[a].setZero();
  }
  const bool one_view = v.is_wall.empty();
  const auto view_of_slot = [&](std::uint32_t s) -> const CoordinateView<D>& {
    return !one_view && v.is_wall[s] ? v.seen_by_walls : v.seen_by_material;
  };
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      Eigen::Matrix<double, D, 1> x_ab;
      const double r = std::sqrt(separation<D>(x, a, b, x_ab));
      const Eigen::Matrix<double, D, 1> gradient_ab = kernel.derivative_over_r(r) * x_ab;
      const auto term_seen_by = [&](std::uint32_t s) -> GradientMatrix<D> {
        Eigen::Matrix<double, D, 1> v_ab;
        separation<D>(view_of_slot(s), a, b, v_ab);
        return v_ab * gradient_ab.transpose();
      };
      const GradientMatrix<D> velocity_term = term_seen_by(a);
      velocity_sum[a] += mass[b] * velocity_term;
      // a and b see the same velocities unless one is a mirrored wall and the other is not.
      velocity_sum[b] +=
          mass[a] * (one_view || v.is_wall[a] == v.is_wall[b] ? velocity_term : term_seen_by(b));
    }
  });
  gradient.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    gradient[a] = velocity_sum[a] * h_inverse[a];
  }
}

// Every slot sees the same velocities `v`.
template <int D>
void velocity_gradients(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                        const CoordinateView<D>& v, std::span<const double> mass,
                        const HalfPairList& pairs, std::span<const GradientMatrix<D>> h_inverse,
                        std::vector<GradientMatrix<D>>& velocity_sum,
                        std::vector<GradientMatrix<D>>& gradient) {
  velocity_gradients<D>(kernel, x, SeenVelocities<D>{v, v, {}}, mass, pairs, h_inverse,
                        velocity_sum, gradient);
}

} // namespace revsph::shtc
