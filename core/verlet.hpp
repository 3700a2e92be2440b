#pragma once
// The two sub-steps of the velocity-Verlet scheme (paper 1 §4) on state fields, generic over
// the arithmetic and the dimension:
//   kick:  v += round(dt * a(x))   — a is a deterministic function of the positions only;
//   drift: x += round(dt * v)      — odd in v because the rounding is odd-symmetric.
// Both are exactly undone by the same update with -dt (in fixed point), which makes
// kick(dt/2) drift(dt) kick(dt/2) bitwise reversible.

#include "core/arithmetic.hpp"
#include "core/fault.hpp"
#include "core/periodic_wrap.hpp"
#include "core/state_field.hpp"
#include "fixedpoint/conversion.hpp"

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace revsph {

// target += dt * rate(c, i), component by component, rate in the target's unit per second. The
// rate is read where it was computed (a pair sum in slot order, say): no copy, no region of its
// own.
template <class Arith, class Rate>
requires std::invocable<const Rate&, int, std::size_t>
void add_rate(StateField<typename Arith::Raw>& target, const Rate& rate, double dt,
              FaultRecorder& faults, const char* fault = "overflow or non-finite value in a kick") {
  const auto& scale = target.info().scale;
  const std::size_t n = target.count();
  const int components = target.components();
  // One parallel region for all components: every region is a barrier, and a busy machine
  // makes each one cost a time slice (issue 15).
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < components; ++c) {
      if (!Arith::try_increment(target.at(c, i), dt * rate(c, i), scale)) {
        faults.record(i, target.info().particle_set.c_str(), target.info().name.c_str(), fault);
      }
    }
  }
  faults.throw_if_any();
}

// The same with the rate as arrays, rate[c][i].
template <class Arith, int D>
void add_rate(StateField<typename Arith::Raw>& target,
              const std::array<std::vector<double>, D>& rate, double dt, FaultRecorder& faults) {
  add_rate<Arith>(
      target, [&rate](int c, std::size_t i) { return rate[c][i]; }, dt, faults);
}

// target += the pair loop's totals of quantities first_quantity.. (one per component), summed
// at the target's own scale (pair impulses tau f_ab, say): in fixed point the exact integer
// totals are added without a rounding of their own, so equal and opposite pair terms change the
// sum over particles by exactly zero, and a reversed update subtracts bit for bit what this one
// added. `slots` maps the target's particles to the loop's slots.
template <class Arith, class Sums>
void add_pair_totals(StateField<typename Arith::Raw>& target, const Sums& sums, int first_quantity,
                     std::span<const std::uint32_t> slots, FaultRecorder& faults) {
  const int components = target.components();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < slots.size(); ++i) {
    for (int c = 0; c < components; ++c) {
      auto& raw = target.at(c, i);
      bool ok = true;
      if constexpr (Arith::kind == Arithmetic::fixed) {
        ok = fixedpoint::try_add(raw, sums.raw_total(first_quantity + c, slots[i]), raw);
      } else {
        raw += sums.value(first_quantity + c, slots[i]);
        ok = std::isfinite(raw);
      }
      if (!ok) {
        faults.record(i, target.info().particle_set.c_str(), target.info().name.c_str(),
                      "overflow or non-finite value in an update");
      }
    }
  }
  faults.throw_if_any();
}

// position += dt * velocity, then the wrap into a periodic domain (core/periodic_wrap.hpp: addition
// modulo the period, exactly undone by the reversed drift's). The increment dt * v is odd in v bit for bit (IEEE negation and
// odd-symmetric rounding), the condition for the drift to be self-inverse under R.
template <class Arith>
void drift(StateField<typename Arith::Raw>& position,
           const StateField<typename Arith::Raw>& velocity, double dt, FaultRecorder& faults) {
  const auto& v_scale = velocity.info().scale;
  add_rate<Arith>(
      position, [&](int c, std::size_t i) { return Arith::real(velocity.at(c, i), v_scale); }, dt,
      faults, "overflow or non-finite value in a drift");
  wrap_into_period(position);
}

// position += dt * momentum / mass, for a state that keeps momenta (two masses, say): dt (-p) / m
// is -(dt p / m) bit for bit, so the drift is odd in p and self-inverse under R like drift().
template <class Arith>
void drift_by_momentum(StateField<typename Arith::Raw>& position,
                       const StateField<typename Arith::Raw>& momentum,
                       std::span<const double> mass, double dt, FaultRecorder& faults) {
  const auto& p_scale = momentum.info().scale;
  add_rate<Arith>(
      position,
      [&](int c, std::size_t i) { return Arith::real(momentum.at(c, i), p_scale) / mass[i]; }, dt,
      faults, "overflow or non-finite value in a drift");
  wrap_into_period(position);
}

} // namespace revsph
