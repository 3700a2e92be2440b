#include "tools/revsph/distribution_summary.hpp"

#include "core/distributed/processes.hpp"

#include <cstdio>

namespace revsph::cli {

DistributionSummary summarise_distribution(const Simulation& simulation,
                                           const distributed::CommunicationTally& stepping,
                                           double stepping_seconds, std::int64_t steps,
                                           int threads) {
  using distributed::max_over_processes;
  using distributed::min_over_processes;
  using distributed::sum_over_processes;
  const distributed::DistributionCounts counts = simulation.distribution_counts();
  const auto total = [](std::uint64_t local) {
    return static_cast<std::uint64_t>(sum_over_processes(static_cast<std::int64_t>(local)));
  };
  DistributionSummary summary;
  summary.processes = distributed::process_count();
  summary.threads = threads;
  summary.communication_seconds_min = min_over_processes(stepping.seconds);
  summary.communication_seconds_max = max_over_processes(stepping.seconds);
  fixedpoint::ExactDoubleSum seconds;
  seconds.add(stepping.seconds);
  summary.communication_seconds_mean =
      sum_over_processes(seconds).value() / static_cast<double>(summary.processes);
  summary.stepping_seconds = max_over_processes(stepping_seconds);
  const double per_step = steps > 0 ? 1.0 / static_cast<double>(steps) : 0.0;
  summary.bytes_sent_per_step = static_cast<double>(total(stepping.bytes_sent)) * per_step;
  summary.calls_per_step = static_cast<double>(stepping.calls) * per_step;
  summary.exchanges_per_step = static_cast<double>(stepping.exchanges) * per_step;
  const auto own = static_cast<double>(counts.own_particles);
  summary.own_particles_min = static_cast<std::uint64_t>(min_over_processes(own));
  summary.own_particles_max = static_cast<std::uint64_t>(max_over_processes(own));
  const std::uint64_t particles = total(counts.own_particles);
  summary.ghost_fraction =
      particles > 0 ? static_cast<double>(total(counts.ghosts)) / static_cast<double>(particles)
                    : 0.0;
  const double largest_work = max_over_processes(counts.work);
  const double mean_work =
      static_cast<double>(sum_over_processes(static_cast<std::int64_t>(counts.work))) /
      summary.processes;
  summary.work_imbalance = mean_work > 0.0 ? largest_work / mean_work : 1.0;
  summary.ghost_lists_made = counts.ghost_lists_made;
  summary.rebalances = counts.rebalances;
  summary.rebalances_by_measured_time = counts.rebalances_by_measured_time;
  return summary;
}

std::string distribution_line(const DistributionSummary& summary) {
  char line[320];
  std::snprintf(line, sizeof line,
                "processes: %d x %d threads; in MPI %.2f-%.2f s of %.2f s stepping; ghosts %.1f %% "
                "of the particles; %.3g bytes sent a step; %llu rebalances (%llu on measured time)",
                summary.processes, summary.threads, summary.communication_seconds_min,
                summary.communication_seconds_max, summary.stepping_seconds,
                100.0 * summary.ghost_fraction, summary.bytes_sent_per_step,
                static_cast<unsigned long long>(summary.rebalances),
                static_cast<unsigned long long>(summary.rebalances_by_measured_time));
  return line;
}

} // namespace revsph::cli
