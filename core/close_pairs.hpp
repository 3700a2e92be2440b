#pragma once
// Pairs of particles closer than a small fraction of dr: particles that have merged or are
// merging. The Wendland kernel's gradient vanishes at r = 0, so nothing pushes such a pair
// apart; under tensile instability (negative pressures) particles fall into pairs and stay
// there. The run's health check counts them (core/run_health.hpp, diagnostics.csv's
// close_pairs). Two fixed particles are never a pair here: their distance is the case's.

#include "core/case_file.hpp"
#include "core/geometry.hpp"
#include "core/periodic_box.hpp"
#include "core/simulation.hpp"
#include "core/state_snapshot.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace revsph {

// The pairs of `points` (finite coordinates; the first `moving` move, the rest are fixed), not
// both fixed, less than `distance` apart, across the periodic faces of `box` too (2 distance
// below every period). Exact, whatever the thread count: candidates from a cell list
// (core/cell_list.hpp) of cells at least `distance` wide, each pair counted once.
template <int D>
std::uint64_t count_close_pairs(const CoordinateView<D>& points, std::size_t moving,
                                double distance, const PeriodicBox& box);

// The count of a running simulation's state.
class ClosePairCount {
public:
  // Pairs closer than `fraction` dr, dr the case's discretisation.dr (without it, none counted:
  // active() is false), over every particle set of `info`.
  ClosePairCount(const CaseFile& case_file, const SimulationInfo& info, double fraction);

  bool active() const { return distance_ > 0.0; }
  // Collective in a distributed run: each process counts the pairs of its own particles and the
  // counts are summed; a pair split between two processes is not seen.
  std::uint64_t count(const StateSnapshot& state) const;

private:
  int dimension_;
  double distance_ = 0.0;
  PeriodicBox box_;
  std::vector<std::string> moving_sets_;
  std::vector<std::string> fixed_sets_;
};

} // namespace revsph
