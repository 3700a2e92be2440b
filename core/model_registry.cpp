#include "core/model_registry.hpp"

#include "core/dimension.hpp"
#include "core/particle_blocks.hpp"
#include "core/periodic_box.hpp"
#include "core/state_snapshot.hpp"

#include <filesystem>
#include <set>
#include <stdexcept>

namespace revsph {

const ModelEntry* ModelRegistry::find(std::string_view name) const {
  for (const ModelEntry& entry : entries_) {
    if (entry.name == name) {
      return &entry;
    }
  }
  return nullptr;
}

const BuiltinCase* find_builtin_case(std::string_view name) {
  for (const BuiltinCase& c : builtin_cases()) {
    if (c.name == name) {
      return &c;
    }
  }
  return nullptr;
}

CaseFile load_case(const std::string& path_or_name) {
  if (!std::filesystem::exists(path_or_name)) {
    if (const BuiltinCase* builtin = find_builtin_case(path_or_name)) {
      return CaseFile::parse(std::string(builtin->text), std::string(builtin->name) + ".toml");
    }
    std::string known;
    for (const BuiltinCase& c : builtin_cases()) {
      known += (known.empty() ? "" : ", ") + std::string(c.name);
    }
    throw CaseError(path_or_name, "",
                    "no such file, and no built-in case of that name (built-in: " + known + ")");
  }
  return CaseFile::load(path_or_name);
}

namespace {

// A point file's values go to the set named by its block's kind (core/state_fill.hpp): a kind
// that makes particles of other sets (two_fluid's "mixed") cannot take them.
void refuse_values_for_no_set(const CaseFile& case_file, Simulation& simulation) {
  std::set<std::string> sets;
  for (const FieldSnapshot& field : simulation.borrow_state().fields) {
    sets.insert(field.info.particle_set);
  }
  for (std::size_t b = 0; b < case_file.table_count("particles"); ++b) {
    const std::string key = "particles[" + std::to_string(b) + "]";
    const std::string kind = case_file.string(key + ".kind");
    if (case_file.string_or(key + ".shape", "box") != "points" || sets.contains(kind)) {
      continue;
    }
    const bool with_values = with_dimension<1, 2, 3>(
        case_file, [&]<int D>() { return !point_blocks_with_values<D>(case_file, kind).empty(); });
    if (with_values) {
      case_file.fail(key + ".file", "kind \"" + kind +
                                        "\" makes particles of several sets: its file can give "
                                        "positions only (use a block per set)");
    }
  }
}

} // namespace

std::unique_ptr<Simulation> create_simulation(const CaseFile& case_file,
                                              const SimulationOptions& options) {
  const std::string model = case_file.string("model");
  const ModelEntry* entry = model_registry().find(model);
  if (entry == nullptr) {
    std::string known;
    for (const ModelEntry& e : model_registry().entries()) {
      known += (known.empty() ? "" : ", ") + e.name;
    }
    case_file.fail("model", "unknown model \"" + model + "\" (available: " + known + ")");
  }
  if (entry->keys == nullptr) {
    throw std::logic_error("model " + model + " registers no case-key table");
  }
  case_file.use_keys({&common_case_keys(), &entry->keys()});
  if (options.arithmetic != Arithmetic::fixed && !entry->fixed_point_only.empty()) {
    throw ArithmeticRefused(model +
                            " runs in fixed point only: " + std::string(entry->fixed_point_only));
  }
  try {
    std::unique_ptr<Simulation> simulation = entry->create(case_file, options);
    refuse_values_for_no_set(case_file, *simulation);
    return simulation;
  } catch (const SimulationFault& fault) {
    // The initial state itself is faulty (say a NaN force at t = 0): step 0.
    if (fault.step() >= 0) {
      throw;
    }
    throw SimulationFault(fault.fault(), 0);
  } catch (const PeriodTooShort& refusal) {
    // Found once the model's radii are known (core/periodic_box.hpp).
    case_file.fail("domain.periodic", refusal.what());
  }
}

} // namespace revsph
