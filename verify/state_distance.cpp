#include "verify/state_distance.hpp"

#include "verify/state_compare.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace revsph {

namespace {

VariableDistance distance_of(const FieldSnapshot& from, const FieldSnapshot& to) {
  require_same_layout(from, to);
  VariableDistance distance;
  distance.particle_set = from.info.particle_set;
  distance.variable = from.info.name;
  distance.unit = from.info.unit;
  distance.evolved = from.info.evolved;
  distance.particles = from.count;
  distance.total_values = from.raw().size();
  double sum_of_squares = 0.0;
  double reference_sum_of_squares = 0.0;
  double units_sum_of_squares = 0.0;
  for (std::size_t i = 0; i < from.count; ++i) {
    double squared_norm = 0.0;
    for (int c = 0; c < from.info.components; ++c) {
      const double reference = from.real(c, i);
      reference_sum_of_squares += reference * reference;
      if (from.at(c, i) == to.at(c, i)) {
        continue;
      }
      ++distance.differing_values;
      const double difference = to.real(c, i) - reference;
      squared_norm += difference * difference;
      const std::uint64_t units = units_in_last_place(from, from.at(c, i), to.at(c, i));
      distance.max_units_in_last_place = std::max(distance.max_units_in_last_place, units);
      units_sum_of_squares += static_cast<double>(units) * static_cast<double>(units);
    }
    sum_of_squares += squared_norm;
    const double norm = std::sqrt(squared_norm);
    // NaN (a value that became NaN) counts as the worst.
    if (norm > distance.max_difference ||
        (std::isnan(norm) && !std::isnan(distance.max_difference))) {
      distance.max_difference = norm;
      distance.worst_particle = i;
    }
  }
  if (from.count > 0) {
    const auto particles = static_cast<double>(from.count);
    distance.rms_difference = std::sqrt(sum_of_squares / particles);
    distance.reference_rms = std::sqrt(reference_sum_of_squares / particles);
  }
  if (distance.total_values > 0) {
    distance.rms_units_in_last_place =
        std::sqrt(units_sum_of_squares / static_cast<double>(distance.total_values));
  }
  return distance;
}

} // namespace

StateDistance state_distance(const StateSnapshot& from, const StateSnapshot& to) {
  if (from.fields.size() != to.fields.size()) {
    throw std::invalid_argument("the states have different numbers of variables (" +
                                std::to_string(from.fields.size()) + " and " +
                                std::to_string(to.fields.size()) + ")");
  }
  StateDistance result;
  for (std::size_t f = 0; f < from.fields.size(); ++f) {
    result.variables.push_back(distance_of(from.fields[f], to.fields[f]));
  }
  return result;
}

bool StateDistance::identical() const {
  for (const VariableDistance& variable : variables) {
    if (!variable.identical()) {
      return false;
    }
  }
  return true;
}

std::vector<const VariableDistance*> StateDistance::differing() const {
  std::vector<const VariableDistance*> result;
  for (const VariableDistance& variable : variables) {
    if (!variable.identical()) {
      result.push_back(&variable);
    }
  }
  return result;
}

std::vector<std::string> StateDistance::table() const {
  std::vector<std::string> lines;
  for (const VariableDistance* d : differing()) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: max %.3e %s, RMS %.3e %s (RMS value %.3e %s; worst particle %zu); %zu of "
                  "%zu values differ, largest %.3e units in the last place, RMS %.3e",
                  d->name().c_str(), d->max_difference, d->unit.c_str(), d->rms_difference,
                  d->unit.c_str(), d->reference_rms, d->unit.c_str(), d->worst_particle,
                  d->differing_values, d->total_values,
                  static_cast<double>(d->max_units_in_last_place), d->rms_units_in_last_place);
    lines.emplace_back(line);
  }
  return lines;
}

} // namespace revsph
