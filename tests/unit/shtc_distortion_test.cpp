// The exactly invertible distortion update of SHTC-SPH (models/shtc/distortion.hpp): bitwise
// reversal for random velocity gradients, including strong compression and expansion, in 2D
// and 3D; second-order accuracy against the exact solution A0 exp(-t L) of dA/dt = -A L; and
// the difference from the paper's Cayley update shrinking as h^2.

#include "models/shtc/distortion.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include "dimensions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>
#include <vector>

namespace {

using revsph::shtc::DistortionScales;
using revsph::shtc::ExactDistortion;
using revsph::shtc::Matrix;

const DistortionScales scales{revsph::fixedpoint::Scale(-50), revsph::fixedpoint::Scale(-48)};

template <int D>
Matrix<D> random_matrix(std::mt19937_64& rng, double spread) {
  std::normal_distribution<double> entry(0.0, spread);
  Matrix<D> m;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      m(r, c) = entry(rng);
    }
  }
  return m;
}

// A random distortion with det > 0: identity plus a perturbation, scaled.
template <int D>
Matrix<D> random_distortion(std::mt19937_64& rng) {
  Matrix<D> a = Matrix<D>::Identity() + random_matrix<D>(rng, 0.3);
  if (a.determinant() < 0.0) {
    a.col(0) *= -1.0;
  }
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  return scale(rng) * a;
}

// h L for one step: a random gradient, every fourth one with a strong volume change
// (tr(h L) up to +-0.8: compression or expansion by a factor e^0.8 in one step).
template <int D>
Matrix<D> random_step_gradient(std::mt19937_64& rng, int index) {
  Matrix<D> h_l = random_matrix<D>(rng, 0.05);
  if (index % 4 == 0) {
    std::uniform_real_distribution<double> volume(-0.8, 0.8);
    h_l += (volume(rng) / D) * Matrix<D>::Identity();
  }
  return h_l;
}

template <int D>
void expect_single_steps_reverse_exactly(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 10000; ++trial) {
    ExactDistortion<D> a;
    ASSERT_TRUE(revsph::shtc::try_make_distortion<D>(random_distortion<D>(rng), scales, a));
    const ExactDistortion<D> initial = a;
    const Matrix<D> h_l = random_step_gradient<D>(rng, trial);
    ASSERT_TRUE(revsph::shtc::try_update_distortion<D>(a, h_l, scales));
    ASSERT_NE(a.unimodular, initial.unimodular) << "the update must do something";
    ASSERT_TRUE(revsph::shtc::try_update_distortion<D>(a, Matrix<D>(-h_l), scales));
    ASSERT_EQ(a.log_det, initial.log_det) << "trial " << trial;
    ASSERT_EQ(a.unimodular, initial.unimodular) << "trial " << trial;
  }
}

// A trajectory of 10 000 steps, a new gradient every step, run back with the negated gradients
// in reverse order (what the time reversal of the SPH step does).
template <int D>
void expect_trajectory_reverses_exactly(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  ExactDistortion<D> a;
  ASSERT_TRUE(revsph::shtc::try_make_distortion<D>(random_distortion<D>(rng), scales, a));
  const ExactDistortion<D> initial = a;
  std::vector<Matrix<D>> gradients;
  std::normal_distribution<double> drift(0.0, 0.02);
  for (int step = 0; step < 10000; ++step) {
    // Small, volume-preserving on average: the trajectory stays within the scales.
    Matrix<D> h_l = random_matrix<D>(rng, 0.02);
    h_l -= (h_l.trace() / D) * Matrix<D>::Identity();
    h_l += (drift(rng) / D) * Matrix<D>::Identity();
    gradients.push_back(h_l);
    ASSERT_TRUE(revsph::shtc::try_update_distortion<D>(a, h_l, scales)) << "step " << step;
  }
  for (auto g = gradients.rbegin(); g != gradients.rend(); ++g) {
    ASSERT_TRUE(revsph::shtc::try_update_distortion<D>(a, Matrix<D>(-*g), scales));
  }
  EXPECT_EQ(a.log_det, initial.log_det);
  EXPECT_EQ(a.unimodular, initial.unimodular);
}

// For a constant L, n steps of h = t / n against A0 exp(-t L).
template <int D>
double error_after(const Matrix<D>& a0, const Matrix<D>& l, double t, int steps, bool exact) {
  const double h = t / steps;
  const Matrix<D> reference = a0 * Matrix<D>(-t * l).exp();
  if (exact) {
    ExactDistortion<D> a;
    EXPECT_TRUE(revsph::shtc::try_make_distortion<D>(a0, scales, a));
    for (int k = 0; k < steps; ++k) {
      EXPECT_TRUE(revsph::shtc::try_update_distortion<D>(a, Matrix<D>(h * l), scales));
    }
    return (revsph::shtc::to_matrix<D>(a, scales) - reference).norm() / reference.norm();
  }
  Matrix<D> a = a0;
  for (int k = 0; k < steps; ++k) {
    a = revsph::shtc::cayley_update<D>(a, Matrix<D>(h * l));
  }
  return (a - reference).norm() / reference.norm();
}

template <int D>
void expect_second_order(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Matrix<D> a0 = random_distortion<D>(rng);
  const Matrix<D> l = random_matrix<D>(rng, 1.0); // rotation, shear and volume change
  for (const bool exact : {true, false}) {
    const double coarse = error_after<D>(a0, l, 1.0, 50, exact);
    const double fine = error_after<D>(a0, l, 1.0, 100, exact);
    const double finer = error_after<D>(a0, l, 1.0, 200, exact);
    // Second order: halving h divides the error by 4 (3.5–4.5 allows the O(h^3) remainder).
    EXPECT_GT(coarse / fine, 3.5) << (exact ? "lifting" : "Cayley");
    EXPECT_LT(coarse / fine, 4.5) << (exact ? "lifting" : "Cayley");
    EXPECT_GT(fine / finer, 3.5) << (exact ? "lifting" : "Cayley");
    EXPECT_LT(fine / finer, 4.5) << (exact ? "lifting" : "Cayley");
    EXPECT_LT(coarse, 1e-2);
  }
}

// The lifting update and the paper's Cayley update differ by O(h^2) over a fixed time.
template <int D>
void expect_close_to_cayley(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Matrix<D> a0 = random_distortion<D>(rng);
  const Matrix<D> l = random_matrix<D>(rng, 1.0);
  auto difference = [&](int steps) {
    const double h = 1.0 / steps;
    ExactDistortion<D> exact;
    EXPECT_TRUE(revsph::shtc::try_make_distortion<D>(a0, scales, exact));
    Matrix<D> cayley = a0;
    for (int k = 0; k < steps; ++k) {
      EXPECT_TRUE(revsph::shtc::try_update_distortion<D>(exact, Matrix<D>(h * l), scales));
      cayley = revsph::shtc::cayley_update<D>(cayley, Matrix<D>(h * l));
    }
    return (revsph::shtc::to_matrix<D>(exact, scales) - cayley).norm() / cayley.norm();
  };
  const double coarse = difference(50);
  const double fine = difference(100);
  EXPECT_GT(coarse / fine, 3.5);
  EXPECT_LT(coarse / fine, 4.5);
}

REVSPH_DIMENSION_TEST_SUITE(ShtcDistortion);

TYPED_TEST(ShtcDistortion, EachUpdateIsUndoneBitForBit) {
  expect_single_steps_reverse_exactly<TypeParam::value>(10 + TypeParam::value);
}
TYPED_TEST(ShtcDistortion, TrajectoryReturnsBitForBit) {
  expect_trajectory_reverses_exactly<TypeParam::value>(20 + TypeParam::value);
}
TYPED_TEST(ShtcDistortion, IsSecondOrderLikeTheCayleyUpdate) {
  expect_second_order<TypeParam::value>(30 + TypeParam::value);
}
TYPED_TEST(ShtcDistortion, DiffersFromCayleyByOrderHSquared) {
  expect_close_to_cayley<TypeParam::value>(40 + TypeParam::value);
}

TEST(ShtcDistortionSetup, RejectsAnInvertedOrDegenerateDistortion) {
  ExactDistortion<2> a;
  Matrix<2> flipped = Matrix<2>::Identity();
  flipped(0, 0) = -1.0;
  EXPECT_FALSE(revsph::shtc::try_make_distortion<2>(flipped, scales, a));
  EXPECT_FALSE(revsph::shtc::try_make_distortion<2>(Matrix<2>::Zero(), scales, a));
}

} // namespace
