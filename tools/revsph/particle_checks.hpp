#pragma once
// What `revsph run` checks of its particles at each energy record, besides the model's
// diagnostics (docs/running.md): how many moving particles have passed into a wall, dummy or
// thermal layer (diagnostics.csv's particles_in_walls, and a warning when it rises), and the
// smallest distance between two particles over dr (the progress line's min r/dr).

#include "core/case_file.hpp"
#include "core/simulation.hpp"
#include "core/state_snapshot.hpp"
#include "core/wall_regions.hpp"

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace revsph::cli {

// The column of diagnostics.csv (unit "1": a number of particles).
inline constexpr const char* particles_in_walls = "particles_in_walls";

// Moving particles inside walls, over the whole run.
struct WallCount {
  std::vector<std::uint64_t> per_region; // in the order of ParticleChecks' regions
  std::uint64_t total = 0;
};

class ParticleChecks {
public:
  // The wall regions of the blocks of the case's fixed particle sets (core/wall_regions.hpp),
  // and the case's dr (discretisation.dr; without it, no checks). `case_file` as the model read
  // it.
  ParticleChecks(const CaseFile& case_file, const SimulationInfo& info);

  bool has_wall_regions() const { return !keys_.empty(); }

  // How many moving particles have passed into each wall (core/wall_penetration.hpp; a particle
  // in two counts for the first).
  // Collective in a distributed run: each process counts its own, and the counts are summed
  // exactly.
  WallCount count_in_walls(const StateSnapshot& state) const;

  // The smallest distance between two particles, not both fixed, over dr (smallest_distance,
  // core/smallest_distance.hpp): over this process's particles, then the smallest over the
  // processes (collective). A pair held by two processes is not looked at: a distributed run
  // may show a larger value than one process would. Infinity without a pair.
  double smallest_distance_over_dr(const StateSnapshot& state) const;

  // One line naming the regions that hold particles: "warning: step 1200, t = 0.431 s: 3 gas
  // particles inside walls (particles[1] "thermal" holds 2, particles[3] "dummy" 1); check …".
  std::string wall_warning(std::int64_t step, double time, const WallCount& count) const;

private:
  int dimension_;
  double dr_ = 0.0;
  std::vector<std::string> moving_sets_;
  std::vector<std::string> fixed_sets_;
  std::variant<std::vector<WallRegion<1>>, std::vector<WallRegion<2>>, std::vector<WallRegion<3>>>
      regions_;
  std::vector<std::string> keys_;  // per region: "particles[1]"
  std::vector<std::string> kinds_; // per region: "thermal"
};

} // namespace revsph::cli
