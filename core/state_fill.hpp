#pragma once
// Filling a set's fields, by the names its state table declares, from the real values a model's
// setup computed (positions, velocities, entropies, masses), with the one-line case error naming
// a key when a value does not fit the field's fixed-point scale.

#include "core/case_file.hpp"
#include "core/geometry.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"

#include <functional>
#include <initializer_list>
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

// Fills the named fields of `set`, `count` particles each (values of another length, or a name
// the set does not declare, are a logic error); its other fields are left as they are.
template <class Arith, int D, ParticleSet Set>
void fill_set(const CaseFile& case_file, Set& set, std::size_t count,
              std::initializer_list<FieldFill<D>> fills) {
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
  }
}

} // namespace revsph
