#pragma once
// A parallel loop over one field's particles that carries the fault bookkeeping: update(i) does
// particle i's update and returns false where the new value does not fit (an overflow, a
// non-finite value). Such a particle is recorded against `field` (named by its set, as the state
// declares it) with `reason`, and after the loop the lowest-index one is thrown as a
// SimulationFault (core/fault.hpp): every model's per-particle updates report alike.

#include "core/fault.hpp"
#include "core/state_field.hpp"

#include <cstddef>

namespace revsph {

template <class Raw, class Update>
void update_each_particle(const StateField<Raw>& field, const char* reason, const Update& update) {
  FaultRecorder faults;
  const std::size_t n = field.count();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!update(i)) {
      faults.record(i, field.info().particle_set.c_str(), field.info().name.c_str(), reason);
    }
  }
  faults.throw_if_any();
}

} // namespace revsph
