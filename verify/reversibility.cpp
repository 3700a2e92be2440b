#include "verify/reversibility.hpp"

#include "verify/state_hash.hpp"

#include <algorithm>
#include <chrono>

namespace revsph {

VerifyReport verify_reversibility(Simulation& simulation, const VerifyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  VerifyReport report;
  const StateSnapshot initial = simulation.capture_state();
  report.initial_hash = state_hash(initial);

  auto run_phase = [&](VerifyPhase phase, const PhaseHooks& phase_hooks) {
    if (phase_hooks.at_start) {
      phase_hooks.at_start(simulation);
    }
    RunHooks hooks;
    hooks.energy_log = phase_hooks.energy_log;
    hooks.energy_every = options.energy_every;
    hooks.progress = phase_hooks.progress;
    hooks.after_step = [&](Simulation& s, std::int64_t step) {
      if (phase_hooks.after_step) {
        phase_hooks.after_step(s);
      }
      if (options.after_step) {
        options.after_step(s, phase, step);
      }
    };
    run_steps(simulation, options.steps, hooks);
    if (phase_hooks.at_end) {
      phase_hooks.at_end(simulation);
    }
  };

  run_phase(VerifyPhase::forward, options.forward);
  report.turning_point_hash = state_hash(simulation.capture_state());
  simulation.reverse_time();
  run_phase(VerifyPhase::backward, options.backward);
  simulation.reverse_time();
  if (options.before_compare) {
    options.before_compare(simulation);
  }
  const StateSnapshot final_state = simulation.capture_state();
  report.final_hash = state_hash(final_state);
  report.comparison = compare_states(initial, final_state);
  if (!report.comparison.identical && report.comparison.layout_error.empty()) {
    report.distance = state_distance(initial, final_state);
  }
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::vector<SubstepCheck> check_substeps(Simulation& simulation, double dt) {
  const StateSnapshot initial = simulation.capture_state();
  const std::vector<std::string> names = simulation.substep_names();
  std::vector<SubstepCheck> checks;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const bool seen = std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i),
                                names[i]) != names.begin() + static_cast<std::ptrdiff_t>(i);
    if (seen) {
      continue; // a palindrome repeats its sub-steps; check each once
    }
    simulation.apply_substep(i, dt);
    simulation.reverse_time();
    simulation.apply_substep(i, dt);
    simulation.reverse_time();
    checks.push_back({names[i], compare_states(initial, simulation.capture_state())});
    simulation.restore_state(initial);
  }
  return checks;
}

} // namespace revsph
