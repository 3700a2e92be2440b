#pragma once
// The reversibility verifier (design note §5): forward N steps, time reversal R, N steps, R,
// then compare every raw integer of every variable of every particle with the initial state.

#include "core/run_loop.hpp"
#include "core/simulation.hpp"
#include "verify/state_compare.hpp"
#include "verify/state_distance.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace revsph {

enum class VerifyPhase { forward, backward };

// What to do during one half of the experiment (all optional).
struct PhaseHooks {
  ProgressReporter* progress = nullptr;
  EnergyLog* energy_log = nullptr;
  // At the start of the phase (for the backward half: after the time reversal) and at its end
  // (before the next reversal): e.g. write snapshots.
  std::function<void(Simulation&)> at_start;
  std::function<void(Simulation&)> at_end;
  // After every step of the phase.
  std::function<void(Simulation&)> after_step;
};

struct VerifyOptions {
  std::int64_t steps = 0; // each way
  std::int64_t energy_every = 100;
  PhaseHooks forward;
  PhaseHooks backward;
  // Test hooks: after each step of a phase (step counted from 1 within the phase), and just
  // before the final comparison. They may change the state through Simulation::restore_state.
  std::function<void(Simulation&, VerifyPhase, std::int64_t)> after_step;
  std::function<void(Simulation&)> before_compare;
};

struct VerifyReport {
  StateComparison comparison;
  // How far the returned state lies from the initial one, variable by variable: set when they
  // differ (a case with irreversible terms, float arithmetic, a fault) and can be compared.
  std::optional<StateDistance> distance;
  std::string initial_hash;
  std::string final_hash;
  std::string turning_point_hash; // after the forward half
  double wall_seconds = 0.0;
  bool identical() const { return comparison.identical; }
};

VerifyReport verify_reversibility(Simulation& simulation, const VerifyOptions& options);

struct SubstepCheck {
  std::string name;
  StateComparison comparison;
};

// Checks R S R S = id for every sub-step S of the model's step on its own, from the current
// state (which is restored afterwards). Names the sub-steps that block reversibility.
std::vector<SubstepCheck> check_substeps(Simulation& simulation, double dt);

} // namespace revsph
