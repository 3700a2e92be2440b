// The relaxation of the distortion (models/shtc/relaxation.hpp, paper 2 eqs. 51-53): a small
// symmetric strain decays as exp(-6 t / tau) (the viscosity nu = tau cs^2 / 6 of eq. 65), and the
// shear energy never increases, for large distortions too and both shear energies.

#include "models/shtc/relaxation.hpp"

#include "dimensions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using revsph::shtc::ElasticMaterial;
using revsph::shtc::ShearEnergy;
using revsph::shtc::Tensor;

template <class Dimension>
class ShtcRelaxation : public revsph::testing::DimensionTest<Dimension> {};
TYPED_TEST_SUITE(ShtcRelaxation, revsph::testing::Dimensions);

TYPED_TEST(ShtcRelaxation, SmallStrainDecaysWithTheViscousRate) {
  constexpr int D = TypeParam::value;
  const double tau = 0.3;
  for (const ShearEnergy model : {ShearEnergy::dprz, ShearEnergy::neo_hookean}) {
    const ElasticMaterial material{1.0, 20.0, 20.0, model};
    Tensor<D> strain = Tensor<D>::Zero();
    strain(0, 1) = strain(1, 0) = 1e-5; // symmetric and trace-free: pure shear
    Tensor<D> a = Tensor<D>::Identity() + strain;
    const int steps = 200;
    const double duration = tau / 6.0; // one e-folding time of the strain
    for (int s = 0; s < steps; ++s) {
      a = revsph::shtc::relax_distortion<D>(material, tau, a, duration / steps);
    }
    const Tensor<D> left = a - Tensor<D>::Identity();
    EXPECT_NEAR(left(0, 1), 1e-5 * std::exp(-1.0), 1e-9);
    EXPECT_NEAR(left(1, 0), 1e-5 * std::exp(-1.0), 1e-9);
  }
}

TYPED_TEST(ShtcRelaxation, ShearEnergyNeverIncreases) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(8);
  std::normal_distribution<double> entry(0.0, 0.3);
  for (const ShearEnergy model : {ShearEnergy::dprz, ShearEnergy::neo_hookean}) {
    const ElasticMaterial material{1.0, 20.0, 20.0, model};
    const double tau = 6.0 * 0.01 / (20.0 * 20.0); // nu = 0.01
    for (int trial = 0; trial < 200; ++trial) {
      Tensor<D> a = Tensor<D>::Identity();
      for (int r = 0; r < D; ++r) {
        for (int c = 0; c < D; ++c) {
          a(r, c) += entry(rng);
        }
      }
      if (a.determinant() < 0.2) {
        continue;
      }
      double energy = revsph::shtc::shear_energy<D>(material, a);
      for (int s = 0; s < 20; ++s) {
        a = revsph::shtc::relax_distortion<D>(material, tau, a, 0.05 * tau);
        const double relaxed = revsph::shtc::shear_energy<D>(material, a);
        ASSERT_LE(relaxed, energy * (1.0 + 1e-14)) << "trial " << trial << " step " << s;
        energy = relaxed;
      }
    }
  }
}

} // namespace
