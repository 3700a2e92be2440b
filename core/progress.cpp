#include "core/progress.hpp"

#include "core/case_file.hpp"
#include "core/distributed/processes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <unistd.h>

namespace revsph {

ProgressSetting progress_setting() {
  const char* value = std::getenv("REVSPH_PROGRESS");
  const std::string setting = value == nullptr ? "auto" : value;
  if (setting == "auto") {
    return ProgressSetting::automatic;
  }
  if (setting == "bar") {
    return ProgressSetting::bar;
  }
  if (setting == "lines") {
    return ProgressSetting::lines;
  }
  throw CaseError("REVSPH_PROGRESS", "", "expected auto, bar or lines, got \"" + setting + "\"");
}

namespace {

// One of several processes started together: MPI's count, or, built without MPI, the count its
// launcher gives (Open MPI's mpirun, MPICH's Hydra). A lone MPI process may set them itself, to 1.
bool among_several_processes() {
  if (distributed::process_count() > 1) {
    return true;
  }
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* count = std::getenv(variable);
    if (count != nullptr && std::atoi(count) > 1) {
      return true;
    }
  }
  return false;
}

} // namespace

bool progress_bar_on(std::FILE* stream) {
  const ProgressSetting setting = progress_setting();
  if (setting != ProgressSetting::automatic) {
    return setting == ProgressSetting::bar;
  }
  return !among_several_processes() && isatty(fileno(stream)) != 0;
}

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) {
    return "--:--";
  }
  const long total = static_cast<long>(std::lround(seconds));
  char buffer[32];
  if (total >= 3600) {
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60,
                  total % 60);
  } else {
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld", total / 60, total % 60);
  }
  return buffer;
}

ProgressReporter::ProgressReporter(std::FILE* stream, std::string label, std::int64_t total_steps,
                                   double dt, double plain_interval_seconds)
    : stream_(stream), label_(std::move(label)), total_steps_(total_steps), dt_(dt),
      interval_seconds_(plain_interval_seconds), live_(progress_bar_on(stream)),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

void ProgressReporter::update(std::int64_t steps_done, const std::string& note) {
  if (first_step_ < 0) {
    first_step_ = steps_done;
    start_ = std::chrono::steady_clock::now();
    last_print_ = start_;
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since >= (live_ ? 0.2 : interval_seconds_)) {
    last_print_ = now;
    print(steps_done, note, false);
  }
}

void ProgressReporter::finish(std::int64_t steps_done, const std::string& note) {
  if (first_step_ < 0) {
    first_step_ = steps_done;
  }
  print(steps_done, note, true);
}

void ProgressReporter::announce(const std::string& line) {
  std::fprintf(stream_, "%s%s\n", live_ ? "\r\033[K" : "", line.c_str());
  std::fflush(stream_);
}

void ProgressReporter::print(std::int64_t steps_done, const std::string& note, bool final) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double done = static_cast<double>(steps_done - first_step_);
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double remaining = static_cast<double>(total_steps_ - steps_done);
  const double fraction =
      total_steps_ > 0 ? static_cast<double>(steps_done) / static_cast<double>(total_steps_) : 1.0;
  char line[512];
  std::snprintf(line, sizeof line,
                "%s %lld/%lld steps (%5.1f%%)  %.3g steps/s  t = %.5g s  %s %s%s%s", label_.c_str(),
                static_cast<long long>(steps_done), static_cast<long long>(total_steps_),
                100.0 * fraction, rate, time_at_step_zero_ + static_cast<double>(steps_done) * dt_,
                final ? "elapsed" : "ETA",
                final ? format_duration(elapsed).c_str()
                      : format_duration(rate > 0 ? remaining / rate : NAN).c_str(),
                note.empty() ? "" : "  ", note.c_str());
  if (live_) {
    const int width = 24;
    const int filled = static_cast<int>(std::lround(fraction * width));
    std::string bar(static_cast<std::size_t>(std::clamp(filled, 0, width)), '#');
    bar.resize(width, '.');
    std::fprintf(stream_, "\r\033[K[%s] %s%s", bar.c_str(), line, final ? "\n" : "");
  } else {
    std::fprintf(stream_, "%s\n", line);
  }
  std::fflush(stream_);
}

} // namespace revsph
