#pragma once
// The sums of SHTC-SPH that depend on the positions alone, in one pass over the pairs of a
// HalfPairList (arrays indexed by slot):
//   rho_a    = sum_b m_b w_ab + C_rho,a                  (paper 2 eq. 7, the sum includes b = a)
//   lambda_a = sum_b m_b h dw_ab/dh + C_lambda,a         (eq. 40, the sum includes b = a)
//   H_a      = sum_b m_b x_ab (x) grad w_ab              (eq. 21a), grad w_ab = w'/r x_ab (eq. 6)
// and H_a^-1 (zero where H_a is singular: a particle with fewer than d independent neighbours has
// no velocity gradient and no shear stress). The pair terms for (b, a) equal those for (a, b)
// up to the mass factor (the tensor product of two odd vectors is even), so each is computed once.
// Sums in double in the order the pair list fixes: the same bits for any thread count, and a
// deterministic function of the positions — what the reversible step needs of them.

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

template <int D>
struct KernelSums {
  std::vector<double> density;
  std::vector<double> lambda;
  std::vector<GradientMatrix<D>> h_matrix;
  std::vector<GradientMatrix<D>> h_inverse;
};

// x_ab = x_a - x_b and |x_ab|^2 (summed over the axes in order), for the pair loops.
template <int D>
double separation(const CoordinateView<D>& x, std::uint32_t a, std::uint32_t b,
                  Eigen::Matrix<double, D, 1>& x_ab) {
  double r_squared = 0.0;
  for (int k = 0; k < D; ++k) {
    x_ab(k) = x[k][a] - x[k][b];
    r_squared += x_ab(k) * x_ab(k);
  }
  return r_squared;
}

// H^-1, or zero when H is singular relative to its own scale (too few neighbours, not a small
// kernel).
template <int D>
GradientMatrix<D> renormalisation_inverse(const GradientMatrix<D>& h) {
  const double determinant = h.determinant();
  const double scale = h.cwiseAbs().maxCoeff();
  if (!(std::fabs(determinant) > 1e-12 * std::pow(scale, D))) {
    return GradientMatrix<D>::Zero();
  }
  return h.inverse();
}

template <int D>
void compute_kernel_sums(const WendlandQuintic<D>& kernel, const CoordinateView<D>& x,
                         std::span<const double> mass, std::span<const double> density_constant,
                         std::span<const double> lambda_constant, const HalfPairList& pairs,
                         KernelSums<D>& sums) {
  const std::size_t n = mass.size();
  sums.density.resize(n);
  sums.lambda.resize(n);
  sums.h_matrix.resize(n);
  sums.h_inverse.resize(n);
  const double self_weight = kernel.value(0.0);
  const double self_scale_derivative = kernel.scale_derivative(0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    sums.density[a] = mass[a] * self_weight;
    sums.lambda[a] = mass[a] * self_scale_derivative;
    sums.h_matrix[a].setZero();
  }
  pairs.for_each_slot([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
    for (const std::uint32_t b : partners) {
      Eigen::Matrix<double, D, 1> x_ab;
      const double r = std::sqrt(separation<D>(x, a, b, x_ab));
      const double w = kernel.value(r);
      const double scale_derivative = kernel.scale_derivative(r);
      const GradientMatrix<D> position_term =
          x_ab * (kernel.derivative_over_r(r) * x_ab).transpose();
      sums.density[a] += mass[b] * w;
      sums.density[b] += mass[a] * w;
      sums.lambda[a] += mass[b] * scale_derivative;
      sums.lambda[b] += mass[a] * scale_derivative;
      sums.h_matrix[a] += mass[b] * position_term;
      sums.h_matrix[b] += mass[a] * position_term;
    }
  });
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    sums.density[a] += density_constant[a];
    sums.lambda[a] += lambda_constant[a];
    sums.h_inverse[a] = renormalisation_inverse<D>(sums.h_matrix[a]);
  }
}

} // namespace revsph::shtc
