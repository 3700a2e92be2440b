#pragma once
// The fixed-point scales of SHTC-SPH's pair sums (core/pair_sum.hpp sums every term exactly at
// its quantity's scale, so the sums do not depend on the cell size or the thread count). Each
// resolves its typical magnitude with 48 bits and reaches 2^15 times it.

#include "fixedpoint/scale.hpp"

#include <algorithm>

namespace revsph::shtc {

struct SumScales {
  // rho, lambda (eqs. 7, 40; also the constants C_rho, C_lambda) and H (eq. 21a, about -rho I).
  fixedpoint::Scale density;
  // sum_b m_b v_ab (x) grad w_ab of eq. (10): up to about rho0 c0 / h.
  fixedpoint::Scale velocity_sum;
  // The acceleration of eq. (48) / m: about max(c0, cp)^2 / h.
  fixedpoint::Scale acceleration;
  // The mirrored walls' sum_a m_a w_ab v_a (mirrored_walls.hpp): about rho0 c0.
  fixedpoint::Scale mirror_velocity_sum;
};

inline SumScales sum_scales(const fixedpoint::Scale& density_scale, double rest_density,
                            double sound_speed, double penalty_speed, double support_radius) {
  const double fastest = std::max(sound_speed, penalty_speed);
  return {density_scale,
          fixedpoint::Scale::covering(rest_density * sound_speed / support_radius, 48),
          fixedpoint::Scale::covering(fastest * fastest / support_radius, 48),
          fixedpoint::Scale::covering(rest_density * sound_speed, 48)};
}

} // namespace revsph::shtc
