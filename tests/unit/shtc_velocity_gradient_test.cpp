// The renormalised velocity gradient of SHTC-SPH (models/shtc/velocity_gradient.hpp): exact for
// linear velocity fields on a disordered lattice (paper 2, Statement 2), odd in the velocities bit
// for bit, and the same bits for any thread count.

#include "core/cell_list.hpp"
#include "core/pair_list.hpp"
#include "core/threads.hpp"
#include "models/shtc/velocity_gradient.hpp"

#include "cell_ordered_cloud.hpp"
#include "dimensions.hpp"
#include "shtc_sums.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <type_traits>

namespace {

using revsph::CoordinateArrays;
using revsph::shtc::GradientMatrix;
using revsph::testing::Cloud;
using revsph::testing::jittered_lattice;

// v = L0 x + c at every point.
template <int D>
CoordinateArrays<D> linear_velocity(const Cloud<D>& cloud, const GradientMatrix<D>& gradient) {
  CoordinateArrays<D> v;
  for (int k = 0; k < D; ++k) {
    v[k].resize(cloud.x[0].size());
    for (std::size_t a = 0; a < v[k].size(); ++a) {
      double value = 0.7 * (k + 1);
      for (int j = 0; j < D; ++j) {
        value += gradient(k, j) * cloud.x[j][a];
      }
      v[k][a] = value;
    }
  }
  return v;
}

template <int D>
std::vector<GradientMatrix<D>> gradients_of(const Cloud<D>& cloud, const CoordinateArrays<D>& v) {
  const revsph::WendlandQuintic<D> kernel(cloud.support);
  return revsph::testing::velocity_gradients_of<D>(kernel, cloud.x, v, cloud.mass);
}

// Random velocities at the points of a cloud.
template <int D>
CoordinateArrays<D> random_velocity(const Cloud<D>& cloud, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> speed(0.0, 1.0);
  CoordinateArrays<D> v;
  for (int k = 0; k < D; ++k) {
    for (std::size_t a = 0; a < cloud.x[0].size(); ++a) {
      v[k].push_back(speed(rng));
    }
  }
  return v;
}

// Every entry of `actual` has the bits of `sign` times the entry of `expected`.
template <int D>
void expect_same_bits(const std::vector<GradientMatrix<D>>& expected,
                      const std::vector<GradientMatrix<D>>& actual, double sign) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t a = 0; a < expected.size(); ++a) {
    for (int r = 0; r < D; ++r) {
      for (int c = 0; c < D; ++c) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(actual[a](r, c)),
                  std::bit_cast<std::uint64_t>(sign * expected[a](r, c)))
            << "slot " << a;
      }
    }
  }
}

REVSPH_DIMENSION_TEST_SUITE(ShtcVelocityGradient);

TYPED_TEST(ShtcVelocityGradient, IsExactForALinearField) {
  constexpr int D = TypeParam::value;
  const Cloud<D> cloud = jittered_lattice<D>(D == 2 ? 30 : 10, 5);
  std::mt19937_64 rng(6);
  std::normal_distribution<double> entry(0.0, 1.0);
  GradientMatrix<D> exact;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      exact(r, c) = entry(rng);
    }
  }
  const auto gradient = gradients_of<D>(cloud, linear_velocity<D>(cloud, exact));
  double worst = 0.0;
  for (const auto& l : gradient) {
    worst = std::max(worst, (l - exact).norm() / exact.norm());
  }
  EXPECT_LT(worst, 1e-12) << "Statement 2: least squares reproduce a linear field exactly";
}

TYPED_TEST(ShtcVelocityGradient, IsOddInTheVelocitiesBitForBit) {
  constexpr int D = TypeParam::value;
  const Cloud<D> cloud = jittered_lattice<D>(D == 2 ? 20 : 8, 7);
  const CoordinateArrays<D> v = random_velocity<D>(cloud, 8);
  CoordinateArrays<D> reversed = v;
  for (int k = 0; k < D; ++k) {
    for (double& component : reversed[k]) {
      component = -component;
    }
  }
  expect_same_bits<D>(gradients_of<D>(cloud, v), gradients_of<D>(cloud, reversed), -1.0);
}

TYPED_TEST(ShtcVelocityGradient, IsTheSameForAnyThreadCount) {
  constexpr int D = TypeParam::value;
  const Cloud<D> cloud = jittered_lattice<D>(D == 2 ? 40 : 12, 9);
  const CoordinateArrays<D> v = random_velocity<D>(cloud, 10);
  revsph::set_thread_count(1);
  const auto one = gradients_of<D>(cloud, v);
  revsph::set_thread_count(2);
  expect_same_bits<D>(one, gradients_of<D>(cloud, v), 1.0);
}

TEST(ShtcVelocityGradientSetup, IsZeroForAnIsolatedParticle) {
  const Cloud<2> cloud = revsph::testing::two_isolated_points();
  const revsph::WendlandQuintic<2> kernel(cloud.support);
  const auto gradient =
      revsph::testing::velocity_gradients_of<2>(kernel, cloud.x, cloud.x, cloud.mass);
  EXPECT_EQ(gradient[0], GradientMatrix<2>::Zero());
  EXPECT_EQ(gradient[1], GradientMatrix<2>::Zero());
}

} // namespace
