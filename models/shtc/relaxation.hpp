#pragma once
// The relaxation of the distortion that makes SHTC-SPH a viscous fluid (paper 2 eqs. 51c, 52d,
// 53): dA/dt = -3 / (tau cs^2) eps_A, integrated over one time step by the classical RK4 scheme
// after the reversible distortion update, as in eq. (52). It lowers the shear energy (d eps_s/dt
// = -3 / (tau cs^2) |eps_A|^2 <= 0): the one dissipative term, outside the reversible step.
// For small strains the symmetric part of A - I decays as exp(-6 t / tau), which gives the
// Navier-Stokes viscosity nu = tau cs^2 / 6 (eqs. 65, 69).

#include "models/shtc/elastic_energy.hpp"

namespace revsph::shtc {

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

} // namespace revsph::shtc
