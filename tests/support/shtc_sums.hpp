#pragma once
// The SHTC-SPH pair sums of a test cloud without integration constants (C_rho = C_lambda = 0).

#include "models/shtc/kernel_sums.hpp"
#include "models/shtc/velocity_gradient.hpp"

#include <vector>

namespace revsph::testing {

template <int D>
shtc::KernelSums<D> kernel_sums_of(const WendlandQuintic<D>& kernel, const CoordinateArrays<D>& x,
                                   const std::vector<double>& mass, const HalfPairList& pairs,
                                   const std::vector<double>& lambda_constant = {}) {
  const std::vector<double> zero(mass.size(), 0.0);
  shtc::KernelSums<D> sums;
  shtc::compute_kernel_sums<D>(kernel, view_of<D>(x), mass, zero,
                               lambda_constant.empty() ? zero : lambda_constant, pairs, sums);
  return sums;
}

template <int D>
std::vector<shtc::GradientMatrix<D>>
velocity_gradients_of(const WendlandQuintic<D>& kernel, const CoordinateArrays<D>& x,
                      const CoordinateArrays<D>& v, const std::vector<double>& mass,
                      const HalfPairList& pairs) {
  const shtc::KernelSums<D> sums = kernel_sums_of<D>(kernel, x, mass, pairs);
  std::vector<shtc::GradientMatrix<D>> velocity_sum;
  std::vector<shtc::GradientMatrix<D>> gradient;
  shtc::velocity_gradients<D>(kernel, view_of<D>(x), view_of<D>(v), mass, pairs, sums.h_inverse,
                              velocity_sum, gradient);
  return gradient;
}

} // namespace revsph::testing
