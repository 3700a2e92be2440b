#include "simulation_fixture.hpp"

#include "core/run_settings.hpp"
#include "verify/state_hash.hpp"

namespace revsph::testing {

std::unique_ptr<Simulation> make_simulation(const std::string& name,
                                            const std::vector<Override>& overrides,
                                            Arithmetic arithmetic) {
  CaseFile case_file = load_case(name);
  for (const Override& o : overrides) {
    case_file.set(o.key, o.value);
  }
  read_run_settings(case_file);
  auto simulation = create_simulation(case_file, SimulationOptions{arithmetic});
  case_file.require_no_unknown_keys();
  return simulation;
}

std::unique_ptr<Simulation> make_simulation_from_text(const std::string& text) {
  CaseFile case_file = CaseFile::parse(text, "test case");
  read_run_settings(case_file);
  auto simulation = create_simulation(case_file, SimulationOptions{Arithmetic::fixed});
  case_file.require_no_unknown_keys();
  return simulation;
}

std::string hash_of(Simulation& simulation) {
  return state_hash(simulation.capture_state());
}

} // namespace revsph::testing
