#pragma once
// Filling a set's fields, by the names its state table declares, from the real values a model's
// setup computed (positions, velocities, entropies, masses), with the one-line case error naming
// a key when a value does not fit the field's fixed-point scale.

#include "core/case_file.hpp"
#include "core/field_components.hpp"
#include "core/geometry.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_sets.hpp"
#include "core/periodic_wrap.hpp"
#include "core/state_field.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

namespace revsph {

namespace detail {
// Sizes the field to `count` particles (zeros) and sets their first `components` components to
// value(i, k), failing on `key` for one that does not fit.
template <class Arith, class Value>
void fill_components(const CaseFile& case_file, const char* key, std::size_t count, int components,
                     const Value& value, StateField<typename Arith::Raw>& field) {
  field.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    for (int k = 0; k < components; ++k) {
      if (!Arith::try_from_real(value(i, k), field.info().scale, field.at(k, i))) {
        case_file.fail(key, "a particle's " + field.info().name +
                                " does not fit its fixed-point scale (see [fixed_point])");
      }
    }
  }
}
} // namespace detail

// What one field of a set is filled with, the field named as its state table declares it: real
// values per particle (D-vectors for a vector field, numbers for a scalar one) or one number for
// every particle (into the first component: 0.0 for a field that starts at zero); `key` is the
// case key a value that does not fit the field's scale is blamed on.
template <int D>
struct FieldFill {
  std::string_view field;
  const char* key;
  std::variant<std::span<const Vec<D>>, std::span<const double>, double> values;
};

// A per-particle value a set-up computes state from rather than a state field (wcsph's initial
// density, which sets the density constants C_a): a point file's column `name` [unit] replaces
// values[i] of the particles it places with from_file(its value), which is NaN for a value the
// model does not admit (`admits` says which it does). Values that share one span are one thing
// (`what`) given in different ways: a file gives one of them.
struct SetUpValue {
  std::string_view name;
  std::string_view unit;
  std::span<double> values;
  std::function<double(double)> from_file;
  std::string admits; // "above 0 kg/m^3"
  std::string what;   // "the initial density"
};

namespace detail {

// Whether fills `a` and `b` were given the same per-particle values: fields that start equal
// (superfluid's velocity and velocity_copy; its wall's velocity and superflow velocity).
template <int D>
bool same_values(const FieldFill<D>& a, const FieldFill<D>& b) {
  return std::visit(
      [](const auto& x, const auto& y) {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (std::is_same_v<X, Y> && !std::is_same_v<X, double>) {
          return x.data() == y.data() && x.size() == y.size();
        } else {
          return false;
        }
      },
      a.values, b.values);
}

// Whether fill `copy` is the copy of fill `original` (a field NAME_copy starting equal to NAME):
// a copy is not given on its own, so that the copies start equal.
template <int D>
bool is_copy_of(const FieldFill<D>& copy, const FieldFill<D>& original) {
  return copy.field == std::string(original.field) + "_copy" && same_values(copy, original);
}

// The fills a point file may give values to: every one but the positions (its x, y, z columns),
// the copies of others and the constants a model computes after filling them with 0
// (integration constants).
template <int D, class Field>
bool file_may_give(const FieldFill<D>& fill, const Field& field,
                   std::initializer_list<FieldFill<D>> fills) {
  const bool computed_later = std::holds_alternative<double>(fill.values) && !field.info().evolved;
  const bool copy = std::ranges::any_of(
      fills, [&](const FieldFill<D>& original) { return is_copy_of(fill, original); });
  return fill.field != "position" && !computed_later && !copy;
}

// Where each of a point file's columns goes: a component of a filled field, or a set-up value.
template <int D>
struct ColumnTarget {
  const FieldFill<D>* fill = nullptr;
  int component = 0;
  const SetUpValue* set_up = nullptr;
};

// A field of several components (a vector, a tensor) that a file gives in part would start with
// the set-up's value in the others: refused, naming the first missing column.
template <int D, class Field>
void require_every_component(const CaseFile& case_file, const std::string& file_key,
                             const std::string& source, const Field& field,
                             const std::set<std::string>& given) {
  bool some = false;
  std::string missing;
  for (int c = 0; c < field.components(); ++c) {
    const std::string name = component_name(field.info().name, D, field.components(), c);
    some = some || given.contains(name);
    if (missing.empty() && !given.contains(name)) {
      missing = name;
    }
  }
  if (some && !missing.empty()) {
    case_file.fail(file_key, source + ": no column " + missing + " [" + field.info().unit +
                                 "]: a file gives every component of " + field.info().name +
                                 " or none");
  }
}

// The values the "points" blocks of this set's kind give its fields (core/point_file.hpp),
// after the set-up's own: each file particle is found by its position in the set (where the
// set-up put it), each column is a component of a filled field in that field's unit or one of
// the set-up's values.
template <class Arith, int D, ParticleSet Set>
void fill_from_point_files(const CaseFile& case_file, Set& set,
                           std::initializer_list<FieldFill<D>> fills,
                           std::initializer_list<SetUpValue> set_up_values) {
  using Raw = typename Arith::Raw;
  using Field = StateField<Raw>;
  const std::vector<PointBlockValues<D>> blocks =
      point_blocks_with_values<D>(case_file, Set::set.name);
  if (blocks.empty()) {
    return;
  }
  std::map<std::string_view, Field*> fields;
  for_each_field_of(set, [&](Field& field) { fields[field.info().name] = &field; });
  const Field& position = *fields.at("position");
  std::map<std::array<Raw, D>, std::size_t> row_at;
  for (std::size_t i = 0; i < position.count(); ++i) {
    std::array<Raw, D> key{};
    for (int k = 0; k < D; ++k) {
      key[k] = position.at(k, i);
    }
    row_at.emplace(key, i);
  }
  for (const PointBlockValues<D>& block : blocks) {
    const std::string file_key = block.key + ".file";
    const PointFile<D>& file = block.file;
    std::vector<std::size_t> rows(file.positions.size());
    for (std::size_t p = 0; p < rows.size(); ++p) {
      std::array<Raw, D> key{};
      for (int k = 0; k < D; ++k) {
        Arith::try_from_real(file.positions[p][k], position.info().scale, key[k]);
      }
      const auto found = row_at.find(key);
      if (found == row_at.end()) {
        case_file.fail(file_key, point_place<D>(file, p, "x") + ": the particle" +
                                     " is not where the set-up left it (an initial "
                                     "state correction moves particles): its values have no "
                                     "particle");
      }
      rows[p] = found->second;
    }
    std::vector<ColumnTarget<D>> targets;
    std::set<std::string> given;
    std::map<const double*, std::string> set_up_given; // a set-up value and the column giving it
    for (const PointColumn& column : file.columns) {
      ColumnTarget<D> target;
      std::string allowed;
      for (const FieldFill<D>& fill : fills) {
        Field& field = *fields.at(fill.field);
        if (!file_may_give(fill, field, fills)) {
          continue;
        }
        for (int c = 0; c < field.components(); ++c) {
          const std::string name = component_name(field.info().name, D, field.components(), c);
          allowed += (allowed.empty() ? "" : ", ") + name + " [" + field.info().unit + "]";
          if (name == column.name) {
            target.fill = &fill;
            target.component = c;
          }
        }
      }
      for (const SetUpValue& value : set_up_values) {
        allowed += (allowed.empty() ? "" : ", ") + std::string(value.name) + " [" +
                   std::string(value.unit) + "]";
        if (value.name == column.name) {
          target.set_up = &value;
        }
      }
      if (target.fill == nullptr && target.set_up == nullptr) {
        case_file.fail(file_key, file.source + ": column " + column.name +
                                     ": no such initial value of set " +
                                     std::string(Set::set.name) + " (it takes " + allowed + ")");
      }
      const std::string unit = target.fill != nullptr ? fields.at(target.fill->field)->info().unit
                                                      : std::string(target.set_up->unit);
      if (column.unit != unit) {
        case_file.fail(file_key, file.source + ": column " + column.name + " is in [" +
                                     column.unit + "]; the field is in [" + unit + "]");
      }
      if (target.set_up != nullptr) {
        const auto [other, fresh] = set_up_given.emplace(target.set_up->values.data(), column.name);
        if (!fresh) {
          case_file.fail(file_key, file.source + ": columns " + other->second + " and " +
                                       column.name + " give one thing (" + target.set_up->what +
                                       "): give one of them");
        }
      }
      given.insert(column.name);
      targets.push_back(target);
    }
    for (const FieldFill<D>& fill : fills) {
      require_every_component<D>(case_file, file_key, file.source, *fields.at(fill.field), given);
    }
    for (std::size_t c = 0; c < file.columns.size(); ++c) {
      const PointColumn& column = file.columns[c];
      const ColumnTarget<D>& target = targets[c];
      if (target.set_up != nullptr) {
        const SetUpValue& value = *target.set_up;
        for (std::size_t p = 0; p < rows.size(); ++p) {
          const double converted =
              value.from_file ? value.from_file(column.values[p]) : column.values[p];
          if (!std::isfinite(converted)) { // the model does not admit it
            case_file.fail(file_key, point_place<D>(file, p, column.name) + ": " +
                                         format_number(column.values[p]) + " [" + column.unit +
                                         "], but it must be " + value.admits);
          }
          value.values[rows[p]] = converted;
        }
        continue;
      }
      // The file's value goes to its field, and to the fields that start equal to it unless
      // the file gives them their own.
      for (const FieldFill<D>& fill : fills) {
        Field& field = *fields.at(fill.field);
        const bool own = given.contains(
            component_name(field.info().name, D, field.components(), target.component));
        if (&fill != target.fill && (own || !same_values(fill, *target.fill))) {
          continue;
        }
        for (std::size_t p = 0; p < rows.size(); ++p) {
          if (field.info().positive && !(column.values[p] > 0.0)) {
            case_file.fail(file_key, point_place<D>(file, p, column.name) + ": " +
                                         format_number(column.values[p]) + " [" + column.unit +
                                         "], but a " + field.info().name + " is positive");
          }
          if (!Arith::try_from_real(column.values[p], field.info().scale,
                                    field.at(target.component, rows[p]))) {
            case_file.fail(file_key,
                           point_place<D>(file, p, column.name) +
                               ": does not fit its fixed-point scale (see [fixed_point])");
          }
        }
      }
    }
  }
}

// A position field's periodic axes ([domain] periodic): every particle must lie in the period,
// [domain.min, domain.max) on those axes, where the drift's wrap keeps it.
template <class Arith, int D>
void set_period(const CaseFile& case_file, StateField<typename Arith::Raw>& position) {
  const PeriodicBox period = read_periodic_box<D>(case_file);
  if (!period.any()) {
    return;
  }
  for (int k = 0; k < D; ++k) {
    typename Arith::Raw face{};
    if (period.periodic[k] && (!Arith::try_from_real(period.min[k], position.info().scale, face) ||
                               !Arith::try_from_real(period.max[k], position.info().scale, face))) {
      case_file.fail("domain.periodic",
                     "the faces on axis " + axis_name(k) + " do not fit the position scale");
    }
  }
  position.set_period(period);
  const RawPeriod<typename Arith::Raw> raw = raw_period<typename Arith::Raw>(position.info());
  for (std::size_t i = 0; i < position.count(); ++i) {
    for (int k = 0; k < D; ++k) {
      const auto x = position.at(k, i);
      if (raw.periodic[k] && !(x >= raw.lower[k] && x < raw.lower[k] + raw.period[k])) {
        case_file.fail("domain.periodic",
                       "a " + position.info().particle_set + " particle at " + axis_name(k) +
                           " = " + std::to_string(Arith::real(x, position.info().scale)) +
                           " lies outside the period [domain.min, domain.max) of that axis");
      }
    }
  }
}

} // namespace detail

// Fills the named fields of `set`, `count` particles each (values of another length, or a name
// the set does not declare, are a logic error); its other fields are left as they are. Then the
// point files of the set's kind give their values (detail::fill_from_point_files): a field in
// `fills` is a field whose initial value a user may give, and so is each of `set_up_values`.
template <class Arith, int D, ParticleSet Set>
void fill_set(const CaseFile& case_file, Set& set, std::size_t count,
              std::initializer_list<FieldFill<D>> fills,
              std::initializer_list<SetUpValue> set_up_values = {}) {
  using Field = StateField<typename Arith::Raw>;
  for (const FieldFill<D>& fill : fills) {
    Field* target = nullptr;
    for_each_field_of(set, [&](Field& field) {
      if (field.info().name == fill.field) {
        target = &field;
      }
    });
    const std::string where = std::string(Set::set.name) + "." + std::string(fill.field);
    if (target == nullptr) {
      throw std::logic_error("fill_set: no field " + where);
    }
    std::visit(
        [&](const auto& values) {
          using Values = std::decay_t<decltype(values)>;
          if constexpr (std::is_same_v<Values, double>) {
            detail::fill_components<Arith>(
                case_file, fill.key, count, 1, [&](std::size_t, int) { return values; }, *target);
          } else {
            if (values.size() != count) {
              throw std::logic_error("fill_set: " + where + " given " +
                                     std::to_string(values.size()) + " values for " +
                                     std::to_string(count) + " particles");
            }
            if constexpr (std::is_same_v<Values, std::span<const double>>) {
              detail::fill_components<Arith>(
                  case_file, fill.key, count, 1, [&](std::size_t i, int) { return values[i]; },
                  *target);
            } else {
              if (target->components() != D) {
                throw std::logic_error("fill_set: " + where + " is not a vector field");
              }
              detail::fill_components<Arith>(
                  case_file, fill.key, count, D, [&](std::size_t i, int k) { return values[i][k]; },
                  *target);
            }
          }
        },
        fill.values);
    if (fill.field == "position") {
      detail::set_period<Arith, D>(case_file, *target);
    }
  }
  detail::fill_from_point_files<Arith, D>(case_file, set, fills, set_up_values);
}

} // namespace revsph
