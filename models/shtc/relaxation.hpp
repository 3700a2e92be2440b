#pragma once
// The relaxation of the distortion that makes SHTC-SPH a viscous fluid (paper 2 eqs. 51c, 52d,
// 53): dA/dt = -3 / (tau cs^2) eps_A, integrated over one time step by the classical RK4 scheme
// after the reversible distortion update, as in eq. (52). It lowers the shear energy (d eps_s/dt
// = -3 / (tau cs^2) |eps_A|^2 <= 0): the one dissipative term, outside the reversible step.
// For small strains the symmetric part of A - I decays as exp(-6 t / tau), which gives the
// Navier-Stokes viscosity nu = tau cs^2 / 6 (eqs. 65, 69).

#include "fixedpoint/deterministic_math.hpp"
#include "models/shtc/elastic_energy.hpp"

#include <cmath>
#include <optional>

namespace revsph::shtc {

// How the relaxation is integrated over the time the step gives it (where it goes in the step is
// the case's step.splitting, core/step_splitting.hpp).
struct RelaxationSplitting {
  double relaxation_time = 0.0; // the tau used in eq. (53)
  int substeps = 1;             // RK4 steps per relaxation sub-step
};

// The paper's splitting (eq. 52): one RK4 step over dt with the case's tau, right after the
// distortion update. In a steady shear the strain after each relaxation is then delta R / (1 - R)
// (delta the strain one update adds, R the RK4 amplification of the linearised relaxation over
// dt, about exp(-x) with x = 6 dt / tau) where the continuous equations hold tau / 6 L = delta / x:
// the viscosity is nu x R / (1 - R), 21 % low at the paper's own dt / tau = 0.075 (Taylor-Couette)
// and 27 % at 0.1 (cavity); unstable (R > 1) beyond dt / tau = 0.46. And the second kick feels
// the relaxed stress while the update raised the elastic energy with the unrelaxed one, so the
// energy budget closes only to first order in dt (tests/system/shtc_test.cpp).
inline RelaxationSplitting paper_splitting(double relaxation_time) {
  return {relaxation_time, 1};
}

namespace detail {

// RK4 steps over `length` whose linearised amplification is `target`: one RK4 step of rate z /
// k amplifies by R(z) = 1 - z + z^2/2 - z^3/6 + z^4/24, decreasing on [0, 1.5] from 1 to 0.27;
// the length is cut into enough substeps that each needs z <= 1 (R(1) = 0.375), z by bisection.
inline RelaxationSplitting amplifying_by(double target, double length) {
  auto amplification = [](double z) {
    return 1.0 - z + z * z / 2.0 - z * z * z / 6.0 + z * z * z * z / 24.0;
  };
  int substeps = 1;
  while (dmath::pow(target, 1.0 / substeps) < amplification(1.0)) {
    ++substeps;
  }
  const double per_substep = dmath::pow(target, 1.0 / substeps);
  double low = 0.0;
  double high = 1.0;
  for (int i = 0; i < 80; ++i) {
    const double z = 0.5 * (low + high);
    (amplification(z) > per_substep ? low : high) = z;
  }
  const double z = 0.5 * (low + high);
  return {6.0 * (length / substeps) / z, substeps};
}

} // namespace detail

// Where the paper's splitting does, with the rate that keeps nu at any dt / tau: amplification
// 1 / (1 + x) over dt, for which the steady strain delta R / (1 - R) is delta / x. The energy
// budget is still that of the paper's splitting.
inline RelaxationSplitting matched_splitting(double relaxation_time, double dt) {
  return detail::amplifying_by(1.0 / (1.0 + 6.0 * dt / relaxation_time), dt);
}

// Relaxation over dt / 2 at both ends of the step. The reversible part then pairs the elastic
// energy the update adds with the kinetic energy the kicks take, to O(dt^2) as without
// relaxation, and the relaxation's removal is counted exactly: the budget closes. Between the
// kick ending one step and the kick starting the next the strain goes from delta / (1 - R) to
// delta R / (1 - R) (R over a whole dt); their mean is delta / x, i.e. nu, for R = (2 - x) / (2
// + x), which is what the two halves give. Needs x < 2, i.e. dt / tau < 1/3 (std::nullopt
// beyond).
inline std::optional<RelaxationSplitting> step_ends_splitting(double relaxation_time, double dt) {
  const double x = 6.0 * dt / relaxation_time;
  if (!(x < 2.0)) {
    return std::nullopt;
  }
  return detail::amplifying_by(std::sqrt((2.0 - x) / (2.0 + x)), 0.5 * dt);
}

// One relaxation over dt between the halves of the distortion update (step.splitting =
// "midpoint"): the kicks see s_end = R (s_start + delta / 2) + delta / 2, steady at delta (1 + R)
// / (2 (1 - R)), which is delta / x, i.e. nu, for the same R = (2 - x) / (2 + x) over dt as the
// two halves at the step's ends give. Needs x < 2 too (std::nullopt beyond).
inline std::optional<RelaxationSplitting> midpoint_splitting(double relaxation_time, double dt) {
  const double x = 6.0 * dt / relaxation_time;
  if (!(x < 2.0)) {
    return std::nullopt;
  }
  return detail::amplifying_by((2.0 - x) / (2.0 + x), dt);
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
