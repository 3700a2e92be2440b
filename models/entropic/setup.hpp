#pragma once
// Building an entropic SPH simulation from a case file.

#include "core/case_file.hpp"
#include "core/model_registry.hpp"
#include "core/simulation.hpp"

#include <memory>

namespace revsph::entropic {

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options);

} // namespace revsph::entropic
