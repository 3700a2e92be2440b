#pragma once
// A case file (TOML) with typed, validated access that remembers which keys were read.
//
// Every problem is reported as one CaseError naming the file, the key and the reason. After a
// model has read its parameters, require_no_unknown_keys() rejects anything nobody read, so a
// misspelt key is an error instead of a silently ignored setting.
//
// With key tables attached (use_keys, done by create_simulation), every access is checked against
// them: reading a key no table declares, or as another type than declared, or with another
// default than declared, is a std::logic_error — a bug in the reader or its table, not in the
// case. That makes the tables (core/case_keys.hpp) a complete reference of what is read.

#include "core/case_inputs.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace toml {
inline namespace v3 {
class table;
class node;
} // namespace v3
} // namespace toml

namespace revsph {

// A number as the error messages write it ("0.001", "1e+20").
std::string format_number(double value);
// "" if the value is acceptable, else the one-line reason: > 0; a finite number >= 0, with what 0
// does ("no heater") if anything. CaseFile's readers and the key checks (core/case_key.hpp) share
// them.
std::string positive_or_why(const double& value);
std::string non_negative_or_why(double value, std::string_view zero_means = {});

class KeyTable;
struct KeyDecl;
enum class KeyType;

class CaseError : public std::runtime_error {
public:
  CaseError(std::string file, std::string key, std::string reason);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& reason() const { return reason_; }

private:
  std::string file_;
  std::string key_;
  std::string reason_;
};

class CaseFile {
public:
  // Throws CaseError (key "" and the line and column in the reason) on a syntax error.
  static CaseFile load(const std::filesystem::path& path);
  static CaseFile parse(std::string text, std::string source_name);

  CaseFile(CaseFile&&) noexcept;
  CaseFile& operator=(CaseFile&&) noexcept;
  ~CaseFile();

  const std::string& source_name() const { return source_name_; }
  // The file as written; the overrides applied since are overrides(). A snapshot stores both,
  // so that a restart rebuilds exactly the same case.
  const std::string& text() const { return text_; }
  const std::vector<std::string>& overrides() const { return overrides_; }
  // The files the case reads besides itself, as bytes (core/case_inputs.hpp): a snapshot stores
  // those used and gives them back to the case it rebuilds.
  CaseInputs& inputs() const { return inputs_; }

  // Keys are dotted paths with array indices: "discretisation.dr", "particles[1].min".
  bool has(std::string_view key) const;
  double number(std::string_view key) const;
  double number_or(std::string_view key, double fallback) const;
  double positive_number(std::string_view key) const;
  // A finite number >= 0 (a rate, a power, an amplitude), `fallback` if absent; `zero_means`
  // says in the error what 0 does ("no heater"), if anything.
  double non_negative_number_or(std::string_view key, double fallback,
                                std::string_view zero_means = {}) const;
  std::int64_t integer(std::string_view key) const;
  std::int64_t integer_or(std::string_view key, std::int64_t fallback) const;
  std::string string(std::string_view key) const;
  std::string string_or(std::string_view key, std::string fallback) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  // An array of exactly `size` numbers.
  std::vector<double> numbers(std::string_view key, std::size_t size) const;
  // An array of one or more numbers, of any length.
  std::vector<double> number_list(std::string_view key) const;
  // Number of tables in an array of tables ([[particles]]); 0 if the key is absent.
  std::size_t table_count(std::string_view key) const;
  // Marks a table as known even if none of its keys were read (an empty [output], say).
  void accept_table(std::string_view key) const;

  // Replaces or adds a value, given as TOML ("0.01", "[1.0, 2.0]", "\"square\"") or as a bare
  // word taken as a string. For command-line overrides (--set key=value).
  void set(std::string_view key, std::string_view value);

  // Checks every later access, and every key read so far, against these tables (the common
  // keys and a model's; see above). The tables must outlive the case file.
  void use_keys(std::vector<const KeyTable*> tables) const;
  const std::vector<const KeyTable*>& key_tables() const { return key_tables_; }
  // Every key and table path the readers asked for so far, as asked ("particles[1].min"):
  // read, tested with has() or defaulted; present in the file or not.
  const std::set<std::string, std::less<>>& accessed_keys() const { return accessed_keys_; }

  // Throws CaseError for the first key (in file order) that was never read; the message names
  // the command that lists every key of the model (revsph cases --keys MODEL).
  void require_no_unknown_keys() const;

  [[noreturn]] void fail(std::string_view key, const std::string& reason) const;

private:
  CaseFile(std::string text, std::string source_name);
  // The unknown-key (or unused-key) message for `key`, at `line` of the file (0: from --set).
  [[noreturn]] void fail_unknown(const std::string& key, std::size_t line) const;
  const toml::node* find(std::string_view key) const;
  const toml::node& require(std::string_view key) const;
  // The declaration of `key` when tables are attached (nullptr otherwise); a std::logic_error if
  // it is undeclared or declared with another type. A null `type` accepts any type.
  const KeyDecl* declared(std::string_view key, const KeyType* type) const;
  // A reader's fallback must be the declared default when that is a literal (else a logic error).
  template <class T>
  void check_fallback(std::string_view key, KeyType type, const T& fallback) const;
  // The value of a present key of TOML type T, else a one-line error: "expected <expected>, ...".
  template <class T>
  T typed_value(std::string_view key, KeyType type, std::string_view expected) const;

  std::string source_name_;
  std::string text_;
  std::vector<std::string> overrides_;
  mutable CaseInputs inputs_;
  std::unique_ptr<toml::table> root_;
  mutable std::set<std::string, std::less<>> read_keys_;
  mutable std::set<std::string, std::less<>> accessed_keys_;
  mutable std::vector<const KeyTable*> key_tables_;
};

} // namespace revsph
