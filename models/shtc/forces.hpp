#pragma once
// The acceleration of SHTC-SPH (paper 2, eq. 48 divided by m_a, i.e. eq. 42):
//   a_a = sum_b m_b (T_a + T_b) grad w_ab - sum_b m_b cp^2 (lambda_a + lambda_b) / rho0^2
//                                              (h/r) d2w/(dr dh) x_ab,
// over the pairs of a HalfPairList (arrays indexed by slot). With g_ab the bracket for (a, b),
// the pair gives m_b g_ab to a and -m_a g_ab to b (grad w and x_ab are odd in the pair), so each
// pair is evaluated once. Sums in double in the pair list's order: the same bits for any thread
// count; a deterministic function of the positions and the distortions.

#include "core/geometry.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_list.hpp"
#include "models/shtc/kernel_sums.hpp"
#include "models/shtc/tensile_penalty.hpp"

#include <cmath>
#include <span>

namespace revsph::shtc {

// `stress` holds T_a (eq. 21b) per slot; `penalty_strength` is cp^2 / rho0^2.
template <int D>
void compute_acceleration(const WendlandQuintic<D>& kernel, double penalty_strength,
                          const CoordinateView<D>& x, std::span<const double> mass,
                          std::span<const GradientMatrix<D>> stress, std::span<const double> lambda,
                          const HalfPairList& pairs, CoordinateArrays<D>& acceleration) {
  const std::size_t n = mass.size();
  for (int k = 0; k < D; ++k) {
    acceleration[k].resize(n);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    for (int k = 0; k < D; ++k) {
      acceleration[k][a] = 0.0;
    }
  }
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      Eigen::Matrix<double, D, 1> x_ab;
      const double r = std::sqrt(separation<D>(x, a, b, x_ab));
      const Eigen::Matrix<double, D, 1> kernel_gradient = kernel.derivative_over_r(r) * x_ab;
      const double penalty =
          penalty_pair_factor<D>(kernel, penalty_strength, lambda[a], lambda[b], r);
      const Eigen::Matrix<double, D, 1> term =
          (stress[a] + stress[b]) * kernel_gradient - penalty * x_ab;
      for (int k = 0; k < D; ++k) {
        acceleration[k][a] += mass[b] * term(k);
        acceleration[k][b] -= mass[a] * term(k);
      }
    }
  });
}

} // namespace revsph::shtc
