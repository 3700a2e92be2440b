#pragma once
// The relaxation of the distortion that makes SHTC-SPH a viscous fluid (paper 2 eqs. 51c, 52d,
// 53): dA/dt = -3 / (tau cs^2) eps_A, integrated over one time step by the classical RK4 scheme
// after the reversible distortion update, as in eq. (52). It lowers the shear energy (d eps_s/dt
// = -3 / (tau cs^2) |eps_A|^2 <= 0): the one dissipative term, outside the reversible step.
// For small strains the symmetric part of A - I decays as exp(-6 t / tau), which gives the
// Navier-Stokes viscosity nu = tau cs^2 / 6 (eqs. 65, 69).

#include "models/shtc/elastic_energy.hpp"

#include <cmath>

namespace revsph::shtc {

// How the relaxation is integrated within one time step of length dt.
struct RelaxationSplitting {
  double relaxation_time = 0.0; // the tau used in eq. (53)
  int substeps = 1;             // RK4 steps of dt / substeps
};

// The paper's splitting (eq. 52): one RK4 step over dt with the case's tau. Split from the
// reversible update, it does not give the viscosity nu: in a steady shear the strain after each
// relaxation is delta R / (1 - R) (delta the strain one update adds, R the RK4 amplification of
// the linearised relaxation over dt, about exp(-x) with x = 6 dt / tau), where the continuous
// equations hold tau / 6 L = delta / x: nu x R / (1 - R), 21 % low at the paper's own dt / tau
// = 0.075 (Taylor-Couette) and 27 % at 0.1 (cavity); unstable (R > 1) beyond dt / tau = 0.46.
inline RelaxationSplitting paper_splitting(double relaxation_time) {
  return {relaxation_time, 1};
}

// The splitting that keeps nu at any dt / tau: RK4 steps whose linear amplification over dt is
// 1 / (1 + x), the value for which the steady strain delta R / (1 - R) is delta / x. One RK4 step
// of length k with rate z / k amplifies by R(z) = 1 - z + z^2/2 - z^3/6 + z^4/24, decreasing on
// [0, 1.5] from 1 to 0.27; the step is cut into enough substeps that each needs z <= 1 (R(1) =
// 0.375), and z is found by bisection.
inline RelaxationSplitting matched_splitting(double relaxation_time, double dt) {
  const double x = 6.0 * dt / relaxation_time;
  auto amplification = [](double z) {
    return 1.0 - z + z * z / 2.0 - z * z * z / 6.0 + z * z * z * z / 24.0;
  };
  int substeps = 1;
  while (std::pow(1.0 + x, -1.0 / substeps) < amplification(1.0)) {
    ++substeps;
  }
  const double target = std::pow(1.0 + x, -1.0 / substeps);
  double low = 0.0;
  double high = 1.0;
  for (int i = 0; i < 80; ++i) {
    const double z = 0.5 * (low + high);
    (amplification(z) > target ? low : high) = z;
  }
  const double z = 0.5 * (low + high);
  return {6.0 * (dt / substeps) / z, substeps};
}

template <int D>
Tensor<D> relax_distortion(const ElasticMaterial& material, double relaxation_time,
                           const Tensor<D>& distortion, double dt) {
  const double cs2 = material.shear_speed * material.shear_speed;
  auto rate = [&](const Tensor<D>& a) -> Tensor<D> {
    return (-3.0 / (relaxation_time * cs2)) * shear_energy_derivative<D>(material, a);
  };
  const Tensor<D> k1 = rate(distortion); // eq. (53), (b1 .. b4) = (1, 1/2, 1/2, 1)
  const Tensor<D> k2 = rate(distortion + 0.5 * dt * k1);
  const Tensor<D> k3 = rate(distortion + 0.5 * dt * k2);
  const Tensor<D> k4 = rate(distortion + dt * k3);
  return distortion + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4); // eq. (52d)
}

template <int D>
Tensor<D> relax_distortion(const ElasticMaterial& material, const RelaxationSplitting& splitting,
                           const Tensor<D>& distortion, double dt) {
  Tensor<D> a = distortion;
  for (int i = 0; i < splitting.substeps; ++i) {
    a = relax_distortion<D>(material, splitting.relaxation_time, a, dt / splitting.substeps);
  }
  return a;
}

} // namespace revsph::shtc
