#pragma once
// A case-file key declared once (issue 31): its path, type, unit, default, meaning, the check its
// value must pass and, for a choice, the values it maps to.
//
// A model's keys are the members of one KeySet, in the order of its key reference:
//
//   struct Keys : KeySet {
//     Keys() : KeySet("wcsph") {}
//     const Key<double> gravity = number("physics.gravity", "m/s^2", "0", "gravitational ...");
//     const Choice<Mode> mode = choice<Mode>("filter.mode", "\"passive\"", "...",
//                                            {{"passive", Mode::passive}, {"active", ...}});
//   };
//
// The set's table is the model's KeyTable (the key reference, the case-file fuzz test and the
// unknown-key messages come from it), and the model reads each value through its member:
// `keys.gravity.read(case_file)`. The path, the type, the default and the check are so written
// once; the default is the declaration's TOML text ("0", "\"passive\"", "required"), or a
// description ("dr") whose value the reader computes (`read_or`).

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/case_values.hpp"
#include "fixedpoint/scale.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace revsph {

enum class Splitting; // core/step_splitting.hpp

// "" if a value is acceptable, else why not ("must be >= 0").
template <class T>
using KeyCheck = std::function<std::string(const T&)>;

// The check that `ok` holds, failing with `reason`.
template <class T, class Predicate>
KeyCheck<T> must(Predicate ok, std::string reason) {
  return [ok, reason = std::move(reason)](const T& value) {
    return ok(value) ? std::string() : reason;
  };
}

template <class T>
class Key {
public:
  Key(const KeyDecl& decl, KeyCheck<T> check);

  const std::string& path() const { return path_; }
  // The file's value, else the declared default; a std::logic_error if the default is a
  // description (use read_or). Fails (CaseError) if the check does not hold.
  T read(const CaseFile& case_file) const;
  // The file's value, else `computed`: for a default the declaration describes ("dr").
  T read_or(const CaseFile& case_file, T computed) const;
  // The file's value, which must be there: for a key required only with another one
  // ("required with a power").
  T require(const CaseFile& case_file) const;
  // The file's value if it is there ("none" by default).
  std::optional<T> read_optional(const CaseFile& case_file) const;

private:
  T checked(const CaseFile& case_file, T value) const;

  std::string path_;
  bool required_ = false;
  std::optional<T> default_;
  KeyCheck<T> check_;
};

// A string key whose values name the members of an enum E.
template <class E>
class Choice {
public:
  Choice(const KeyDecl& decl, std::vector<std::pair<std::string, E>> values);

  const std::string& path() const { return path_; }
  E read(const CaseFile& case_file) const;

private:
  std::string path_;
  std::optional<std::string> default_; // nullopt: required
  std::vector<std::pair<std::string, E>> values_;
};

// A fixed-point scale's exponent key, fixed_point.QUANTITY_exponent: the scale it gives, or by
// default the one that covers a magnitude known at setup with `fraction_bits` bits below it
// (scale_or, core/case_values.hpp). The bits are stated here once: the reference's default text
// is made from them.
class ScaleKey {
public:
  ScaleKey(std::string path, int fraction_bits)
      : path_(std::move(path)), fraction_bits_(fraction_bits) {}
  const std::string& path() const { return path_; }
  fixedpoint::Scale read(const CaseFile& case_file, double magnitude) const {
    return scale_or(case_file, path_.c_str(), magnitude, fraction_bits_);
  }

private:
  std::string path_;
  int fraction_bits_;
};

// fixed_point.position_exponent, the same key in every model (position_scale_or).
class PositionScaleKey {
public:
  fixedpoint::Scale read(const CaseFile& case_file, double max_abs_coordinate, double dr) const {
    return position_scale_or(case_file, max_abs_coordinate, dr);
  }
};

// The check that a value lies between `low` and `high`, each end closed or open. nullopt is an
// infinite end: a number may be that infinity only if the end is closed ("(0, inf]": a time that
// may be infinite). NaN never passes. Fails with `message` and the value.
template <class T>
KeyCheck<T> within(std::optional<T> low, bool low_closed, std::optional<T> high, bool high_closed,
                   std::string message) {
  return [=](const T& value) {
    bool ok = !low || (low_closed ? value >= *low : value > *low);
    ok = ok && (!high || (high_closed ? value <= *high : value < *high));
    if constexpr (std::is_floating_point_v<T>) {
      ok = ok && !std::isnan(value) &&
           (value != -std::numeric_limits<T>::infinity() || (!low && low_closed)) &&
           (value != std::numeric_limits<T>::infinity() || (!high && high_closed));
      return ok ? std::string() : message + " (got " + format_number(value) + ")";
    } else {
      return ok ? std::string() : message + " (got " + std::to_string(value) + ")";
    }
  };
}

// positive_or_why (core/case_file.hpp) checks a positive number.
// A finite number >= 0 (a rate, a power, an amplitude); `zero_means` says in the error what 0
// does ("no heater"), if anything (as CaseFile::non_negative_number_or).
KeyCheck<double> non_negative(std::string zero_means = {});

// "expected \"a\", \"b\" or \"c\", got \"x\"": the error of a choice key.
std::string expected_one_of(const std::vector<std::string>& names, const std::string& got);

class KeySet {
public:
  explicit KeySet(std::string name) : table_(std::move(name)) {}
  KeySet(const KeySet&) = delete;
  KeySet& operator=(const KeySet&) = delete;

  const KeyTable& table() const { return table_; }

protected:
  Key<double> number(std::string path, std::string unit, std::string default_value,
                     std::string meaning, KeyCheck<double> check = {});
  Key<std::int64_t> integer(std::string path, std::string default_value, std::string meaning,
                            KeyCheck<std::int64_t> check = {});
  Key<bool> boolean(std::string path, std::string default_value, std::string meaning);
  Key<std::string> text(std::string path, std::string default_value, std::string meaning,
                        KeyCheck<std::string> check = {});
  template <class E>
  Choice<E> choice(std::string path, std::string default_value, std::string meaning,
                   std::vector<std::pair<std::string, E>> values) {
    std::vector<std::string> names;
    for (const auto& value : values) {
      names.push_back(value.first);
    }
    return Choice<E>(add({std::move(path), KeyType::string, "-", std::move(default_value),
                          std::move(meaning), std::move(names)}),
                     std::move(values));
  }
  // fixed_point.QUANTITY_exponent, by default covering `magnitude` (its name in the reference:
  // "u1", "rho0") with `fraction_bits` bits; `note` follows the default's text.
  ScaleKey scale(const std::string& quantity, const std::string& magnitude, int fraction_bits,
                 std::string meaning, const std::string& note = {});
  PositionScaleKey position_scale();
  // physics.gravity, g along minus the last axis (`detail`: what it acts on, an equation), and
  // physics.gravity_reference_height: the two keys every model with gravity has.
  Key<double> gravity(std::string_view detail = "");
  Key<double> gravity_reference_height();
  // step.splitting: where the model's irreversible operators go in the step
  // (core/step_splitting.hpp); `default_name` is the model's ("strang", ...).
  Choice<Splitting> splitting(const std::string& default_name);
  // A key read elsewhere (by a core reader, or an array of numbers read with the dimension):
  // declared here, read through the path this returns.
  std::string declare(KeyDecl decl) { return add(std::move(decl)).path; }
  // Keys that core readers declare and read (discretisation, walls, domain, particle blocks).
  int declare(const std::vector<KeyDecl>& decls) {
    table_.add(decls);
    return 0;
  }

private:
  // Valid until the next key is added.
  const KeyDecl& add(KeyDecl decl);

  KeyTable table_;
};

// ---- implementation

namespace key_detail {
template <class T>
T read_present(const CaseFile& case_file, const std::string& path) {
  if constexpr (std::is_same_v<T, double>) {
    return case_file.number(path);
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    return case_file.integer(path);
  } else if constexpr (std::is_same_v<T, std::string>) {
    return case_file.string(path);
  } else {
    static_assert(std::is_same_v<T, bool>);
    return case_file.boolean_or(path, false);
  }
}
template <class T>
T read_or(const CaseFile& case_file, const std::string& path, T fallback) {
  if constexpr (std::is_same_v<T, double>) {
    return case_file.number_or(path, fallback);
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    return case_file.integer_or(path, fallback);
  } else if constexpr (std::is_same_v<T, std::string>) {
    return case_file.string_or(path, std::move(fallback));
  } else {
    static_assert(std::is_same_v<T, bool>);
    return case_file.boolean_or(path, fallback);
  }
}
} // namespace key_detail

template <class T>
Key<T>::Key(const KeyDecl& decl, KeyCheck<T> check)
    : path_(decl.path), required_(decl.default_value == "required"),
      default_(literal_default<T>(decl.default_value)), check_(std::move(check)) {}

template <class T>
T Key<T>::checked(const CaseFile& case_file, T value) const {
  if (check_) {
    if (const std::string reason = check_(value); !reason.empty()) {
      case_file.fail(path_, reason);
    }
  }
  return value;
}

template <class T>
T Key<T>::read(const CaseFile& case_file) const {
  if (required_) {
    return checked(case_file, key_detail::read_present<T>(case_file, path_));
  }
  if (!default_) {
    throw std::logic_error("case key \"" + path_ +
                           "\": its default is a description; read it with read_or");
  }
  return checked(case_file, key_detail::read_or<T>(case_file, path_, *default_));
}

template <class T>
T Key<T>::read_or(const CaseFile& case_file, T computed) const {
  return checked(case_file, case_file.has(path_) ? key_detail::read_present<T>(case_file, path_)
                                                 : std::move(computed));
}

template <class T>
T Key<T>::require(const CaseFile& case_file) const {
  return checked(case_file, key_detail::read_present<T>(case_file, path_));
}

template <class T>
std::optional<T> Key<T>::read_optional(const CaseFile& case_file) const {
  if (!case_file.has(path_)) {
    return std::nullopt;
  }
  return require(case_file);
}

template <class E>
Choice<E>::Choice(const KeyDecl& decl, std::vector<std::pair<std::string, E>> values)
    : path_(decl.path), default_(literal_default<std::string>(decl.default_value)),
      values_(std::move(values)) {}

template <class E>
E Choice<E>::read(const CaseFile& case_file) const {
  const std::string name =
      default_ ? case_file.string_or(path_, *default_) : case_file.string(path_);
  std::vector<std::string> names;
  for (const auto& [value_name, value] : values_) {
    if (value_name == name) {
      return value;
    }
    names.push_back(value_name);
  }
  case_file.fail(path_, expected_one_of(names, name));
}

} // namespace revsph
