#pragma once
// The tensile penalty of SHTC-SPH (paper 2, eqs. 39–42): an energy that keeps d rho / d h small,
//   lambda_a = sum_b m_b h dw_ab/dh + C_lambda,a   (40, the sum includes b = a; kernel_sums.hpp)
//   P_h      = 1/2 sum_a m_a cp^2 (lambda_a / rho0)^2               (39)
//   a_a      = -sum_b m_b cp^2 (lambda_a + lambda_b) / rho0^2 (h/r) d2w/(dr dh) x_ab   (41, 42)
// The pair loop that adds the acceleration is forces.hpp's, with the stress; the acceleration is
// exactly -grad_a P_h / m_a (tests/unit/shtc_tensile_penalty_test.cpp checks it against finite
// differences of P_h).

#include "core/kernel_wendland.hpp"

#include <span>

namespace revsph::shtc {

struct PenaltyParameters {
  double penalty_speed = 0.0; // cp
  double rest_density = 1.0;  // rho0
};

template <int D>
double penalty_energy(const PenaltyParameters& parameters, std::span<const double> mass,
                      std::span<const double> lambda) {
  double energy = 0.0;
  for (std::size_t a = 0; a < mass.size(); ++a) {
    const double relative = lambda[a] / parameters.rest_density;
    energy +=
        0.5 * mass[a] * parameters.penalty_speed * parameters.penalty_speed * relative * relative;
  }
  return energy;
}

// The pair factor F of the penalty acceleration: a_a -= m_b F x_ab, a_b += m_a F x_ab.
template <int D>
double penalty_pair_factor(const WendlandQuintic<D>& kernel, double strength, double lambda_a,
                           double lambda_b, double r) {
  return strength * (lambda_a + lambda_b) * kernel.scale_derivative_of_derivative_over_r(r);
}

// cp^2 / rho0^2, the strength of the penalty force.
inline double penalty_strength(const PenaltyParameters& parameters) {
  return parameters.penalty_speed * parameters.penalty_speed /
         (parameters.rest_density * parameters.rest_density);
}

} // namespace revsph::shtc
