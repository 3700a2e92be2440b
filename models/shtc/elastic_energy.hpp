#pragma once
// Specific internal energy of SHTC-SPH and its derivatives (paper 2, eqs. 28–37):
//   eps(rho, A) = eps_0(rho) + eps_s(A),
//   eps_0 = c0^2 / 2 (rho0 / rho - 1)^2                     (29), eps_rho = p / rho^2 with
//   p = rho^2 d eps_0 / d rho = c0^2 rho0 (1 - rho0 / rho)  (30, 37),
//   DPRZ:        eps_s = cs^2 / 4 |dev(A^T A)|_F^2              (31, 32),
//                eps_A = cs^2 A dev(A^T A)
//   Neo-Hookean: eps_s = cs^2 / 2 (tr B - 3 + 2 ln det A),  B = A^-1 A^-T   (35),
//                eps_A = cs^2 A^-T (I - B)
// and the stress of eq. (21b), T = -eps_rho I + A^T eps_A H^-1.
//
// Two misprints of the journal text are corrected from the preprint (seeds/002_…, eqs. 13, 16,
// 18): eq. (29) reads (rho / rho0 - 1)^2, whose derivative is not the pressure of eqs. (30) and
// (37) (tests/unit/shtc_elastic_energy_test.cpp checks p = rho^2 d eps_0 / d rho); eqs. (33) and
// (36) read -p / rho for the first term of T, where eq. (21b) and the preprint give -p / rho^2
// (the fluid limit of the force, eq. 23, is then the SPH pressure force).
//
// In 2D the distortion is embedded in 3D as plane strain, A33 = 1 (so that dev uses 1/3 as in
// eq. 32 and the energy of the undistorted state is zero); the in-plane block is returned.

#include "fixedpoint/deterministic_math.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace revsph::shtc {

enum class ShearEnergy { dprz, neo_hookean };

struct ElasticMaterial {
  double rest_density = 1.0;
  double sound_speed = 1.0; // c0, bulk
  double shear_speed = 0.0; // cs
  ShearEnergy shear_energy = ShearEnergy::dprz;
};

template <int D>
using Tensor = Eigen::Matrix<double, D, D>;

namespace detail {

template <int D>
Eigen::Matrix3d embed(const Tensor<D>& a) {
  if constexpr (D == 3) {
    return a;
  } else {
    Eigen::Matrix3d full = Eigen::Matrix3d::Identity();
    full.topLeftCorner<2, 2>() = a;
    return full;
  }
}

inline Eigen::Matrix3d deviator(const Eigen::Matrix3d& m) {
  return m - (m.trace() / 3.0) * Eigen::Matrix3d::Identity(); // eq. (32)
}

} // namespace detail

// eps_0 (eq. 29) and p = rho^2 d eps_0 / d rho (eq. 30).
inline double bulk_energy(const ElasticMaterial& material, double density) {
  const double strain = material.rest_density / density - 1.0;
  return 0.5 * material.sound_speed * material.sound_speed * strain * strain;
}
inline double pressure(const ElasticMaterial& material, double density) {
  return material.sound_speed * material.sound_speed * material.rest_density *
         (1.0 - material.rest_density / density);
}

// eps_s (eq. 31 or 35).
template <int D>
double shear_energy(const ElasticMaterial& material, const Tensor<D>& distortion) {
  const Eigen::Matrix3d a = detail::embed<D>(distortion);
  const double cs2 = material.shear_speed * material.shear_speed;
  if (material.shear_energy == ShearEnergy::dprz) {
    return 0.25 * cs2 * detail::deviator(a.transpose() * a).squaredNorm();
  }
  const Eigen::Matrix3d inverse = a.inverse();
  const Eigen::Matrix3d b = inverse * inverse.transpose();
  return 0.5 * cs2 * (b.trace() - 3.0 + 2.0 * dmath::log(a.determinant()));
}

// d eps_s / d A, the in-plane block in 2D.
template <int D>
Tensor<D> shear_energy_derivative(const ElasticMaterial& material, const Tensor<D>& distortion) {
  const Eigen::Matrix3d a = detail::embed<D>(distortion);
  const double cs2 = material.shear_speed * material.shear_speed;
  Eigen::Matrix3d derivative;
  if (material.shear_energy == ShearEnergy::dprz) {
    derivative = cs2 * a * detail::deviator(a.transpose() * a);
  } else {
    const Eigen::Matrix3d inverse = a.inverse();
    const Eigen::Matrix3d b = inverse * inverse.transpose();
    derivative = cs2 * inverse.transpose() * (Eigen::Matrix3d::Identity() - b);
  }
  return derivative.topLeftCorner<D, D>();
}

// The part A^T eps_A H^-1 of T that comes from the distortion: its force is the one paired with
// the velocities in L (eq. 10), hence the power a wall with a prescribed velocity feeds in.
template <int D>
Tensor<D> shear_stress(const ElasticMaterial& material, const Tensor<D>& distortion,
                       const Tensor<D>& h_inverse) {
  return distortion.transpose() * shear_energy_derivative<D>(material, distortion) * h_inverse;
}

// T = -eps_rho I + A^T eps_A H^-1 (eq. 21b), with eps_rho = p / rho^2.
template <int D>
Tensor<D> stress(const ElasticMaterial& material, double density, const Tensor<D>& distortion,
                 const Tensor<D>& h_inverse) {
  const double eps_rho = pressure(material, density) / (density * density);
  return -eps_rho * Tensor<D>::Identity() + shear_stress<D>(material, distortion, h_inverse);
}

} // namespace revsph::shtc
