#include "tools/revsph/interruption.hpp"

#include "core/distributed/processes.hpp"

#include <csignal>
#include <cstring>

namespace revsph::cli {

namespace {

volatile std::sig_atomic_t received_signal = 0;

extern "C" void remember_signal(int signal_number) {
  received_signal = signal_number;
}

struct sigaction previous_interrupt {};
struct sigaction previous_terminate {};

} // namespace

RunInterrupted::RunInterrupted(int signal_number)
    : std::runtime_error(std::string("interrupted by ") +
                         (signal_number == SIGINT ? "SIGINT" : "SIGTERM")),
      signal_number_(signal_number) {}

StopOnSignals::StopOnSignals() {
  received_signal = 0;
  struct sigaction action {};
  action.sa_handler = remember_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_interrupt);
  sigaction(SIGTERM, &action, &previous_terminate);
}

StopOnSignals::~StopOnSignals() {
  sigaction(SIGINT, &previous_interrupt, nullptr);
  sigaction(SIGTERM, &previous_terminate, nullptr);
}

void StopOnSignals::stop_if_signalled() const {
  double signal_number = static_cast<double>(received_signal);
  if (distributed::process_count() > 1) {
    // The largest signal number any process got: SIGTERM (15) over SIGINT (2).
    signal_number = distributed::max_over_processes(signal_number);
  }
  if (signal_number > 0.0) {
    throw RunInterrupted(static_cast<int>(signal_number));
  }
}

} // namespace revsph::cli
