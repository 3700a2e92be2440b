#pragma once
// Building a two-fluid simulation from a case file.

#include "core/case_file.hpp"
#include "core/model_registry.hpp"
#include "core/simulation.hpp"

#include <memory>

namespace revsph::two_fluid {

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options);

} // namespace revsph::two_fluid
