#pragma once
// Totals over every particle of a run, whichever process holds it (docs/design/distributed.md,
// piece 3): what a model reports as an energy or a diagnostic. A model adds its own particles'
// terms into an ExactDoubleSum (exact, so the order of the terms, the thread and the process that
// adds them do not matter) and reads the run's total here; energy.csv then has the same digits
// for any split of the particles. Every process calls these at the same points (they are
// collective), as every process computes the same energies.

#include "core/distributed/processes.hpp"
#include "core/distributed/records_of_every_process.hpp"
#include "core/run_total.hpp"
#include "fixedpoint/exact_double_sum.hpp"
#include "fixedpoint/exact_sum.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace revsph {

using fixedpoint::ExactDoubleSum;

// The run's total of a sum of doubles, correctly rounded once.
inline RunTotal global_total(const ExactDoubleSum& own) {
  return RunTotal::same_on_every_process(distributed::sum_over_processes(own).value());
}

// The run's total of integers (raw fixed-point values summed exactly).
inline fixedpoint::int128 global_total(fixedpoint::int128 own) {
  return distributed::sum_over_processes(own);
}

// The run's total of raw fixed-point values, as a real number: value_of_one is the real value of
// the raw value 1 (fixedpoint::to_real(1, scale)).
inline RunTotal global_total_real(fixedpoint::int128 own, double value_of_one) {
  return RunTotal::same_on_every_process(static_cast<double>(global_total(own))) * value_of_one;
}

// The run's number of particles of which this process holds `own`.
inline std::size_t global_count(std::size_t own) {
  return static_cast<std::size_t>(distributed::sum_over_processes(static_cast<std::int64_t>(own)));
}

// The run's largest value (exact in any order).
inline RunTotal global_max(double own) {
  return RunTotal::same_on_every_process(distributed::max_over_processes(own));
}

// The run's total of value(s) over the own slots s of a pair layout (core/slot_layout.hpp; its
// ghost slots are other processes' particles, counted there): an energy account's increment
// from a pair pass's sums, say.
template <class Layout, class Value>
RunTotal global_total_over_own_slots(const Layout& layout, const Value& value) {
  ExactDoubleSum sum;
  for (std::size_t s = 0; s < layout.slot_count(); ++s) {
    if (!layout.is_ghost_slot(s)) {
      sum.add(value(s));
    }
  }
  return global_total(sum);
}

// A value at the particle nearest a point (a probe's reading): offer every particle held here, by
// its index in the run (SlotLayout::run_index); the run's reading is the nearest particle's, the
// lowest index of equally near ones, as one process looping over the particles in order finds.
struct NearestParticle {
  double distance = std::numeric_limits<double>::infinity();
  std::uint64_t run_index = std::numeric_limits<std::uint64_t>::max();
  double value = 0.0;

  void offer(double particle_distance, std::uint64_t particle_run_index, double particle_value) {
    if (particle_distance < distance ||
        (particle_distance == distance && particle_run_index < run_index)) {
      distance = particle_distance;
      run_index = particle_run_index;
      value = particle_value;
    }
  }
};

// The run's nearest particle's value (collective).
inline RunTotal global_value_of_nearest(const NearestParticle& own) {
  const std::vector<NearestParticle> nearest = distributed::combined_in_rank_order(
      std::span<const NearestParticle>(&own, 1),
      [](NearestParticle& kept, const NearestParticle& other) {
        kept.offer(other.distance, other.run_index, other.value);
      });
  return RunTotal::same_on_every_process(nearest.front().value);
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
