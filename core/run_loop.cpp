#include "core/run_loop.hpp"

#include <cstdio>
#include <iterator>

namespace revsph {

namespace {
std::string energy_note(const EnergyLog* log) {
  if (log == nullptr || log->empty()) {
    return {};
  }
  // Both relative errors of energy.csv: over E(0) (the paper's) and over the energy that moved.
  char note[96];
  std::snprintf(note, sizeof note, "dE/E0 = %.2e  dE/Emech = %.2e", log->last_relative_error(),
                log->last_mechanical_relative_error());
  return note;
}
} // namespace

std::vector<EnergyTerm> diagnostics_row(Simulation& simulation, const RunHooks& hooks) {
  std::vector<EnergyTerm> row = simulation.diagnostics();
  if (hooks.extra_diagnostics) {
    std::vector<EnergyTerm> extra = hooks.extra_diagnostics(simulation);
    row.insert(row.end(), std::make_move_iterator(extra.begin()),
               std::make_move_iterator(extra.end()));
  }
  return row;
}

void run_steps(Simulation& simulation, std::int64_t steps, const RunHooks& hooks) {
  std::string flow;
  auto note = [&] {
    const std::string energy = energy_note(hooks.energy_log);
    return flow.empty() ? energy : energy.empty() ? flow : energy + "  " + flow;
  };
  auto record_energy = [&] {
    if (hooks.flow_note) {
      flow = hooks.flow_note(simulation);
    }
    if (hooks.energy_log != nullptr) {
      hooks.energy_log->record(simulation.steps_taken(), simulation.time(), simulation.energy());
    }
    if (hooks.diagnostics_log != nullptr) {
      hooks.diagnostics_log->record(simulation.steps_taken(), simulation.time(),
                                    diagnostics_row(simulation, hooks));
    }
  };
  if (hooks.energy_log != nullptr && hooks.energy_log->empty()) {
    record_energy();
  }
  if (hooks.progress != nullptr) {
    hooks.progress->update(simulation.steps_taken());
  }
  for (std::int64_t s = 1; s <= steps; ++s) {
    simulation.advance(1);
    if (hooks.after_step) {
      hooks.after_step(simulation, s);
    }
    if (simulation.steps_taken() % hooks.energy_every == 0 || s == steps) {
      record_energy();
    }
    if (hooks.progress != nullptr) {
      hooks.progress->update(simulation.steps_taken(), note());
    }
  }
  if (hooks.progress != nullptr) {
    hooks.progress->finish(simulation.steps_taken(), note());
  }
}

} // namespace revsph
