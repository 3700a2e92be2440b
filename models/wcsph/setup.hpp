#pragma once
// Building a WCSPH simulation from a case file.

#include "core/case_file.hpp"
#include "core/model_registry.hpp"
#include "core/simulation.hpp"

#include <memory>

namespace revsph::wcsph {

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options);

} // namespace revsph::wcsph
