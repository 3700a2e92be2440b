#pragma once
// What every model holds and hands out the same way: its parameters (read from the case file),
// its SimulationInfo and its declared state. A model derives from ModelParts and brings the
// three names into its own scope (`using Parts::state_;` ...): the accessors the Model concept
// asks for (core/simulation.hpp) are then written once, here.

#include "core/simulation.hpp"

#include <utility>

namespace revsph {

template <class Parameters, class State>
class ModelParts {
public:
  State& state() { return state_; }
  const SimulationInfo& info() const { return info_; }
  const Parameters& parameters() const { return parameters_; }

protected:
  ModelParts(Parameters parameters, SimulationInfo info, State state)
      : parameters_(std::move(parameters)), info_(std::move(info)), state_(std::move(state)) {}

  Parameters parameters_;
  SimulationInfo info_;
  State state_;
};

} // namespace revsph
