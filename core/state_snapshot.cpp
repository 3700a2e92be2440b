#include "core/state_snapshot.hpp"

#include "fixedpoint/conversion.hpp"

namespace revsph {

double FieldSnapshot::real_of(std::int64_t raw) const {
  if (kind == RawKind::ieee_double) {
    return std::bit_cast<double>(raw);
  }
  return fixedpoint::to_real(raw, info.scale);
}

const FieldSnapshot* StateSnapshot::find(const std::string& particle_set,
                                         const std::string& name) const {
  for (const FieldSnapshot& field : fields) {
    if (field.info.particle_set == particle_set && field.info.name == name) {
      return &field;
    }
  }
  return nullptr;
}

FieldSnapshot* StateSnapshot::find(const std::string& particle_set, const std::string& name) {
  const auto* self = this;
  return const_cast<FieldSnapshot*>(self->find(particle_set, name));
}

const SetRows* StateSnapshot::rows_of(const std::string& particle_set) const {
  for (const SetRows& rows : pieces) {
    if (rows.set == particle_set) {
      return &rows;
    }
  }
  return nullptr;
}

std::uint64_t whole_count(const StateSnapshot& state, const FieldSnapshot& field) {
  if (state.pieces.empty()) {
    return field.count;
  }
  const SetRows* rows = state.rows_of(field.info.particle_set);
  if (rows == nullptr) {
    throw std::invalid_argument("no rows of particle set " + field.info.particle_set);
  }
  return rows->total;
}

void require_same_layout(const FieldSnapshot& expected, const FieldSnapshot& found) {
  const VariableInfo& a = expected.info;
  const VariableInfo& b = found.info;
  const std::string what = a.particle_set + "." + a.name;
  if (a.particle_set != b.particle_set || a.name != b.name) {
    throw std::invalid_argument("snapshot field " + b.particle_set + "." + b.name +
                                " where the model declares " + what);
  }
  if (a.components != b.components || expected.count != found.count) {
    throw std::invalid_argument("snapshot field " + what + " has a different shape (components " +
                                std::to_string(b.components) + " x particles " +
                                std::to_string(found.count) + ", expected " +
                                std::to_string(a.components) + " x " +
                                std::to_string(expected.count) + ")");
  }
  if (!(a.scale == b.scale) || expected.kind != found.kind) {
    throw std::invalid_argument("snapshot field " + what +
                                " uses a different fixed-point scale or arithmetic");
  }
}

} // namespace revsph
