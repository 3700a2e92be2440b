#pragma once
// The declared keys of case files: one table per model plus the model-independent one.
//
// A table is the single source of both the case-file reference (`revsph cases --keys MODEL`,
// docs/case-keys.md) and of what the readers may read: once create_simulation has attached the
// tables to a CaseFile, reading a key that no table declares, or reading it as another type than
// declared, is a std::logic_error. So every key a reader accepts appears in the reference.
//
// Keys are dotted paths; an element of an array of tables is written with empty brackets:
// "particles[].min" declares particles[0].min, particles[1].min, …

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace revsph {

enum class KeyType {
  number,  // an integer or floating-point value
  integer, // an integer value only
  string,
  boolean,
  numbers, // an array of numbers (a point or a vector: one per axis)
  tables,  // an array of tables ([[particles]] blocks)
};

std::string_view to_string(KeyType type);

struct KeyDecl {
  // A constructor rather than an aggregate: most declarations have no allowed values, and
  // -Wextra warns about the member an aggregate initialiser leaves out.
  KeyDecl(std::string path_, KeyType type_, std::string unit_, std::string default_value_,
          std::string meaning_, std::vector<std::string> allowed_ = {})
      : path(std::move(path_)), type(type_), unit(std::move(unit_)),
        default_value(std::move(default_value_)), meaning(std::move(meaning_)),
        allowed(std::move(allowed_)) {}

  std::string path;
  KeyType type;
  // SI unit ("m", "kg/m^3"), "1" for a dimensionless number, "-" for what has no unit (strings,
  // booleans, counts, exponents).
  std::string unit;
  // "required", or the value taken when the key is absent. Written as TOML ("0.95", "\"rest\"",
  // "true") it is compared with the default the reader passes (see CaseFile); anything else is a
  // description ("dr", "required with young_modulus") and documents a computed default.
  std::string default_value;
  std::string meaning;
  std::vector<std::string> allowed; // the accepted values of a string key; empty: any
};

class KeyTable {
public:
  // `name`: the model ("wcsph"), or "common" for the keys of every model.
  explicit KeyTable(std::string name) : name_(std::move(name)) {}

  KeyTable& add(KeyDecl decl);
  KeyTable& add(const std::vector<KeyDecl>& decls);

  const std::string& name() const { return name_; }
  const std::vector<KeyDecl>& keys() const { return keys_; }
  // The declaration of a key pattern ("particles[].min"), or nullptr.
  const KeyDecl* find(std::string_view pattern) const;
  // Whether some declared key lies under this table path ("output" for "output.energy_every").
  bool declares_table(std::string_view pattern) const;

private:
  std::string name_;
  std::vector<KeyDecl> keys_;
};

// "particles[3].min" -> "particles[].min": the pattern a key is declared under.
std::string key_pattern(std::string_view key);

// The declared key closest to a misspelt `key` ("discretisation.drr" -> "discretisation.dr"), with
// the array indices of `key` filled in; empty if none is within two edits. For the unknown-key
// error.
std::string nearest_declared_key(const std::vector<const KeyTable*>& tables, std::string_view key);

// The keys every case file has, whatever its model: model, name, [run], [output].
const KeyTable& common_case_keys();

// Keys read by core/particle_blocks.cpp, for a model's table: [domain] and the [[particles]]
// blocks with the particle kinds the model has.
std::vector<KeyDecl> domain_case_keys();
std::vector<KeyDecl> particle_block_case_keys(const std::vector<std::string>& kinds);

// A declared default that is a TOML number or integer ("0.1", "20"), or nullopt for a description
// ("dr") or "required".
std::optional<double> literal_number(const std::string& text);
std::optional<std::int64_t> literal_integer(const std::string& text);

// The value of a declared default of type T (double, std::int64_t, std::string: a quoted text,
// bool: true or false), or nullopt for a description or "required".
template <class T>
std::optional<T> literal_default(const std::string& text) {
  if constexpr (std::is_same_v<T, double>) {
    return literal_number(text);
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    return literal_integer(text);
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
      return text.substr(1, text.size() - 2);
    }
    return std::nullopt;
  } else {
    static_assert(std::is_same_v<T, bool>);
    if (text == "true" || text == "false") {
      return text == "true";
    }
    return std::nullopt;
  }
}

} // namespace revsph
