#pragma once
// Setting a state field from the real values a model's setup computed (positions, velocities,
// entropies, masses), with the one-line case error naming `key` when a value does not fit the
// field's fixed-point scale.

#include "core/case_file.hpp"
#include "core/geometry.hpp"
#include "core/state_field.hpp"

#include <string>
#include <vector>

namespace revsph {

template <class Arith, int D>
void fill_vector_field(const CaseFile& case_file, const char* key,
                       const std::vector<Vec<D>>& values, StateField<typename Arith::Raw>& field) {
  field.resize(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      if (!Arith::try_from_real(values[i][k], field.info().scale, field.at(k, i))) {
        case_file.fail(key, "a particle's " + field.info().name +
                                " does not fit its fixed-point scale (see [fixed_point])");
      }
    }
  }
}

template <class Arith>
void fill_scalar_field(const CaseFile& case_file, const char* key,
                       const std::vector<double>& values, StateField<typename Arith::Raw>& field) {
  field.resize(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!Arith::try_from_real(values[i], field.info().scale, field.at(0, i))) {
      case_file.fail(key, "a particle's " + field.info().name +
                              " does not fit its fixed-point scale (see [fixed_point])");
    }
  }
}

} // namespace revsph
