#include "core/fault.hpp"

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

SimulationFault::SimulationFault(FaultDescription fault, std::int64_t step)
    : std::runtime_error(describe(fault, step)), fault_(std::move(fault)), step_(step) {}

void FaultRecorder::record(std::size_t particle, const char* particle_set, const char* variable,
                           const char* reason) {
  std::lock_guard lock(mutex_);
  if (!first_ || particle < first_->particle) {
    first_ = FaultDescription{particle_set, particle, variable, reason};
  }
  any_.store(true, std::memory_order_relaxed);
}

void FaultRecorder::throw_if_any() {
  if (!any()) {
    return;
  }
  FaultDescription fault = *first_;
  first_.reset();
  any_.store(false, std::memory_order_relaxed);
  throw SimulationFault(std::move(fault), -1);
}

} // namespace revsph
