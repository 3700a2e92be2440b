#pragma once
// The two sub-steps of the velocity-Verlet scheme (paper 1 §4) on state fields, generic over
// the arithmetic and the dimension:
//   kick:  v += round(dt * a(x))   — a is a deterministic function of the positions only;
//   drift: x += round(dt * v)      — odd in v because the rounding is odd-symmetric.
// Both are exactly undone by the same update with -dt (in fixed point), which makes
// kick(dt/2) drift(dt) kick(dt/2) bitwise reversible.

#include "core/fault.hpp"
#include "core/state_field.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace revsph {

// target += dt * rate, component by component. `rate[c][i]` is in the target's unit per second.
template <class Arith, int D>
void add_rate(StateField<typename Arith::Raw>& target,
              const std::array<std::vector<double>, D>& rate, double dt, FaultRecorder& faults) {
  const auto& scale = target.info().scale;
  for (int c = 0; c < D; ++c) {
    auto values = target.component(c);
    const double* r = rate[c].data();
    const std::size_t n = values.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (!Arith::try_increment(values[i], dt * r[i], scale)) {
        faults.record(i, target.info().particle_set.c_str(), target.info().name.c_str(),
                      "overflow or non-finite value in a kick");
      }
    }
  }
  faults.throw_if_any();
}

// position += dt * velocity. The increment dt * v is odd in v bit for bit (IEEE negation and
// odd-symmetric rounding), the condition for the drift to be self-inverse under R.
template <class Arith>
void drift(StateField<typename Arith::Raw>& position,
           const StateField<typename Arith::Raw>& velocity, double dt, FaultRecorder& faults) {
  const auto& x_scale = position.info().scale;
  const auto& v_scale = velocity.info().scale;
  for (int c = 0; c < position.components(); ++c) {
    auto x = position.component(c);
    const auto v = velocity.component(c);
    const std::size_t n = x.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (!Arith::try_increment(x[i], dt * Arith::real(v[i], v_scale), x_scale)) {
        faults.record(i, position.info().particle_set.c_str(), position.info().name.c_str(),
                      "overflow or non-finite value in a drift");
      }
    }
  }
  faults.throw_if_any();
}

} // namespace revsph
