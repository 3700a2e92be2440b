#pragma once
// The list of models and built-in cases. Both are filled by code that models/CMakeLists.txt
// generates from the folders under models/: adding a model never edits core/.

#include "core/arithmetic.hpp"
#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/simulation.hpp"

#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {

struct SimulationOptions {
  Arithmetic arithmetic = Arithmetic::fixed;
  // Memory a case may use; 0: what the machine has available. Cases that would need more are
  // refused before allocating (see ParticleBudget).
  std::size_t memory_budget_bytes = 0;
};

using ModelFactory =
    std::function<std::unique_ptr<Simulation>(const CaseFile&, const SimulationOptions&)>;

struct ModelEntry {
  std::string name;
  std::string description;
  ModelFactory create;
  // The keys of the model's case files beyond common_case_keys(): the reference that
  // `revsph cases --keys` prints and what create_simulation lets the model read.
  const KeyTable& (*keys)() = nullptr;
  // Why the model has no floating-point variant ("" where it has one): create_simulation then
  // refuses `--arithmetic float` with this reason before the set-up (ArithmeticRefused).
  std::string_view fixed_point_only = "";
};

// The arithmetic asked for is one the model does not have: bad input, not a failed set-up.
class ArithmeticRefused : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

class ModelRegistry {
public:
  void add(ModelEntry entry) { entries_.push_back(std::move(entry)); }
  const ModelEntry* find(std::string_view name) const;
  const std::vector<ModelEntry>& entries() const { return entries_; }

private:
  std::vector<ModelEntry> entries_;
};

struct BuiltinCase {
  std::string_view name;  // file name without .toml, e.g. "dambreak-small"
  std::string_view model; // the folder under models/
  std::string_view text;
};

// Defined in the generated models registration file.
const ModelRegistry& model_registry();
std::span<const BuiltinCase> builtin_cases();
const BuiltinCase* find_builtin_case(std::string_view name);

// A case file from a path, or, if no such file exists, the built-in case of that name.
CaseFile load_case(const std::string& path_or_name);

// Reads `model`, attaches the common and the model's key tables to the case file (see
// CaseFile::use_keys) and creates the simulation. The caller reads its own sections ([run],
// [output]) and then calls case_file.require_no_unknown_keys().
std::unique_ptr<Simulation> create_simulation(const CaseFile& case_file,
                                              const SimulationOptions& options);

} // namespace revsph
