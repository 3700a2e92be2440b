#pragma once
// The Gresho vortex (Gresho & Chan 1990; paper 1 App. A): a stationary solution of the Euler
// equations with constant density rho0, azimuthal velocity
//   u(r) = 5 r  (r < 0.2),   2 - 5 r  (0.2 <= r < 0.4),   0  (r >= 0.4),
// and the pressure that balances it, dp/dr = rho0 u^2 / r, here with p = 0 outside the vortex:
//   p(r) = rho0 (12.5 r^2 + 2 - 4 ln 2)                    (r < 0.2)
//        = rho0 (12.5 r^2 - 20 r + 4 ln r + 6 - 4 ln 0.4)  (0.2 <= r < 0.4)
//        = 0                                                (r >= 0.4).

#include "fixedpoint/deterministic_math.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace revsph::wcsph::gresho {

inline double azimuthal_velocity(double r) {
  if (r < 0.2) {
    return 5.0 * r;
  }
  return r < 0.4 ? 2.0 - 5.0 * r : 0.0;
}

// The velocity (u_x, u_y) at offset (dx, dy) from the vortex centre: u(r) along e_theta.
inline std::array<double, 2> velocity(double dx, double dy) {
  const double r = dmath::hypot(dx, dy);
  if (!(r > 0.0)) {
    return {0.0, 0.0};
  }
  const double u = azimuthal_velocity(r);
  return {-u * dy / r, u * dx / r};
}

inline double pressure(double r, double rest_density) {
  if (r < 0.2) {
    return rest_density * (12.5 * r * r + 2.0 - 4.0 * std::numbers::ln2);
  }
  if (r < 0.4) {
    return rest_density *
           (12.5 * r * r - 20.0 * r + 4.0 * dmath::log(r) + 6.0 - 4.0 * dmath::log(0.4));
  }
  return 0.0;
}

// The squared L2 norm of the exact velocity field, integral |u|^2 dA = 4 pi / 75: paper 1
// eq. (11) divides by it, so that the zero field has error 1.
inline constexpr double velocity_norm_squared = 4.0 * std::numbers::pi / 75.0;

} // namespace revsph::wcsph::gresho
