#pragma once
// summary.json's "distribution" record of a run (docs/running.md, "Several processes"): how the
// particles were spread over the processes, what the processes sent each other during the time
// steps, and how long they spent communicating or waiting for one another.

#include "core/distributed/communication_tally.hpp"
#include "core/simulation.hpp"

#include <cstdint>
#include <string>

namespace revsph::cli {

struct DistributionSummary {
  int processes = 1;
  int threads = 1;
  // Seconds inside MPI calls during the steps, over the processes: the smallest is nearest the
  // transfers themselves, the largest adds the waiting for the slowest process.
  double communication_seconds_min = 0.0;
  double communication_seconds_max = 0.0;
  double communication_seconds_mean = 0.0;
  double stepping_seconds = 0.0;
  double bytes_sent_per_step = 0.0; // by every process together
  double calls_per_step = 0.0;      // MPI calls of one process (the same on each)
  double exchanges_per_step = 0.0;  // of them, all-to-all exchanges (the others are reductions)
  std::uint64_t own_particles_min = 0;
  std::uint64_t own_particles_max = 0;
  double ghost_fraction = 0.0; // ghosts held by every process / particles of the run
  double work_imbalance = 1.0; // largest / mean estimated work, at the last migration
  std::uint64_t ghost_lists_made = 0;
  std::uint64_t rebalances = 0;
  std::uint64_t rebalances_by_measured_time = 0;
};

// Collective: every process calls it with its own tallies of the stepping.
DistributionSummary summarise_distribution(const Simulation& simulation,
                                           const distributed::CommunicationTally& stepping,
                                           double stepping_seconds, std::int64_t steps,
                                           int threads);

// One line for the console.
std::string distribution_line(const DistributionSummary& summary);

} // namespace revsph::cli
