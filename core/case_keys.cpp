#include "core/case_keys.hpp"

#include <stdexcept>

namespace revsph {

std::string_view to_string(KeyType type) {
  switch (type) {
  case KeyType::number:
    return "number";
  case KeyType::integer:
    return "integer";
  case KeyType::string:
    return "string";
  case KeyType::boolean:
    return "boolean";
  case KeyType::numbers:
    return "array of numbers";
  case KeyType::tables:
    return "array of tables";
  }
  return "?";
}

KeyTable& KeyTable::add(KeyDecl decl) {
  if (decl.path.empty() || find(decl.path) != nullptr) {
    throw std::logic_error("case key \"" + decl.path + "\" declared twice (or empty) in the " +
                           name_ + " key table");
  }
  keys_.push_back(std::move(decl));
  return *this;
}

KeyTable& KeyTable::add(const std::vector<KeyDecl>& decls) {
  for (const KeyDecl& decl : decls) {
    add(decl);
  }
  return *this;
}

const KeyDecl* KeyTable::find(std::string_view pattern) const {
  for (const KeyDecl& decl : keys_) {
    if (decl.path == pattern) {
      return &decl;
    }
  }
  return nullptr;
}

bool KeyTable::declares_table(std::string_view pattern) const {
  for (const KeyDecl& decl : keys_) {
    if (decl.path.size() > pattern.size() && decl.path.starts_with(pattern) &&
        decl.path[pattern.size()] == '.') {
      return true;
    }
  }
  return false;
}

std::string key_pattern(std::string_view key) {
  std::string pattern;
  pattern.reserve(key.size());
  bool in_index = false;
  for (const char c : key) {
    if (c == '[') {
      in_index = true;
      pattern += '[';
    } else if (c == ']') {
      in_index = false;
      pattern += ']';
    } else if (!in_index) {
      pattern += c;
    }
  }
  return pattern;
}

} // namespace revsph
