#pragma once
// summary.json of a run: what ran, how fast, with which build, and the final state hash.

#include "core/energy_log.hpp"
#include "core/run_settings.hpp"
#include "core/simulation.hpp"
#include "tools/revsph/distribution_summary.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace revsph::cli {

struct RunSummary {
  std::string case_source;
  std::vector<std::string> overrides;
  std::optional<std::string> from_snapshot; // the snapshot a restarted run began from
  std::int64_t start_step = 0;
  std::int64_t steps_requested = 0;
  RunEnd end;                    // where the run ends, absolute, and what said so
  double wall_seconds = 0.0;     // the whole run: stepping, energy log and snapshot writes
  double stepping_seconds = 0.0; // the time steps alone (no initial or final snapshot)
  int threads = 1;
  int processes = 1; // of a distributed run (MPI)
  std::string initial_hash;
  std::string final_hash;
  std::optional<std::string> failure;      // the fault message if the run stopped early
  bool healthy = true;                     // the health checks (core/run_health.hpp)
  std::vector<std::string> health_reasons; // one line per check crossed
  std::size_t snapshots_written = 0;
  std::vector<EnergyTerm> diagnostics_maxima; // the largest value of each diagnostic
  std::vector<EnergyTerm> diagnostics_minima; // and the smallest
  std::optional<std::string> last_snapshot;
  std::optional<DistributionSummary> distribution; // after the steps (not after a fault)
  // Peak resident memory at the end, of process 0 and the largest over the processes.
  std::size_t peak_memory_bytes = 0;
  std::size_t peak_memory_bytes_max_over_processes = 0;
};

// Written atomically (temporary file, then rename).
void write_summary(const std::filesystem::path& path, Simulation& simulation, const RunSummary& run,
                   const EnergyLog& energy);

} // namespace revsph::cli
