#pragma once
// What this process has spent on communication so far, for summary.json's "distribution" record
// (docs/running.md): every MPI call of core/distributed is timed by a CommunicationTimer. Time
// inside a collective call includes waiting there for the slowest process, so among the
// processes the smallest tally is nearest the transfers themselves and the largest minus the
// smallest is mostly waiting (unequal work). Zoltan's own messages while it cuts the regions are
// not counted (they happen at setup and at each rebalance only).

#include <chrono>
#include <cstdint>

namespace revsph::distributed {

struct CommunicationTally {
  double seconds = 0.0;         // inside MPI calls, waiting included
  std::uint64_t bytes_sent = 0; // by this process, to the others
  std::uint64_t calls = 0;      // MPI calls (each collective counts once)
  std::uint64_t exchanges = 0;  // of them, personalised all-to-all exchanges (ghosts, migration)
};

// This process's running tally (MPI calls are made by the main thread only: no lock).
inline CommunicationTally& communication_tally() {
  static CommunicationTally tally;
  return tally;
}

inline CommunicationTally operator-(const CommunicationTally& later,
                                    const CommunicationTally& earlier) {
  return {later.seconds - earlier.seconds, later.bytes_sent - earlier.bytes_sent,
          later.calls - earlier.calls, later.exchanges - earlier.exchanges};
}

// Adds its own lifetime, one call and `bytes_sent` to the tally.
class CommunicationTimer {
public:
  explicit CommunicationTimer(std::uint64_t bytes_sent = 0)
      : bytes_sent_(bytes_sent), start_(std::chrono::steady_clock::now()) {}
  ~CommunicationTimer() {
    CommunicationTally& tally = communication_tally();
    tally.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    tally.bytes_sent += bytes_sent_;
    ++tally.calls;
  }
  CommunicationTimer(const CommunicationTimer&) = delete;
  CommunicationTimer& operator=(const CommunicationTimer&) = delete;

private:
  std::uint64_t bytes_sent_;
  std::chrono::steady_clock::time_point start_;
};

} // namespace revsph::distributed
