#pragma once
// Wall blocks that turn rigidly (particles[].wall_motion = "rigid", README "Wall grip"): in each
// drift every such wall particle's position (about its block's centre) and velocity are turned by
// theta = s |Omega| dt, s the sense of the particle's own motion, the sign of (x - c) x v.
//
// Exactly reversible in fixed point: the rotation is three lifting steps (design note §4),
//   x += round(a y), y += round(b x), x += round(a y),  a = -tan(theta / 2), b = sin(theta),
// each undone exactly by the same step with -a or -b; a and b are odd in theta (computed from
// |theta| and given theta's sign) and the rounding is odd (half away from zero), so the turn by
// -theta is bitwise the inverse of the turn by theta. Under the time reversal R the velocity
// changes sign and with it s (the sign of an exact integer cross product, which a turn keeps:
// |x - c| |v| is many orders above the rounding), so a reversed step turns back by -theta: the
// drift obeys Delta(R y) = -R Delta(y) as §2 requires. The drift with -dt (the sub-step check)
// turns by -theta likewise. Positions are never recomputed from an angle: the lattice points
// themselves turn, and stay within a rounding walk (sqrt(steps) units) of the exact rotation.

#include "core/fault.hpp"
#include "core/state_field.hpp"
#include "fixedpoint/deterministic_math.hpp"
#include "fixedpoint/exact_sum.hpp"
#include "models/two_fluid/parameters.hpp"

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace revsph::two_fluid {

namespace rigid_detail {

// round(c y) for a raw value: the nearest integer, ties away from zero (odd), or c y for the
// floating-point variant.
template <class Raw>
Raw scaled(double c, Raw y) {
  if constexpr (std::is_integral_v<Raw>) {
    return static_cast<Raw>(std::llround(c * static_cast<double>(y)));
  } else {
    return c * y;
  }
}

// The sign of (x - c) x v: exact in 128-bit integers for raw fixed-point values (the two scales
// are positive, so the raw cross product has the physical one's sign).
template <class Raw>
int turning_sense(Raw rx, Raw ry, Raw vx, Raw vy) {
  if constexpr (std::is_integral_v<Raw>) {
    using fixedpoint::int128;
    const int128 cross = static_cast<int128>(rx) * vy - static_cast<int128>(ry) * vx;
    return cross > 0 ? 1 : cross < 0 ? -1 : 0;
  } else {
    const double cross = rx * vy - ry * vx;
    return cross > 0.0 ? 1 : cross < 0.0 ? -1 : 0;
  }
}

// Turns (x, y) by the angle whose lifting coefficients are a, b.
template <class Raw>
void turn(Raw& x, Raw& y, double a, double b) {
  x += scaled(a, y);
  y += scaled(b, x);
  x += scaled(a, y);
}

} // namespace rigid_detail

// Turns the rigid walls' positions and velocities (2D) by their rate times dt.
template <class Arith, class Raw>
void turn_rigid_walls(StateField<Raw>& position, StateField<Raw>& velocity, const RigidWalls& walls,
                      double dt, FaultRecorder& faults) {
  const std::size_t n = position.count();
  const auto& x_scale = position.info().scale;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(walls.rate[i] > 0.0)) {
      continue;
    }
    Raw centre[2];
    if (!Arith::try_from_real(walls.centre[i][0], x_scale, centre[0]) ||
        !Arith::try_from_real(walls.centre[i][1], x_scale, centre[1])) {
      faults.record(i, "wall", "position", "rotation centre outside the fixed-point range");
      continue;
    }
    Raw rx = position.at(0, i) - centre[0];
    Raw ry = position.at(1, i) - centre[1];
    Raw& vx = velocity.at(0, i);
    Raw& vy = velocity.at(1, i);
    const int sense = rigid_detail::turning_sense(rx, ry, vx, vy);
    if (sense == 0) {
      continue; // on the centre, or at rest
    }
    const double theta = sense * walls.rate[i] * dt;
    const double half = dmath::tan(0.5 * std::abs(theta));
    const double a = std::copysign(half, -theta);
    const double b = std::copysign(dmath::sin(std::abs(theta)), theta);
    rigid_detail::turn(rx, ry, a, b);
    rigid_detail::turn(vx, vy, a, b);
    position.at(0, i) = rx + centre[0];
    position.at(1, i) = ry + centre[1];
  }
  faults.throw_if_any();
}

} // namespace revsph::two_fluid
