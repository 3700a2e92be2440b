#include "core/case_file.hpp"

#include "core/case_keys.hpp"

#include <toml++/toml.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace revsph {

namespace {

std::string describe_type(const toml::node& node) {
  switch (node.type()) {
  case toml::node_type::string:
    return "a string";
  case toml::node_type::integer:
    return "an integer";
  case toml::node_type::floating_point:
    return "a number";
  case toml::node_type::boolean:
    return "a boolean";
  case toml::node_type::table:
    return "a table";
  case toml::node_type::array:
    return "an array";
  default:
    return "a date or time";
  }
}

// The value of a number node. node.value<double>() is empty for an integer beyond 2^53 (not
// exactly representable), so an integer is converted here, to the nearest double as a float
// literal would be.
double number_value(const toml::node& node) {
  if (const auto* integer = node.as_integer()) {
    return static_cast<double>(integer->get());
  }
  return node.as_floating_point()->get();
}

std::string table_names(const std::vector<const KeyTable*>& tables) {
  std::string names;
  for (const KeyTable* table : tables) {
    names += (names.empty() ? "" : ", ") + table->name();
  }
  return names;
}

// A declared default written as TOML must be the one the reader falls back to: the reference
// shows the table's, the run uses the reader's. Descriptions ("dr") are not compared.
void check_default(const KeyDecl& decl, std::string_view key, bool same, bool literal) {
  if (literal && !same) {
    throw std::logic_error("case key \"" + std::string(key) +
                           "\": the reader's default differs "
                           "from the declared default " +
                           decl.default_value);
  }
}

struct UnreadKey {
  std::string key;
  toml::source_position position;
};

// Collects every leaf (value or array of values) and every empty table that was not read.
void collect_unread(const toml::node& node, const std::string& path,
                    const std::set<std::string, std::less<>>& read, std::vector<UnreadKey>& out) {
  if (const auto* table = node.as_table()) {
    if (table->empty() && !path.empty() && !read.contains(path)) {
      out.push_back({path, node.source().begin});
    }
    for (const auto& [key, child] : *table) {
      const std::string child_path =
          path.empty() ? std::string(key.str()) : path + "." + std::string(key.str());
      collect_unread(child, child_path, read, out);
    }
    return;
  }
  if (const auto* array = node.as_array(); array && array->is_array_of_tables()) {
    for (std::size_t i = 0; i < array->size(); ++i) {
      collect_unread(*array->get(i), path + "[" + std::to_string(i) + "]", read, out);
    }
    return;
  }
  if (!read.contains(path)) {
    out.push_back({path, node.source().begin});
  }
}

} // namespace

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string positive_or_why(const double& value) {
  return value > 0.0 ? std::string() : "must be > 0 (got " + format_number(value) + ")";
}

std::string non_negative_or_why(double value, std::string_view zero_means) {
  if (value >= 0.0 && std::isfinite(value)) {
    return {};
  }
  std::string reason = "must be a finite number >= 0";
  if (!zero_means.empty()) {
    reason += " (0: " + std::string(zero_means) + ")";
  }
  return reason + " (got " + format_number(value) + ")";
}

CaseError::CaseError(std::string file, std::string key, std::string reason)
    : std::runtime_error(file + ": " + (key.empty() ? std::string() : key + ": ") + reason),
      file_(std::move(file)), key_(std::move(key)), reason_(std::move(reason)) {}

CaseFile::CaseFile(std::string text, std::string source_name)
    : source_name_(std::move(source_name)), text_(std::move(text)),
      root_(std::make_unique<toml::table>()) {
  try {
    *root_ = toml::parse(text_, source_name_);
  } catch (const toml::parse_error& error) {
    const auto& where = error.source().begin;
    std::ostringstream reason;
    reason << "syntax error at line " << where.line << ", column " << where.column << ": "
           << error.description();
    throw CaseError(source_name_, "", reason.str());
  }
}

CaseFile::CaseFile(CaseFile&&) noexcept = default;
CaseFile& CaseFile::operator=(CaseFile&&) noexcept = default;
CaseFile::~CaseFile() = default;

CaseFile CaseFile::load(const std::filesystem::path& path) {
  // A directory opens as a stream that reads as empty, which would be reported as a case with
  // no `model`.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw CaseError(path.string(), "", "is a directory, not a case file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw CaseError(path.string(), "", "cannot open the case file");
  }
  std::ostringstream content;
  content << in.rdbuf();
  return CaseFile(content.str(), path.string());
}

CaseFile CaseFile::parse(std::string text, std::string source_name) {
  return CaseFile(std::move(text), std::move(source_name));
}

void CaseFile::fail(std::string_view key, const std::string& reason) const {
  // A value from --set has no place in the file (line 0): say so, or the file takes the blame.
  const toml::node* node = root_->at_path(key).node();
  const bool from_command_line = node != nullptr && node->source().begin.line == 0 &&
                                 reason.find("given with --set") == std::string::npos;
  throw CaseError(source_name_, std::string(key),
                  from_command_line ? reason + " (given with --set)" : reason);
}

const KeyDecl* CaseFile::declared(std::string_view key, const KeyType* type) const {
  if (!accessed_keys_.contains(key)) {
    accessed_keys_.emplace(key);
  }
  if (key_tables_.empty()) {
    return nullptr;
  }
  const std::string pattern = key_pattern(key);
  for (const KeyTable* table : key_tables_) {
    if (const KeyDecl* decl = table->find(pattern)) {
      if (type != nullptr && decl->type != *type) {
        throw std::logic_error("case key \"" + std::string(key) + "\" is declared as " +
                               std::string(to_string(decl->type)) + " but read as " +
                               std::string(to_string(*type)));
      }
      return decl;
    }
  }
  throw std::logic_error("case key \"" + std::string(key) +
                         "\" is read but not declared in the key tables (" +
                         table_names(key_tables_) + "): declare it in the model's case_keys()");
}

void CaseFile::use_keys(std::vector<const KeyTable*> tables) const {
  key_tables_ = std::move(tables);
  // The keys read before the tables were known (model, name, [run], [output]) are checked now.
  for (const std::string& key : accessed_keys_) {
    const std::string pattern = key_pattern(key);
    bool known = false;
    for (const KeyTable* table : key_tables_) {
      known = known || table->find(pattern) != nullptr || table->declares_table(pattern);
    }
    if (!known) {
      declared(key, nullptr); // throws the logic_error naming the key
    }
  }
}

const toml::node* CaseFile::find(std::string_view key) const {
  read_keys_.emplace(key);
  return root_->at_path(key).node();
}

const toml::node& CaseFile::require(std::string_view key) const {
  const toml::node* node = find(key);
  if (node == nullptr) {
    // A misspelt key (dx for dr, [discretization]) leaves the required one missing: name the
    // misspelling, as the unknown-key check would have had the reader not stopped first.
    std::vector<UnreadKey> unread;
    collect_unread(*root_, "", read_keys_, unread);
    for (const UnreadKey& u : unread) {
      if (nearest_declared_key(key_tables_, u.key) == key) {
        fail_unknown(u.key, u.position.line);
      }
    }
    fail(key, "missing required key");
  }
  return *node;
}

bool CaseFile::has(std::string_view key) const {
  declared(key, nullptr);
  return root_->at_path(key).node() != nullptr;
}

double CaseFile::number(std::string_view key) const {
  constexpr KeyType type = KeyType::number;
  declared(key, &type);
  const toml::node& node = require(key);
  if (!node.is_number()) {
    fail(key, "expected a number, got " + describe_type(node));
  }
  const double value = number_value(node);
  if (!std::isfinite(value)) {
    fail(key, "expected a finite number, got " + format_number(value));
  }
  return value;
}

template <class T>
void CaseFile::check_fallback(std::string_view key, KeyType type, const T& fallback) const {
  if (const KeyDecl* decl = declared(key, &type)) {
    const std::optional<T> literal = literal_default<T>(decl->default_value);
    check_default(*decl, key, literal == fallback, literal.has_value());
  }
}

double CaseFile::number_or(std::string_view key, double fallback) const {
  check_fallback(key, KeyType::number, fallback);
  return has(key) ? number(key) : fallback;
}

double CaseFile::positive_number(std::string_view key) const {
  const double value = number(key);
  if (const std::string why = positive_or_why(value); !why.empty()) {
    fail(key, why);
  }
  return value;
}

double CaseFile::non_negative_number_or(std::string_view key, double fallback,
                                        std::string_view zero_means) const {
  const double value = number_or(key, fallback);
  if (const std::string why = non_negative_or_why(value, zero_means); !why.empty()) {
    fail(key, why);
  }
  return value;
}

template <class T>
T CaseFile::typed_value(std::string_view key, KeyType type, std::string_view expected) const {
  declared(key, &type);
  const toml::node& node = require(key);
  if (!node.is<T>()) {
    fail(key, "expected " + std::string(expected) + ", got " + describe_type(node));
  }
  return *node.value<T>();
}

std::int64_t CaseFile::integer(std::string_view key) const {
  return typed_value<std::int64_t>(key, KeyType::integer, "an integer");
}

std::int64_t CaseFile::integer_or(std::string_view key, std::int64_t fallback) const {
  check_fallback(key, KeyType::integer, fallback);
  return has(key) ? integer(key) : fallback;
}

std::string CaseFile::string(std::string_view key) const {
  return typed_value<std::string>(key, KeyType::string, "a string");
}

std::string CaseFile::string_or(std::string_view key, std::string fallback) const {
  check_fallback(key, KeyType::string, fallback);
  return has(key) ? string(key) : fallback;
}

bool CaseFile::boolean_or(std::string_view key, bool fallback) const {
  check_fallback(key, KeyType::boolean, fallback);
  return has(key) ? typed_value<bool>(key, KeyType::boolean, "true or false") : fallback;
}

std::vector<double> CaseFile::numbers(std::string_view key, std::size_t size) const {
  const toml::node* node = find(key);
  const toml::array* array = node != nullptr ? node->as_array() : nullptr;
  if (node != nullptr && array == nullptr) {
    constexpr KeyType type = KeyType::numbers;
    declared(key, &type);
    fail(key,
         "expected an array of " + std::to_string(size) + " numbers, got " + describe_type(*node));
  }
  if (array != nullptr && array->size() != size) {
    constexpr KeyType type = KeyType::numbers;
    declared(key, &type);
    fail(key,
         "expected " + std::to_string(size) + " numbers, got " + std::to_string(array->size()));
  }
  return number_list(key);
}

std::vector<double> CaseFile::number_list(std::string_view key) const {
  constexpr KeyType type = KeyType::numbers;
  declared(key, &type);
  const toml::node& node = require(key);
  const toml::array* array = node.as_array();
  if (array == nullptr || array->empty()) {
    fail(key, "expected an array of numbers, got " +
                  (array == nullptr ? describe_type(node) : std::string("an empty array")));
  }
  std::vector<double> values;
  for (const toml::node& element : *array) {
    if (!element.is_number()) {
      fail(key, "expected an array of numbers, found " + describe_type(element) + " in it");
    }
    const double value = number_value(element);
    if (!std::isfinite(value)) {
      fail(key, "expected finite numbers, got " + format_number(value));
    }
    values.push_back(value);
  }
  return values;
}

std::size_t CaseFile::table_count(std::string_view key) const {
  constexpr KeyType type = KeyType::tables;
  declared(key, &type);
  const toml::node* node = find(key);
  if (node == nullptr) {
    return 0;
  }
  const toml::array* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    fail(key, "expected an array of tables ([[" + std::string(key) + "]] blocks), got " +
                  describe_type(*node));
  }
  return array->size();
}

void CaseFile::accept_table(std::string_view key) const {
  accessed_keys_.emplace(key);
  if (!key_tables_.empty()) {
    bool known = false;
    for (const KeyTable* table : key_tables_) {
      known = known || table->declares_table(key_pattern(key));
    }
    if (!known) {
      throw std::logic_error("case table \"" + std::string(key) +
                             "\" is accepted but declares no key in the key tables");
    }
  }
  read_keys_.emplace(key);
}

void CaseFile::set(std::string_view key, std::string_view value) {
  overrides_.push_back(std::string(key) + "=" + std::string(value));
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + std::string(value));
  } catch (const toml::parse_error&) {
    parsed.insert_or_assign("value", std::string(value)); // a bare word: take it as a string
  }
  // Walk (and create) the tables of the dotted path; array elements must exist already.
  toml::node* current = root_.get();
  std::string_view rest = key;
  std::string walked;
  while (true) {
    const std::size_t dot = rest.find('.');
    std::string_view part = rest.substr(0, dot);
    std::optional<std::size_t> index;
    if (const std::size_t bracket = part.find('['); bracket != std::string_view::npos) {
      // from_chars rather than stoul: a malformed index must be a CaseError naming the key, not
      // a std::invalid_argument that reaches the user as "stoul".
      const std::string_view digits =
          part.ends_with(']') ? part.substr(bracket + 1, part.size() - bracket - 2) : "";
      std::size_t parsed_index = 0;
      const auto [end, error] =
          std::from_chars(digits.data(), digits.data() + digits.size(), parsed_index);
      if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
        fail(key, "cannot set: expected an array index such as particles[0], got '" +
                      std::string(part) + "'");
      }
      index = parsed_index;
      part = part.substr(0, bracket);
    }
    if (part.empty()) {
      fail(key, "cannot set: the key has an empty part");
    }
    toml::table* table = current->as_table();
    if (table == nullptr) {
      fail(key, "cannot set: '" + walked + "' is not a table");
    }
    if (!walked.empty()) {
      walked += '.';
    }
    walked += part;
    const bool last = dot == std::string_view::npos;
    if (index) {
      toml::array* array = table->get_as<toml::array>(part);
      if (array == nullptr || *index >= array->size()) {
        fail(key, "cannot set: no element " + std::to_string(*index) + " in '" + walked + "'");
      }
      current = array->get(*index);
      walked.append("[").append(std::to_string(*index)).append("]");
      if (last) {
        fail(key, "cannot replace a whole array element");
      }
    } else if (last) {
      table->insert_or_assign(part, *parsed.get("value"));
      return;
    } else {
      if (!table->contains(part)) {
        table->insert(part, toml::table{});
      }
      current = table->get(part);
    }
    rest = rest.substr(dot + 1);
  }
}

void CaseFile::require_no_unknown_keys() const {
  std::vector<UnreadKey> unread;
  collect_unread(*root_, "", read_keys_, unread);
  if (unread.empty()) {
    return;
  }
  const UnreadKey* first = &unread.front();
  for (const UnreadKey& u : unread) {
    if (u.position.line < first->position.line ||
        (u.position.line == first->position.line && u.position.column < first->position.column)) {
      first = &u;
    }
  }
  fail_unknown(first->key, first->position.line);
}

void CaseFile::fail_unknown(const std::string& key, std::size_t line) const {
  // Values added by --set have no position in the file (line 0).
  const std::string where =
      line == 0 ? std::string("given with --set") : "line " + std::to_string(line);
  // Point to the model's reference: the table other than the common one.
  std::string model = "MODEL";
  for (const KeyTable* table : key_tables_) {
    if (table->name() != "common") {
      model = table->name();
    }
  }
  const std::string nearest = nearest_declared_key(key_tables_, key);
  if (nearest == key) {
    // A declared key the case's other settings leave unread (say, a seed for particles that are
    // not drawn at random): suggesting the key itself would only puzzle.
    fail(key, "not used with this case's other settings (" + where +
                  "; what each key needs: revsph cases --keys " + model + ")");
  }
  fail(key, "unknown key (" + where + "; every key: revsph cases --keys " + model + ")" +
                (nearest.empty() ? std::string() : "; did you mean " + nearest + "?"));
}

} // namespace revsph
