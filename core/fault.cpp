#include "core/fault.hpp"

#include "core/distributed/processes.hpp"

#include <sstream>

namespace revsph {

namespace {
std::string describe(const FaultDescription& fault, std::int64_t step) {
  std::ostringstream message;
  if (step >= 0) {
    message << "step " << step << ": ";
  }
  message << fault.particle_set << " particle " << fault.particle << ": " << fault.variable << ": "
          << fault.reason;
  return message.str();
}
} // namespace

SimulationFault::SimulationFault(FaultDescription fault, std::int64_t step, bool shared)
    : std::runtime_error(describe(fault, step)), fault_(std::move(fault)), step_(step),
      shared_(shared) {}

void FaultRecorder::record(std::size_t particle, const char* particle_set, const char* variable,
                           const char* reason) {
  std::lock_guard lock(mutex_);
  if (!first_ || particle < first_->particle) {
    first_ = FaultDescription{particle_set, particle, variable, reason};
  }
  any_.store(true, std::memory_order_relaxed);
}

void FaultRecorder::throw_if_any() {
  // Every process of a distributed run passes here at the same point, some perhaps waiting in
  // the next exchange for a process that found a fault: they agree whether any did, and all
  // throw together (ModelSimulation then agrees on which fault to report).
  const bool distributed_run = distributed::process_count() > 1;
  if (distributed_run ? distributed::or_over_processes(any() ? 1 : 0) == 0 : !any()) {
    return;
  }
  FaultDescription fault = first_.value_or(FaultDescription{});
  first_.reset();
  any_.store(false, std::memory_order_relaxed);
  throw SimulationFault(std::move(fault), -1, distributed_run);
}

} // namespace revsph
