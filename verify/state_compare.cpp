#include "verify/state_compare.hpp"

#include "core/distributed/records_of_every_process.hpp"
#include "fixedpoint/exact_sum.hpp"
#include "verify/aligned_states.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace revsph {

namespace {

using fixedpoint::int128;

std::string component_suffix(const FieldSnapshot& field, int component) {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "[" + std::string + "]".
  std::string suffix;
  if (field.info.components > 1) {
    suffix.append("[").append(std::to_string(component)).append("]");
  }
  return suffix;
}

} // namespace

std::uint64_t units_in_last_place(const FieldSnapshot& field, std::int64_t a, std::int64_t b) {
  constexpr auto largest = std::numeric_limits<std::uint64_t>::max();
  if (field.kind == RawKind::ieee_double) {
    const double units = std::ceil(std::fabs(std::bit_cast<double>(a) - std::bit_cast<double>(b)) /
                                   field.info.scale.unit());
    return !(units < 1.8e19) ? largest : static_cast<std::uint64_t>(units);
  }
  const int128 difference = int128{a} - int128{b};
  const int128 magnitude = difference < 0 ? -difference : difference;
  return magnitude > int128{largest} ? largest : static_cast<std::uint64_t>(magnitude);
}

namespace {

// What one process finds about one variable on its rows: numbers only, so that the processes of
// a distributed run can send them to each other and combine them (`then`) in index order.
struct RawLocation {
  std::uint64_t particle = 0;
  std::int64_t component = 0;
  std::int64_t expected = 0;
  std::int64_t actual = 0;
};
struct VariableFindings {
  std::uint64_t differing_values = 0;
  std::uint64_t max_units_in_last_place = 0;
  double max_abs_difference = 0.0;
  std::uint64_t has_first = 0;
  RawLocation first;
  RawLocation worst; // the first value reaching max_units_in_last_place
};

VariableFindings compare_variable(const FieldSnapshot& e, const FieldSnapshot& a,
                                  std::uint64_t first_index) {
  VariableFindings found;
  for (std::size_t i = 0; i < e.count; ++i) {
    for (int c = 0; c < e.info.components; ++c) {
      const std::int64_t expected_bits = e.at(c, i);
      const std::int64_t actual_bits = a.at(c, i);
      if (expected_bits == actual_bits) {
        continue;
      }
      const RawLocation location{first_index + i, c, expected_bits, actual_bits};
      if (found.has_first == 0) {
        found.has_first = 1;
        found.first = location;
      }
      ++found.differing_values;
      const std::uint64_t ulps = units_in_last_place(e, expected_bits, actual_bits);
      if (ulps > found.max_units_in_last_place) {
        found.max_units_in_last_place = ulps;
        found.worst = location;
      }
      const double abs_difference = std::fabs(e.real(c, i) - a.real(c, i));
      if (abs_difference > found.max_abs_difference || std::isnan(abs_difference)) {
        found.max_abs_difference = abs_difference;
      }
    }
  }
  return found;
}

// `earlier`'s rows all precede `later`'s in index order.
void then(VariableFindings& earlier, const VariableFindings& later) {
  if (earlier.has_first == 0 && later.has_first != 0) {
    earlier.has_first = 1;
    earlier.first = later.first;
  }
  earlier.differing_values += later.differing_values;
  if (later.max_units_in_last_place > earlier.max_units_in_last_place) {
    earlier.max_units_in_last_place = later.max_units_in_last_place;
    earlier.worst = later.worst;
  }
  if (later.max_abs_difference > earlier.max_abs_difference ||
      std::isnan(later.max_abs_difference)) {
    earlier.max_abs_difference = later.max_abs_difference;
  }
}

ValueLocation located(const FieldSnapshot& field, const RawLocation& at) {
  const int c = static_cast<int>(at.component);
  return ValueLocation{field.info.particle_set,
                       field.info.name + component_suffix(field, c),
                       at.particle,
                       c,
                       at.expected,
                       at.actual,
                       field.real_of(at.expected),
                       field.real_of(at.actual),
                       field.info.unit};
}

} // namespace

StateComparison compare_states(const StateSnapshot& expected, const StateSnapshot& actual) {
  StateComparison result;
  std::optional<AlignedStates> aligned;
  try {
    aligned.emplace(expected, actual);
  } catch (const std::invalid_argument& error) {
    result.identical = false;
    result.layout_error = error.what();
    return result;
  }
  const std::vector<FieldSnapshot>& e = aligned->expected().fields;
  const std::vector<FieldSnapshot>& a = aligned->actual().fields;
  std::vector<VariableFindings> found;
  for (std::size_t f = 0; f < e.size(); ++f) {
    found.push_back(compare_variable(e[f], a[f], aligned->first_index(e[f])));
  }
  if (aligned->in_pieces()) {
    // Every process's findings, combined in rank order: index order.
    found = distributed::combined_in_rank_order(std::span<const VariableFindings>(found), then);
  }
  for (std::size_t f = 0; f < e.size(); ++f) {
    const std::uint64_t values =
        static_cast<std::uint64_t>(whole_count(aligned->expected(), e[f])) *
        static_cast<std::uint64_t>(e[f].info.components);
    result.compared_values += values;
    const VariableFindings& v = found[f];
    if (v.differing_values == 0) {
      continue;
    }
    if (!result.first_difference) {
      result.first_difference = located(e[f], v.first);
    }
    result.identical = false;
    result.differences.push_back(VariableDifference{
        e[f].info.particle_set, e[f].info.name, v.differing_values, values,
        v.max_units_in_last_place, v.max_abs_difference, e[f].info.unit, located(e[f], v.worst)});
  }
  return result;
}

std::string StateComparison::verdict() const {
  std::ostringstream out;
  out.precision(17);
  if (!layout_error.empty()) {
    out << "cannot compare: " << layout_error;
    return out.str();
  }
  if (identical) {
    out << "bitwise identical (" << compared_values << " raw values compared)";
    return out.str();
  }
  const ValueLocation& first = *first_difference;
  std::size_t differing = 0;
  std::uint64_t worst = 0;
  for (const VariableDifference& d : differences) {
    differing += d.differing_values;
    worst = std::max(worst, d.max_units_in_last_place);
  }
  out << "NOT identical: first difference at " << first.particle_set << " particle "
      << first.particle << ", " << first.variable << " (expected " << first.expected_value << " "
      << first.unit << ", got " << first.actual_value << " " << first.unit << "); " << differing
      << " of " << compared_values << " values differ, largest difference " << worst
      << " units in the last place";
  return out.str();
}

std::vector<std::string> StateComparison::details() const {
  std::vector<std::string> lines;
  for (const VariableDifference& d : differences) {
    std::ostringstream out;
    out << d.particle_set << "." << d.variable << ": " << d.differing_values << " of "
        << d.total_values << " values differ; largest " << d.max_units_in_last_place
        << " units in the last place (" << d.max_abs_difference << " " << d.unit << ") at "
        << d.worst.particle_set << " particle " << d.worst.particle << ", " << d.worst.variable;
    lines.push_back(out.str());
  }
  return lines;
}

} // namespace revsph
