#pragma once
// The exact wrap of positions into their period (core/periodic_box.hpp), in raw units of the
// position field's arithmetic: integers in fixed point (exact, so reversible), doubles in the
// floating-point variant (not reversible anyway).

#include "core/periodic_box.hpp"
#include "core/state_field.hpp"
#include "fixedpoint/conversion.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace revsph {

// A position field's periodic axes in its raw units: lower face and period.
template <class Raw>
struct RawPeriod {
  std::array<bool, 3> periodic{};
  std::array<Raw, 3> lower{};
  std::array<Raw, 3> period{};
};

template <class Raw>
RawPeriod<Raw> raw_period(const VariableInfo& info) {
  RawPeriod<Raw> raw;
  for (int k = 0; k < 3; ++k) {
    raw.periodic[k] = info.period.periodic[k];
    if (!raw.periodic[k]) {
      continue;
    }
    if constexpr (std::is_same_v<Raw, double>) {
      raw.lower[k] = info.period.min[k];
      raw.period[k] = info.period.max[k] - info.period.min[k];
    } else {
      // fill_set checked that both faces fit the scale.
      Raw lower = 0;
      Raw upper = 0;
      fixedpoint::try_to_fixed(info.period.min[k], info.scale, lower);
      fixedpoint::try_to_fixed(info.period.max[k], info.scale, upper);
      raw.lower[k] = lower;
      raw.period[k] = upper - lower;
    }
  }
  return raw;
}

// x into [lower, lower + period).
template <class Raw>
Raw wrapped(Raw x, Raw lower, Raw period) {
  if constexpr (std::is_same_v<Raw, double>) {
    double offset = std::fmod(x - lower, period);
    offset += offset < 0.0 ? period : 0.0;
    return offset >= period ? lower : lower + offset;
  } else {
    Raw offset = (x - lower) % period;
    offset += offset < 0 ? period : 0;
    return lower + offset;
  }
}

// Every particle of the field into the period on its periodic axes (after a drift).
template <class Raw>
void wrap_into_period(StateField<Raw>& position) {
  if (!position.info().period.any()) {
    return;
  }
  const RawPeriod<Raw> raw = raw_period<Raw>(position.info());
  for (int k = 0; k < position.components(); ++k) {
    if (!raw.periodic[k]) {
      continue;
    }
    for (Raw& x : position.component(k)) {
      x = wrapped(x, raw.lower[k], raw.period[k]);
    }
  }
}

} // namespace revsph
