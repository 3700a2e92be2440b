// The tensile penalty of SHTC-SPH (models/shtc/tensile_penalty.hpp): lambda against an all-pairs
// sum, and the penalty acceleration (the force loop of forces.hpp with zero stress) against
// central differences of the penalty energy P_h
// (eqs. 39–42): the force must be exactly -grad P_h for the energy to be conserved.

#include "models/shtc/forces.hpp"
#include "models/shtc/tensile_penalty.hpp"

#include "cell_ordered_cloud.hpp"
#include "dimensions.hpp"
#include "shtc_sums.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using revsph::CoordinateArrays;
using revsph::shtc::PenaltyParameters;

// lambda_a = sum over all b (including a) of m_b h dw/dh + C_a, by brute force.
template <int D>
std::vector<double> all_pairs_lambda(const revsph::WendlandQuintic<D>& kernel,
                                     const CoordinateArrays<D>& x, const std::vector<double>& mass,
                                     const std::vector<double>& constant) {
  const std::size_t n = mass.size();
  std::vector<double> lambda(constant);
  const revsph::CoordinateView<D> points = revsph::view_of<D>(x);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      const double r_squared = revsph::squared_distance<D>(points, a, b);
      lambda[a] += mass[b] * kernel.scale_derivative(std::sqrt(r_squared));
    }
  }
  return lambda;
}

REVSPH_DIMENSION_TEST_SUITE(ShtcTensilePenalty);

TYPED_TEST(ShtcTensilePenalty, AccelerationIsMinusTheEnergyGradient) {
  constexpr int D = TypeParam::value;
  const auto cloud = revsph::testing::jittered_lattice<D>(D == 2 ? 12 : 6, 3);
  const revsph::WendlandQuintic<D> kernel(cloud.support);
  const PenaltyParameters parameters{3.0, 1.0};
  const std::size_t n = cloud.mass.size();
  std::mt19937_64 rng(4);
  std::normal_distribution<double> offset(0.0, 0.3);
  std::vector<double> constant(n);
  for (double& c : constant) {
    c = offset(rng);
  }

  const revsph::shtc::KernelSums<D> sums =
      revsph::testing::kernel_sums_of<D>(kernel, cloud.x, cloud.mass, constant);
  const std::vector<double>& lambda = sums.lambda;
  const std::vector<double> expected_lambda =
      all_pairs_lambda<D>(kernel, cloud.x, cloud.mass, constant);
  for (std::size_t a = 0; a < n; ++a) {
    ASSERT_NEAR(lambda[a], expected_lambda[a], 1e-12 * std::fabs(kernel.scale_derivative(0.0)))
        << "slot " << a;
  }

  // The force loop with zero stress leaves the penalty acceleration alone.
  const std::vector<revsph::shtc::GradientMatrix<D>> no_stress(
      n, revsph::shtc::GradientMatrix<D>::Zero());
  const CoordinateArrays<D> acceleration = revsph::testing::acceleration_of<D>(
      kernel, revsph::shtc::penalty_strength(parameters), cloud.x, cloud.mass, no_stress, lambda);

  auto energy_at = [&](const CoordinateArrays<D>& x) {
    return revsph::shtc::penalty_energy<D>(parameters, cloud.mass,
                                           all_pairs_lambda<D>(kernel, x, cloud.mass, constant));
  };
  double largest = 0.0;
  for (int k = 0; k < D; ++k) {
    for (std::size_t a = 0; a < n; ++a) {
      largest = std::max(largest, std::fabs(acceleration[k][a]));
    }
  }
  ASSERT_GT(largest, 0.0);
  const double step = 1e-6;
  for (std::size_t a = 0; a < n; a += 7) {
    for (int k = 0; k < D; ++k) {
      CoordinateArrays<D> plus = cloud.x;
      CoordinateArrays<D> minus = cloud.x;
      plus[k][a] += step;
      minus[k][a] -= step;
      const double gradient = (energy_at(plus) - energy_at(minus)) / (2.0 * step);
      EXPECT_NEAR(acceleration[k][a], -gradient / cloud.mass[a], 1e-6 * largest)
          << "slot " << a << " axis " << k;
    }
  }
}

} // namespace
