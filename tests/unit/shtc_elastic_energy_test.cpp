// SHTC-SPH energies (models/shtc/elastic_energy.hpp): zero energy and stress-free at rest, the
// analytic derivatives against central finite differences, frame indifference, the pressure as
// rho^2 d eps_0 / d rho, and the fluid limit of the stress.

#include "models/shtc/elastic_energy.hpp"

#include "dimensions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

namespace {

using revsph::shtc::ElasticMaterial;
using revsph::shtc::ShearEnergy;
using revsph::shtc::Tensor;

ElasticMaterial material(ShearEnergy model) {
  return {1000.0, 50.0, 20.0, model};
}

template <int D>
Tensor<D> random_distortion(std::mt19937_64& rng) {
  std::normal_distribution<double> entry(0.0, 0.15);
  Tensor<D> a = Tensor<D>::Identity();
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      a(r, c) += entry(rng);
    }
  }
  return a;
}

template <int D>
Tensor<D> random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> entry(0.0, 1.0);
  Tensor<D> m;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      m(r, c) = entry(rng);
    }
  }
  Tensor<D> q = Eigen::HouseholderQR<Tensor<D>>(m).householderQ();
  if (q.determinant() < 0.0) {
    q.col(0) *= -1.0;
  }
  return q;
}

REVSPH_DIMENSION_TEST_SUITE(ShtcElasticEnergy);

TYPED_TEST(ShtcElasticEnergy, VanishesAtRest) {
  constexpr int D = TypeParam::value;
  for (const ShearEnergy model : {ShearEnergy::dprz, ShearEnergy::neo_hookean}) {
    const ElasticMaterial m = material(model);
    EXPECT_NEAR(revsph::shtc::shear_energy<D>(m, Tensor<D>::Identity()), 0.0, 1e-12);
    EXPECT_LT(revsph::shtc::shear_energy_derivative<D>(m, Tensor<D>::Identity()).norm(), 1e-12);
  }
}

// check(material, A, rng) for both shear energies and 20 random distortions each.
template <int D, class Check>
void for_random_distortions(std::uint64_t seed, Check&& check) {
  std::mt19937_64 rng(seed);
  for (const ShearEnergy model : {ShearEnergy::dprz, ShearEnergy::neo_hookean}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Tensor<D> a = random_distortion<D>(rng);
      check(material(model), a, rng);
    }
  }
}

TYPED_TEST(ShtcElasticEnergy, DerivativeMatchesFiniteDifferences) {
  constexpr int D = TypeParam::value;
  for_random_distortions<D>(3, [](const ElasticMaterial& m, const Tensor<D>& a, auto&) {
    const Tensor<D> analytic = revsph::shtc::shear_energy_derivative<D>(m, a);
    const double step = 1e-6;
    for (int r = 0; r < D; ++r) {
      for (int c = 0; c < D; ++c) {
        Tensor<D> plus = a;
        Tensor<D> minus = a;
        plus(r, c) += step;
        minus(r, c) -= step;
        const double numeric =
            (revsph::shtc::shear_energy<D>(m, plus) - revsph::shtc::shear_energy<D>(m, minus)) /
            (2.0 * step);
        // Central differences: O(step^2) truncation, O(eps * |eps_s| / step) rounding.
        EXPECT_NEAR(analytic(r, c), numeric, 1e-5 * (1.0 + analytic.norm()))
            << "entry " << r << c
            << (m.shear_energy == ShearEnergy::dprz ? " DPRZ" : " Neo-Hookean");
      }
    }
  });
}

TYPED_TEST(ShtcElasticEnergy, IsFrameIndifferent) {
  constexpr int D = TypeParam::value;
  for_random_distortions<D>(4, [](const ElasticMaterial& m, const Tensor<D>& a, auto& rng) {
    const Tensor<D> q = random_rotation<D>(rng);
    // A = dX/dx: a rotation of the spatial frame, x' = Q x, gives A' = A Q^T.
    const double original = revsph::shtc::shear_energy<D>(m, a);
    const double rotated = revsph::shtc::shear_energy<D>(m, Tensor<D>(a * q.transpose()));
    EXPECT_NEAR(rotated, original, 1e-10 * std::fabs(original));
  });
}

TEST(ShtcBulkEnergy, PressureIsRhoSquaredTimesTheDensityDerivative) {
  const ElasticMaterial m = material(ShearEnergy::dprz);
  for (const double density : {950.0, 1000.0, 1042.0}) {
    const double step = 1e-4;
    const double derivative = (revsph::shtc::bulk_energy(m, density + step) -
                               revsph::shtc::bulk_energy(m, density - step)) /
                              (2.0 * step);
    EXPECT_NEAR(revsph::shtc::pressure(m, density), density * density * derivative,
                1e-6 * m.sound_speed * m.sound_speed * m.rest_density);
  }
}

TEST(ShtcStress, FluidLimitIsTheSphPressureTerm) {
  ElasticMaterial fluid = material(ShearEnergy::dprz);
  fluid.shear_speed = 0.0;
  std::mt19937_64 rng(5);
  const Tensor<2> a = random_distortion<2>(rng);
  const Tensor<2> h_inverse = -Tensor<2>::Identity() / 900.0; // H is negative definite
  const double density = 1010.0;
  const Tensor<2> t = revsph::shtc::stress<2>(fluid, density, a, h_inverse);
  const double expected = -revsph::shtc::pressure(fluid, density) / (density * density);
  EXPECT_DOUBLE_EQ(t(0, 0), expected);
  EXPECT_DOUBLE_EQ(t(1, 1), expected);
  EXPECT_EQ(t(0, 1), 0.0);
}

} // namespace
