#include "case_text.hpp"

#include "core/model_registry.hpp"

#include <stdexcept>

namespace revsph::testing {

std::string builtin_case_text(std::string_view name) {
  const BuiltinCase* builtin = find_builtin_case(name);
  if (builtin == nullptr) {
    throw std::logic_error("the built-in case " + std::string(name) + " is missing");
  }
  return std::string(builtin->text);
}

std::string replaced_once(std::string text, std::string_view from, std::string_view to) {
  const std::size_t first = text.find(from);
  if (first == std::string::npos || text.find(from, first + 1) != std::string::npos) {
    throw std::logic_error("expected exactly one occurrence of \"" + std::string(from) +
                           "\" in the case text");
  }
  return text.replace(first, from.size(), to);
}

int line_at(const std::string& text, std::size_t offset) {
  int line = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    line += text[i] == '\n' ? 1 : 0;
  }
  return line;
}

std::string with_edit_line(std::string part, const std::string& text, const std::string& edit) {
  const std::string marker = "@LINE@";
  if (const std::size_t at = part.find(marker); at != std::string::npos) {
    part.replace(at, marker.size(), std::to_string(line_at(text, text.find(edit) + edit.size())));
  }
  return part;
}

} // namespace revsph::testing
