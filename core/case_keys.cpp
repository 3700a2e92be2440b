#include "core/case_keys.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>
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

namespace {

// Levenshtein distance: insertions, deletions and substitutions of one character each.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// `pattern` with its "[]" replaced, in order, by the indices "[n]" of `key`.
std::string with_indices_of(std::string_view key, const std::string& pattern) {
  std::vector<std::string> indices;
  for (std::size_t open = key.find('['); open != std::string_view::npos;
       open = key.find('[', open + 1)) {
    const std::size_t close = key.find(']', open);
    if (close == std::string_view::npos) {
      break;
    }
    indices.emplace_back(key.substr(open, close - open + 1));
  }
  std::string concrete;
  std::size_t next = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern.compare(i, 2, "[]") == 0 && next < indices.size()) {
      concrete += indices[next++];
      ++i;
    } else {
      concrete += pattern[i];
    }
  }
  return concrete;
}

} // namespace

std::string nearest_declared_key(const std::vector<const KeyTable*>& tables, std::string_view key) {
  const std::string pattern = key_pattern(key);
  constexpr std::size_t max_edits = 2;
  std::size_t best = max_edits + 1;
  std::string nearest;
  for (const KeyTable* table : tables) {
    for (const KeyDecl& decl : table->keys()) {
      const std::size_t distance = edit_distance(pattern, decl.path);
      if (distance < best) {
        best = distance;
        nearest = decl.path;
      }
    }
  }
  return nearest.empty() ? nearest : with_indices_of(key, nearest);
}

std::optional<double> literal_number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> literal_integer(const std::string& text) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    return std::nullopt;
  }
  return value;
}

} // namespace revsph
