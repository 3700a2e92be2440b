#pragma once
// SIGINT and SIGTERM during `revsph run`: the step under way finishes, a last snapshot of that
// complete state is written with summary.json marked incomplete, and the run exits 130 or 143
// (128 + the signal), so that `revsph run --from` continues it (docs/restart.md). In a
// distributed run the processes agree after each step on whether any was signalled, so that all
// stop at the same step.

#include <stdexcept>
#include <string>

namespace revsph::cli {

// Thrown after a step when a signal asked the run to stop.
class RunInterrupted : public std::runtime_error {
public:
  explicit RunInterrupted(int signal_number);
  int signal_number() const { return signal_number_; }
  int exit_status() const { return 128 + signal_number_; }

private:
  int signal_number_;
};

// Installs the handlers for the life of the object (the previous ones come back after).
class StopOnSignals {
public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  // Throws RunInterrupted if a signal came (collective in a distributed run).
  void stop_if_signalled() const;
};

} // namespace revsph::cli
