#pragma once
// Progress of a long run: on a terminal a live line (bar, steps/s, simulated time, ETA, a
// caller-supplied note such as the energy error); otherwise a plain line every few seconds.
// The environment variable REVSPH_PROGRESS chooses: "bar", "lines" or "auto" (unset: auto).

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace revsph {

enum class ProgressSetting { automatic, bar, lines };

// REVSPH_PROGRESS; throws CaseError (file "REVSPH_PROGRESS") on another value.
ProgressSetting progress_setting();

// Whether progress on `stream` is the live bar (carriage returns, escape codes). auto: on a
// terminal, but not in a run of several processes, which write to terminals of their launcher's
// (Open MPI forwards each one's output through a pseudo-terminal) even when its output goes to a
// file.
bool progress_bar_on(std::FILE* stream);

class ProgressReporter {
public:
  ProgressReporter(std::FILE* stream, std::string label, std::int64_t total_steps, double dt,
                   double plain_interval_seconds);
  // Cheap enough to call every step: it only prints when a refresh is due.
  void update(std::int64_t steps_done, const std::string& note = {});
  // Prints the final state and ends the live line.
  void finish(std::int64_t steps_done, const std::string& note = {});
  // A line of its own between progress lines (a snapshot written, a warning): on a terminal
  // above the live line, which the next update draws again.
  void announce(const std::string& line);

  bool live() const { return live_; }
  // The simulated time at step 0 as this run counts it (not 0 in a run continued at another
  // dt than its snapshot's: Simulation::time_at).
  void set_time_at_step_zero(double time) { time_at_step_zero_ = time; }

private:
  void print(std::int64_t steps_done, const std::string& note, bool final);

  std::FILE* stream_;
  std::string label_;
  std::int64_t total_steps_;
  double dt_;
  double interval_seconds_;
  bool live_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::int64_t first_step_ = -1;
  double time_at_step_zero_ = 0.0;
};

std::string format_duration(double seconds);

} // namespace revsph
