#pragma once
// The renormalised SPH velocity gradient of SHTC-SPH (paper 2, eqs. 10 and 21a):
//   H_a = sum_b m_b x_ab (x) grad w_ab,
//   L_a = (sum_b m_b v_ab (x) grad w_ab) H_a^-1,      grad w_ab = w'(r_ab) / r_ab x_ab (eq. 6),
// over the pairs of a HalfPairList (arrays indexed by slot). L_a is exact for a linear velocity
// field whenever a has d linearly independent neighbours (Statement 2).
//
// Each pair term is computed once and added to both particles: the tensor products for (b, a)
// equal those for (a, b) (both factors change sign), only the mass factor differs. The sums are
// in double, in the order fixed by the pair list (the same for any thread count), and every v
// term is odd in v: negating all velocities negates L bit for bit — what the reversible step
// (eq. 49) needs of it.

#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_list.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <span>
#include <vector>

namespace revsph::shtc {

template <int D>
using GradientMatrix = Eigen::Matrix<double, D, D>;

// h_matrix[a] = H_a; gradient[a] = L_a, or zero where H_a is singular (fewer than d independent
// neighbours: an isolated particle has no velocity gradient).
template <int D>
void velocity_gradients(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                        const CoordinateView<D>& v, std::span<const double> mass,
                        const HalfPairList& pairs, std::vector<GradientMatrix<D>>& h_matrix,
                        std::vector<GradientMatrix<D>>& gradient) {
  const std::size_t n = mass.size();
  std::vector<GradientMatrix<D>> velocity_sum(n, GradientMatrix<D>::Zero());
  h_matrix.assign(n, GradientMatrix<D>::Zero());
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      Eigen::Matrix<double, D, 1> x_ab;
      Eigen::Matrix<double, D, 1> v_ab;
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        x_ab(k) = x[k][a] - x[k][b];
        v_ab(k) = v[k][a] - v[k][b];
        r_squared += x_ab(k) * x_ab(k);
      }
      const Eigen::Matrix<double, D, 1> kernel_gradient =
          kernel.derivative_over_r(std::sqrt(r_squared)) * x_ab;
      const GradientMatrix<D> position_term = x_ab * kernel_gradient.transpose();
      const GradientMatrix<D> velocity_term = v_ab * kernel_gradient.transpose();
      h_matrix[a] += mass[b] * position_term;
      h_matrix[b] += mass[a] * position_term;
      velocity_sum[a] += mass[b] * velocity_term;
      velocity_sum[b] += mass[a] * velocity_term;
    }
  });
  gradient.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const double determinant = h_matrix[a].determinant();
    // Relative to the scale of H: a particle with too few neighbours, not a small kernel.
    const double scale = h_matrix[a].cwiseAbs().maxCoeff();
    if (!(std::fabs(determinant) > 1e-12 * std::pow(scale, D))) {
      gradient[a].setZero();
      continue;
    }
    gradient[a] = velocity_sum[a] * h_matrix[a].inverse();
  }
}

} // namespace revsph::shtc
