// The relaxation of the distortion (models/shtc/relaxation.hpp, paper 2 eqs. 51-53): a small
// symmetric strain decays as exp(-6 t / tau) (the viscosity nu = tau cs^2 / 6 of eq. 65), and the
// shear energy never increases, for large distortions too and both shear energies; split from the
// distortion update, the paper's splitting loses viscosity as dt / tau grows and the matched one
// keeps it.

#include "models/shtc/relaxation.hpp"

#include "dimensions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using revsph::shtc::ElasticMaterial;
using revsph::shtc::ShearEnergy;
using revsph::shtc::Tensor;

REVSPH_DIMENSION_TEST_SUITE(ShtcRelaxation);

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

// The shear stress A^T eps_A (frame-indifferent, so steady although A keeps turning) that a
// steady simple shear of rate 1 reaches when each step updates A <- A (I - dt L) (exact: L^2 = 0)
// and then relaxes it, in 2D.
double steady_shear_stress(const revsph::shtc::RelaxationSplitting& splitting, double dt) {
  const ElasticMaterial material{1.0, 20.0, 20.0, ShearEnergy::dprz};
  Tensor<2> velocity_gradient = Tensor<2>::Zero();
  velocity_gradient(0, 1) = 1.0;
  const Tensor<2> update = Tensor<2>::Identity() - dt * velocity_gradient;
  Tensor<2> a = Tensor<2>::Identity();
  const int steps = static_cast<int>(std::ceil(40.0 * splitting.relaxation_time / dt)) + 40;
  for (int s = 0; s < steps; ++s) {
    a = revsph::shtc::relax_distortion<2>(material, splitting, a * update, dt);
  }
  const Tensor<2> stress = a.transpose() * revsph::shtc::shear_energy_derivative<2>(material, a);
  return stress(0, 1);
}

TEST(ShtcRelaxationSplitting, MatchedSplittingKeepsTheViscosityAtLargeTimeSteps) {
  const double tau = 6.0 * 0.01 / (20.0 * 20.0); // nu = 0.01, cs = 20 (cavity at Re 100)
  // Newtonian: the stress of the distortion is nu times the shear rate (1), up to its sign (the
  // sign of the paper's splitting at dt / tau = 1e-3, where it is the continuous relaxation).
  const double reference =
      std::copysign(0.01, steady_shear_stress(revsph::shtc::paper_splitting(tau), 1e-3 * tau));
  for (const double ratio : {0.075, 0.3, 1.0, 3.0}) {
    const double dt = ratio * tau;
    const double matched = steady_shear_stress(revsph::shtc::matched_splitting(tau, dt), dt);
    EXPECT_NEAR(matched / reference, 1.0, 2e-3) << "dt / tau = " << ratio;
    // The paper's splitting: nu x R / (1 - R), x = 6 dt / tau, R the RK4 amplification
    // (relaxation.hpp); 0.79 nu at dt / tau = 0.075, 0.72 nu at 0.3.
    const double paper = steady_shear_stress(revsph::shtc::paper_splitting(tau), dt);
    const double x = 6.0 * ratio;
    const double r = 1.0 - x + x * x / 2.0 - x * x * x / 6.0 + x * x * x * x / 24.0;
    if (ratio <= 0.3) { // beyond, one RK4 step over dt amplifies
      EXPECT_NEAR(paper / reference, x * r / (1.0 - r), 0.01) << "dt / tau = " << ratio;
      EXPECT_LT(paper / reference, 0.8) << "dt / tau = " << ratio;
    }
  }
}

} // namespace
