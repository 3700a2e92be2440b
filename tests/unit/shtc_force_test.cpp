// The SHTC-SPH force (models/shtc/forces.hpp, paper 2 eq. 48) is what conserves the energy of
// eq. (24): along any motion x -> x + e v with the distortion carried by dA = -A L de (eq. 16),
// dU/de = -sum_a m_a a_a . v_a (eq. 22). Checked by central differences of the total internal
// energy (volumetric + shear + penalty) on a disordered cloud with random distortions, for both
// shear energies, in 2D and 3D. A missing factor, a wrong sign or a transposed stress fails it.

#include "models/shtc/distortion.hpp"
#include "models/shtc/elastic_energy.hpp"
#include "models/shtc/forces.hpp"
#include "models/shtc/velocity_gradient.hpp"

#include "cell_ordered_cloud.hpp"
#include "dimensions.hpp"
#include "shtc_sums.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace revsph::shtc {
namespace {

template <int D>
struct Problem {
  revsph::testing::Cloud<D> cloud;
  std::vector<GradientMatrix<D>> distortion;
  std::vector<double> lambda_constant;
  ElasticMaterial material;
  revsph::shtc::PenaltyParameters penalty;
};

// Volumetric + shear + penalty energy at positions x and distortions a.
template <int D>
double internal_energy(const Problem<D>& p, const CoordinateArrays<D>& x,
                       const std::vector<GradientMatrix<D>>& a) {
  const revsph::WendlandQuintic<D> kernel(p.cloud.support);
  const auto sums = revsph::testing::kernel_sums_of<D>(kernel, x, p.cloud.mass, p.lambda_constant);
  double energy = revsph::shtc::penalty_energy<D>(p.penalty, p.cloud.mass, sums.lambda);
  for (std::size_t i = 0; i < p.cloud.mass.size(); ++i) {
    energy += p.cloud.mass[i] * (revsph::shtc::bulk_energy(p.material, sums.density[i]) +
                                 revsph::shtc::shear_energy<D>(p.material, a[i]));
  }
  return energy;
}

REVSPH_DIMENSION_TEST_SUITE(ShtcForce);

TYPED_TEST(ShtcForce, IsMinusTheEnergyRateAlongTheDistortionFlow) {
  constexpr int D = TypeParam::value;
  for (const ShearEnergy model : {ShearEnergy::dprz, ShearEnergy::neo_hookean}) {
    Problem<D> p{revsph::testing::jittered_lattice<D>(D == 2 ? 12 : 6, 21), {}, {}, {}, {}};
    const std::size_t n = p.cloud.mass.size();
    const revsph::WendlandQuintic<D> kernel(p.cloud.support);
    // rho ~ 100 on this cloud (masses ~1, spacing 0.1): rho0 = 90 gives real pressures.
    p.material = {90.0, 3.0, 2.0, model};
    p.penalty = {1.5, p.material.rest_density};
    std::mt19937_64 rng(5);
    std::normal_distribution<double> entry(0.0, 0.1);
    for (std::size_t i = 0; i < n; ++i) {
      GradientMatrix<D> a = GradientMatrix<D>::Identity();
      for (int r = 0; r < D; ++r) {
        for (int c = 0; c < D; ++c) {
          a(r, c) += entry(rng);
        }
      }
      p.distortion.push_back(a);
      p.lambda_constant.push_back(20.0 * entry(rng));
    }
    CoordinateArrays<D> v;
    for (int k = 0; k < D; ++k) {
      for (std::size_t i = 0; i < n; ++i) {
        v[k].push_back(entry(rng) * 10.0);
      }
    }

    const auto sums =
        revsph::testing::kernel_sums_of<D>(kernel, p.cloud.x, p.cloud.mass, p.lambda_constant);
    std::vector<GradientMatrix<D>> stress(n);
    for (std::size_t i = 0; i < n; ++i) {
      stress[i] =
          revsph::shtc::stress<D>(p.material, sums.density[i], p.distortion[i], sums.h_inverse[i]);
    }
    const CoordinateArrays<D> acceleration =
        revsph::testing::acceleration_of<D>(kernel, revsph::shtc::penalty_strength(p.penalty),
                                            p.cloud.x, p.cloud.mass, stress, sums.lambda);
    double power = 0.0; // sum_a m_a a_a . v_a
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < D; ++k) {
        power += p.cloud.mass[i] * acceleration[k][i] * v[k][i];
      }
    }
    const auto gradient =
        revsph::testing::velocity_gradients_of<D>(kernel, p.cloud.x, v, p.cloud.mass);
    auto moved = [&](double e) {
      CoordinateArrays<D> x = p.cloud.x;
      std::vector<GradientMatrix<D>> a(n);
      for (std::size_t i = 0; i < n; ++i) {
        for (int k = 0; k < D; ++k) {
          x[k][i] += e * v[k][i];
        }
        a[i] = revsph::shtc::cayley_update<D>(p.distortion[i], e * gradient[i]); // A exp(-e L)
      }
      return internal_energy<D>(p, x, a);
    };
    const double e = 1e-6;
    const double rate = (moved(e) - moved(-e)) / (2.0 * e);
    ASSERT_GT(std::fabs(power), 1.0) << "the check needs a real energy exchange";
    EXPECT_NEAR(rate, -power, 1e-6 * std::fabs(power))
        << (model == ShearEnergy::dprz ? "DPRZ" : "Neo-Hookean");
  }
}

} // namespace
} // namespace revsph::shtc
