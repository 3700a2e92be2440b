#include "simulation_fixture.hpp"

#include "core/run_settings.hpp"
#include "verify/state_hash.hpp"

#include <limits>

namespace revsph::testing {

namespace {

// As the CLI does: run settings read, unknown keys refused after the model has read its own.
std::unique_ptr<Simulation> simulation_of(CaseFile& case_file, Arithmetic arithmetic) {
  read_run_settings(case_file);
  auto simulation = create_simulation(case_file, SimulationOptions{arithmetic});
  case_file.require_no_unknown_keys();
  return simulation;
}

} // namespace

std::unique_ptr<Simulation> make_simulation(const std::string& name,
                                            const std::vector<Override>& overrides,
                                            Arithmetic arithmetic) {
  CaseFile case_file = load_case(name);
  for (const Override& o : overrides) {
    case_file.set(o.key, o.value);
  }
  return simulation_of(case_file, arithmetic);
}

std::unique_ptr<Simulation> make_simulation_from_text(const std::string& text) {
  CaseFile case_file = CaseFile::parse(text, "test case");
  return simulation_of(case_file, Arithmetic::fixed);
}

std::string hash_of(Simulation& simulation) {
  return state_hash(simulation.capture_state());
}

std::string hash_after(const std::string& name, std::int64_t steps,
                       const std::vector<Override>& overrides) {
  auto simulation = make_simulation(name, overrides);
  simulation->advance(steps);
  return hash_of(*simulation);
}

fixedpoint::int128 raw_total(Simulation& simulation, const std::string& set,
                             const std::string& field) {
  const StateSnapshot state = simulation.capture_state();
  fixedpoint::int128 total = 0;
  for (const std::int64_t raw : state.find(set, field)->bits) {
    total += raw;
  }
  return total;
}

fixedpoint::int128 raw_total(const StateSnapshot& state, const std::string& set,
                             const std::string& field, std::size_t component) {
  const FieldSnapshot& f = *state.find(set, field);
  fixedpoint::int128 total = 0;
  for (std::size_t i = 0; i < f.count; ++i) {
    total += f.bits[component * f.count + i];
  }
  return total;
}

double named_value(const std::vector<EnergyTerm>& terms, const std::string& name) {
  for (const EnergyTerm& term : terms) {
    if (term.name == name) {
      return term.value;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::map<std::string, std::vector<double>> views_named(Simulation& simulation,
                                                       const std::string& name) {
  std::map<std::string, std::vector<double>> views;
  simulation.derived_views([&](ParticleView&& view) {
    if (view.name == name) {
      views[view.particle_set] = std::move(view.values);
    }
  });
  return views;
}

} // namespace revsph::testing
