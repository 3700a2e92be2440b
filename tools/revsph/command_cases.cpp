#include "core/model_registry.hpp"
#include "tools/revsph/commands.hpp"

#include <iostream>

namespace revsph::cli {

int cases_command(const std::string& name) {
  if (!name.empty()) {
    const BuiltinCase* builtin = find_builtin_case(name);
    if (builtin == nullptr) {
      print_error("no built-in case \"" + name + "\" (list them with: revsph cases)");
      return bad_input;
    }
    std::cout << builtin->text;
    return success;
  }
  std::cout << "built-in cases (use the name where a CASE.toml is expected; print one with "
               "`revsph cases NAME`):\n";
  for (const BuiltinCase& c : builtin_cases()) {
    std::cout << "  " << c.name << "  (model " << c.model << ")\n";
  }
  std::cout << "models:\n";
  for (const ModelEntry& model : model_registry().entries()) {
    std::cout << "  " << model.name << "  " << model.description << "\n";
  }
  return success;
}

} // namespace revsph::cli
