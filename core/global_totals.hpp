#pragma once
// Totals over every particle of a run, whichever process holds it (docs/design/distributed.md,
// piece 3): what a model reports as an energy or a diagnostic. A model adds its own particles'
// terms into an ExactDoubleSum (exact, so the order of the terms, the thread and the process that
// adds them do not matter) and reads the run's total here; energy.csv then has the same digits
// for any split of the particles. Every process calls these at the same points (they are
// collective), as every process computes the same energies.

#include "core/distributed/processes.hpp"
#include "fixedpoint/exact_double_sum.hpp"
#include "fixedpoint/exact_sum.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace revsph {

using fixedpoint::ExactDoubleSum;

// The run's total of a sum of doubles, correctly rounded once.
inline double global_total(const ExactDoubleSum& own) {
  return distributed::sum_over_processes(own).value();
}

// The run's total of integers (raw fixed-point values summed exactly).
inline fixedpoint::int128 global_total(fixedpoint::int128 own) {
  return distributed::sum_over_processes(own);
}

// The run's number of particles of which this process holds `own`.
inline std::size_t global_count(std::size_t own) {
  return static_cast<std::size_t>(distributed::sum_over_processes(static_cast<std::int64_t>(own)));
}

// The run's largest value (exact in any order).
inline double global_max(double own) {
  return distributed::max_over_processes(own);
}

// The run's total of value(s) over the own slots s of a pair layout (core/slot_layout.hpp; its
// ghost slots are other processes' particles, counted there): an energy account's increment
// from a pair pass's sums, say.
template <class Layout, class Value>
double global_total_over_own_slots(const Layout& layout, const Value& value) {
  ExactDoubleSum sum;
  for (std::size_t s = 0; s < layout.slot_count(); ++s) {
    if (!layout.is_ghost_slot(s)) {
      sum.add(value(s));
    }
  }
  return global_total(sum);
}

// The exact sum of per-particle values.
inline ExactDoubleSum exact_sum_of(std::span<const double> values) {
  ExactDoubleSum sum;
  for (const double value : values) {
    sum.add(value);
  }
  return sum;
}

} // namespace revsph
