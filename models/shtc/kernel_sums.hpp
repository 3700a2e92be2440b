#pragma once
// The sums of SHTC-SPH that depend on the positions alone, one pair term for core's pair loop
// (core/pair_sum.hpp; arrays indexed by slot):
//   rho_a    = sum_b m_b w_ab + C_rho,a                  (paper 2 eq. 7, the sum includes b = a)
//   lambda_a = sum_b m_b h dw_ab/dh + C_lambda,a         (eq. 40, the sum includes b = a)
//   H_a      = sum_b m_b x_ab (x) grad w_ab              (eq. 21a), grad w_ab = w'/r x_ab (eq. 6)
// and H_a^-1 (zero where H_a is singular: a particle with fewer than d independent neighbours has
// no velocity gradient and no shear stress). The pair terms for (b, a) equal those for (a, b)
// up to the mass factor (the tensor product of two odd vectors is even). Every sum is exact in
// integers at SumScales::density: the same bits for any thread count and any cell size, a
// deterministic function of the positions, which is what the reversible step needs of them.

#include "core/arithmetic.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/slot_layout.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace revsph::shtc {

template <int D>
using GradientMatrix = Eigen::Matrix<double, D, D>;

// H is symmetric (x_ab (x) x_ab w'/r): its upper triangle, row by row, is summed.
template <int D>
constexpr int upper_triangle_size = D*(D + 1) / 2;

template <int D>
struct KernelSumsTerm {
  static constexpr int width = 2 + upper_triangle_size<D>; // rho, lambda, H's upper triangle
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  std::span<const std::int64_t> density_constant; // raw at the density scale; empty: zero
  std::span<const std::int64_t> lambda_constant;  // the same

  void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
            std::array<double, width>& to_b) const {
    const double w = kernel.value(p.r);
    const double scale_derivative = kernel.scale_derivative(p.r);
    const double slope = kernel.derivative_over_r(p.r);
    to_a[0] = mass[p.b] * w;
    to_b[0] = mass[p.a] * w;
    to_a[1] = mass[p.b] * scale_derivative;
    to_b[1] = mass[p.a] * scale_derivative;
    int entry = 2;
    for (int i = 0; i < D; ++i) {
      for (int j = i; j < D; ++j, ++entry) {
        const double position_term = p.x_ab[i] * (slope * p.x_ab[j]);
        to_a[entry] = mass[p.b] * position_term;
        to_b[entry] = mass[p.a] * position_term;
      }
    }
  }
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    add(0, mass[s] * kernel.value(0.0));
    add(1, mass[s] * kernel.scale_derivative(0.0));
    if (!density_constant.empty()) {
      add.raw(0, density_constant[s]);
      add.raw(1, lambda_constant[s]);
    }
  }
};

template <int D>
struct KernelSums {
  explicit KernelSums(const fixedpoint::Scale& density_scale) : totals(quantities(density_scale)) {}

  std::vector<double> density;
  std::vector<double> lambda;
  std::vector<GradientMatrix<D>> h_matrix;
  std::vector<GradientMatrix<D>> h_inverse;
  PairSums<FixedArithmetic, KernelSumsTerm<D>::width> totals;

private:
  static std::array<SummedQuantity, KernelSumsTerm<D>::width>
  quantities(const fixedpoint::Scale& scale) {
    std::array<SummedQuantity, KernelSumsTerm<D>::width> q{};
    q.fill({"renormalisation_matrix", scale});
    q[0] = {"density", scale};
    q[1] = {"lambda", scale};
    return q;
  }
};

// H^-1, or zero when H is singular relative to its own scale (too few neighbours, not a small
// kernel).
template <int D>
GradientMatrix<D> renormalisation_inverse(const GradientMatrix<D>& h) {
  const double determinant = h.determinant();
  const double scale = h.cwiseAbs().maxCoeff();
  if (!(std::fabs(determinant) > 1e-12 * dmath::integer_power(scale, D))) {
    return GradientMatrix<D>::Zero();
  }
  return h.inverse();
}

// The sums over the layout's pairs; the constants are raw at the density scale (empty: zero).
template <int D>
void compute_kernel_sums(const WendlandQuintic<D>& kernel, const SlotLayout<D>& layout,
                         std::span<const double> mass,
                         std::span<const std::int64_t> density_constant,
                         std::span<const std::int64_t> lambda_constant, KernelSums<D>& sums) {
  const std::size_t n = layout.slot_count();
  sums.density.resize(n);
  sums.lambda.resize(n);
  sums.h_matrix.resize(n);
  sums.h_inverse.resize(n);
  // Each slot's values and H^-1 as soon as its sums are final (no region of their own).
  const auto unpack = [&sums](std::uint32_t s) {
    sums.density[s] = sums.totals.value(0, s);
    sums.lambda[s] = sums.totals.value(1, s);
    int entry = 2;
    for (int i = 0; i < D; ++i) {
      for (int j = i; j < D; ++j, ++entry) {
        sums.h_matrix[s](i, j) = sums.totals.value(entry, s);
        sums.h_matrix[s](j, i) = sums.h_matrix[s](i, j);
      }
    }
    sums.h_inverse[s] = renormalisation_inverse<D>(sums.h_matrix[s]);
  };
  sum_pairs<FixedArithmetic>(layout,
                             KernelSumsTerm<D>{kernel, mass, density_constant, lambda_constant},
                             sums.totals, {}, unpack);
}

} // namespace revsph::shtc
