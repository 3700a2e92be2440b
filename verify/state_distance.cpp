#include "verify/state_distance.hpp"

#include "core/distributed/records_of_every_process.hpp"
#include "fixedpoint/exact_double_sum.hpp"
#include "verify/aligned_states.hpp"
#include "verify/state_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace revsph {

namespace {

using fixedpoint::ExactDoubleSum;

// What one process finds about one variable on its rows, as numbers (the sums as exact images),
// so that the processes of a distributed run can combine them (`then`) in index order. The sums
// are exact: the RMS values do not depend on who added what.
struct VariableFindings {
  std::uint64_t differing_values = 0;
  std::uint64_t max_units_in_last_place = 0;
  double max_difference = 0.0;
  std::uint64_t worst_particle = 0;
  ExactDoubleSum::Image squares{};           // of the per-particle norms of the difference
  ExactDoubleSum::Image reference_squares{}; // of the first state's values
  ExactDoubleSum::Image units_squares{};     // of the differences in units of the last place
};

VariableFindings measure_variable(const FieldSnapshot& from, const FieldSnapshot& to,
                                  std::uint64_t first_index) {
  VariableFindings found;
  ExactDoubleSum squares;
  ExactDoubleSum reference_squares;
  ExactDoubleSum units_squares;
  for (std::size_t i = 0; i < from.count; ++i) {
    double squared_norm = 0.0;
    for (int c = 0; c < from.info.components; ++c) {
      const double reference = from.real(c, i);
      reference_squares.add(reference * reference);
      if (from.at(c, i) == to.at(c, i)) {
        continue;
      }
      ++found.differing_values;
      const double difference = to.real(c, i) - reference;
      squared_norm += difference * difference;
      const std::uint64_t units = units_in_last_place(from, from.at(c, i), to.at(c, i));
      found.max_units_in_last_place = std::max(found.max_units_in_last_place, units);
      units_squares.add(static_cast<double>(units) * static_cast<double>(units));
    }
    squares.add(squared_norm);
    const double norm = std::sqrt(squared_norm);
    // NaN (a value that became NaN) counts as the worst.
    if (norm > found.max_difference || (std::isnan(norm) && !std::isnan(found.max_difference))) {
      found.max_difference = norm;
      found.worst_particle = first_index + i;
    }
  }
  found.squares = squares.image();
  found.reference_squares = reference_squares.image();
  found.units_squares = units_squares.image();
  return found;
}

ExactDoubleSum::Image sum_of(const ExactDoubleSum::Image& a, const ExactDoubleSum::Image& b) {
  ExactDoubleSum sum = ExactDoubleSum::from_image(a);
  sum.add(ExactDoubleSum::from_image(b));
  return sum.image();
}

// `earlier`'s rows all precede `later`'s in index order.
void then(VariableFindings& earlier, const VariableFindings& later) {
  earlier.differing_values += later.differing_values;
  earlier.max_units_in_last_place =
      std::max(earlier.max_units_in_last_place, later.max_units_in_last_place);
  if (later.max_difference > earlier.max_difference ||
      (std::isnan(later.max_difference) && !std::isnan(earlier.max_difference))) {
    earlier.max_difference = later.max_difference;
    earlier.worst_particle = later.worst_particle;
  }
  earlier.squares = sum_of(earlier.squares, later.squares);
  earlier.reference_squares = sum_of(earlier.reference_squares, later.reference_squares);
  earlier.units_squares = sum_of(earlier.units_squares, later.units_squares);
}

} // namespace

StateDistance state_distance(const StateSnapshot& from, const StateSnapshot& to) {
  const AlignedStates aligned(from, to);
  const std::vector<FieldSnapshot>& a = aligned.expected().fields;
  const std::vector<FieldSnapshot>& b = aligned.actual().fields;
  std::vector<VariableFindings> found;
  for (std::size_t f = 0; f < a.size(); ++f) {
    found.push_back(measure_variable(a[f], b[f], aligned.first_index(a[f])));
  }
  if (aligned.in_pieces()) {
    // Every process's findings, combined in rank order: index order.
    found = distributed::combined_in_rank_order(std::span<const VariableFindings>(found), then);
  }
  StateDistance result;
  for (std::size_t f = 0; f < a.size(); ++f) {
    const VariableFindings& v = found[f];
    VariableDistance distance;
    distance.particle_set = a[f].info.particle_set;
    distance.variable = a[f].info.name;
    distance.unit = a[f].info.unit;
    distance.evolved = a[f].info.evolved;
    distance.particles = whole_count(aligned.expected(), a[f]);
    distance.total_values = distance.particles * static_cast<std::size_t>(a[f].info.components);
    distance.differing_values = v.differing_values;
    distance.max_difference = v.max_difference;
    distance.worst_particle = v.worst_particle;
    distance.max_units_in_last_place = v.max_units_in_last_place;
    if (distance.particles > 0) {
      const auto particles = static_cast<double>(distance.particles);
      distance.rms_difference =
          std::sqrt(ExactDoubleSum::from_image(v.squares).value() / particles);
      distance.reference_rms =
          std::sqrt(ExactDoubleSum::from_image(v.reference_squares).value() / particles);
      distance.rms_units_in_last_place =
          std::sqrt(ExactDoubleSum::from_image(v.units_squares).value() /
                    static_cast<double>(distance.total_values));
    }
    result.variables.push_back(std::move(distance));
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
