#pragma once
// Faults found while stepping (fixed-point overflow, NaN, a particle leaving the domain).
//
// Parallel loops cannot throw; they record into a FaultRecorder, which keeps the fault of the
// lowest particle index so that the report is the same for any thread count. The caller then
// throws a SimulationFault naming the particle, the variable and the step.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

namespace revsph {

struct FaultDescription {
  std::string particle_set;
  std::size_t particle = 0;
  std::string variable;
  std::string reason;
};

class SimulationFault : public std::runtime_error {
public:
  // `shared`: in a distributed run, every process threw it at the same point (FaultRecorder),
  // so that they can agree on one report (ModelSimulation); a fault without it was met by one
  // process alone, which must end the others (tools/revsph: stop_every_process).
  SimulationFault(FaultDescription fault, std::int64_t step, bool shared = false);
  const FaultDescription& fault() const { return fault_; }
  // The step during which the fault happened (steps completed before it + 1), -1 if unknown.
  std::int64_t step() const { return step_; }
  bool shared() const { return shared_; }
  // A shared fault that another process found (this one has nothing to report).
  bool found_elsewhere() const { return shared_ && fault_.particle_set.empty(); }

private:
  FaultDescription fault_;
  std::int64_t step_;
  bool shared_;
};

class FaultRecorder {
public:
  // Thread-safe. Keeps the fault with the lowest particle index.
  void record(std::size_t particle, const char* particle_set, const char* variable,
              const char* reason);
  bool any() const { return any_.load(std::memory_order_relaxed); }
  // Throws SimulationFault (step unknown) if a fault was recorded, and clears the recorder. In a
  // distributed run every process calls it at the same point of a step (collective): if any
  // process recorded a fault, every process throws, a shared fault.
  void throw_if_any();

private:
  std::atomic<bool> any_{false};
  std::mutex mutex_;
  std::optional<FaultDescription> first_;
};

} // namespace revsph
