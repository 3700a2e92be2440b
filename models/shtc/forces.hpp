#pragma once
// The acceleration of SHTC-SPH (paper 2, eq. 48 divided by m_a, i.e. eq. 42):
//   a_a = sum_b m_b (T_a + T_b) grad w_ab - sum_b m_b cp^2 (lambda_a + lambda_b) / rho0^2
//                                              (h/r) d2w/(dr dh) x_ab,
// as a pair term of core's pair loop (arrays indexed by slot). With g_ab the bracket for (a, b),
// the pair gives m_b g_ab to a and -m_a g_ab to b (grad w and x_ab are odd in the pair). Sums
// exact in integers (SumScales::acceleration): the same bits for any thread count and cell size;
// a deterministic function of the positions and the distortions.

#include "core/arithmetic.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "models/shtc/kernel_sums.hpp"
#include "models/shtc/tensile_penalty.hpp"

#include <span>

namespace revsph::shtc {

template <int D>
struct StressForceTerm {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  double penalty_strength; // cp^2 / rho0^2
  std::span<const double> mass;
  std::span<const GradientMatrix<D>> stress; // T_a of eq. (21b)
  std::span<const double> lambda;

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    Eigen::Matrix<double, D, 1> x_ab;
    for (int k = 0; k < D; ++k) {
      x_ab(k) = p.x_ab[k];
    }
    const Eigen::Matrix<double, D, 1> kernel_gradient = kernel.derivative_over_r(p.r) * x_ab;
    const double penalty =
        penalty_pair_factor<D>(kernel, penalty_strength, lambda[p.a], lambda[p.b], p.r);
    const Eigen::Matrix<double, D, 1> term =
        (stress[p.a] + stress[p.b]) * kernel_gradient - penalty * x_ab;
    for (int k = 0; k < D; ++k) {
      to_a[k] = mass[p.b] * term(k);
      to_b[k] = -(mass[p.a] * term(k));
    }
  }
};

// The acceleration by slot into acceleration[k][slot]; `sums` is the loop's scratch (D
// quantities at the acceleration scale, see acceleration_sums).
template <int D>
void compute_acceleration(const WendlandQuintic<D>& kernel, double penalty_strength,
                          const SlotLayout<D>& layout, std::span<const double> mass,
                          std::span<const GradientMatrix<D>> stress, std::span<const double> lambda,
                          PairSums<FixedArithmetic, D>& sums, CoordinateArrays<D>& acceleration) {
  sum_pairs<FixedArithmetic>(
      layout, StressForceTerm<D>{kernel, penalty_strength, mass, stress, lambda}, sums);
  for (int k = 0; k < D; ++k) {
    const std::span<const double> values = sums.values(k);
    acceleration[k].assign(values.begin(), values.end());
  }
}

template <int D>
PairSums<FixedArithmetic, D> acceleration_sums(const fixedpoint::Scale& scale) {
  std::array<SummedQuantity, D> q{};
  q.fill({"acceleration", scale});
  return PairSums<FixedArithmetic, D>(q);
}

} // namespace revsph::shtc
