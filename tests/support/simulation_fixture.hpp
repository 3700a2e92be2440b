#pragma once
// Helpers shared by the system tests: build a simulation from a built-in or inline case.

#include "core/model_registry.hpp"
#include "core/simulation.hpp"
#include "fixedpoint/exact_sum.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace revsph::testing {

struct Override {
  std::string key;
  std::string value;
};

// A simulation of the built-in case `name` with command-line style overrides applied, checked
// for unknown keys like the CLI does.
std::unique_ptr<Simulation> make_simulation(const std::string& name,
                                            const std::vector<Override>& overrides = {},
                                            Arithmetic arithmetic = Arithmetic::fixed);

// The same from case-file text (tests/support/case_text.hpp edits built-in cases).
std::unique_ptr<Simulation> make_simulation_from_text(const std::string& text);

std::string hash_of(Simulation& simulation);

// The state hash of the built-in case `name` (with `overrides`) after `steps` steps.
std::string hash_after(const std::string& name, std::int64_t steps,
                       const std::vector<Override>& overrides = {});

// The exact sum of the raw integers of the field `set`.`field` (all its components).
fixedpoint::int128 raw_total(Simulation& simulation, const std::string& set,
                             const std::string& field);

// The same of one component of the field in `state`.
fixedpoint::int128 raw_total(const StateSnapshot& state, const std::string& set,
                             const std::string& field, std::size_t component);

// The value of the energy term or diagnostic called `name`; NaN (which fails every comparison)
// if there is none.
double named_value(const std::vector<EnergyTerm>& terms, const std::string& name);

// The values of the output view `name` (ParticleView), by particle set: empty where no set has it.
std::map<std::string, std::vector<double>> views_named(Simulation& simulation,
                                                       const std::string& name);

} // namespace revsph::testing
