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

template <int D>
void velocity_gradients(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                        const CoordinateView<D>& v, std::span<const double> mass,
                        const HalfPairList& pairs, std::span<const GradientMatrix<D>> h_inverse,
                        std::vector<GradientMatrix<D>>& velocity_sum,
                        std::vector<GradientMatrix<D>>& gradient) {
  const std::size_t n = mass.size();
  velocity_sum.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    velocity_sum[a].setZero();
  }
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      Eigen::Matrix<double, D, 1> x_ab;
      Eigen::Matrix<double, D, 1> v_ab;
      const double r = std::sqrt(separation<D>(x, a, b, x_ab));
      separation<D>(v, a, b, v_ab);
      const GradientMatrix<D> velocity_term =
          v_ab * (kernel.derivative_over_r(r) * x_ab).transpose();
      velocity_sum[a] += mass[b] * velocity_term;
      velocity_sum[b] += mass[a] * velocity_term;
    }
  });
  gradient.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    gradient[a] = velocity_sum[a] * h_inverse[a];
  }
}

} // namespace revsph::shtc
