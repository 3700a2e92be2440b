#include "verify/state_compare.hpp"

#include "fixedpoint/exact_sum.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
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

StateComparison compare_states(const StateSnapshot& expected, const StateSnapshot& actual) {
  StateComparison result;
  if (expected.fields.size() != actual.fields.size()) {
    result.identical = false;
    result.layout_error = "the states have different numbers of variables";
    return result;
  }
  for (std::size_t f = 0; f < expected.fields.size(); ++f) {
    const FieldSnapshot& e = expected.fields[f];
    const FieldSnapshot& a = actual.fields[f];
    try {
      require_same_layout(e, a);
    } catch (const std::invalid_argument& error) {
      result.identical = false;
      result.layout_error = error.what();
      return result;
    }
    VariableDifference difference{e.info.particle_set, e.info.name, 0, e.raw().size(), 0, 0.0,
                                  e.info.unit,         {}};
    for (std::size_t i = 0; i < e.count; ++i) {
      for (int c = 0; c < e.info.components; ++c) {
        const std::int64_t expected_bits = e.at(c, i);
        const std::int64_t actual_bits = a.at(c, i);
        if (expected_bits == actual_bits) {
          continue;
        }
        const ValueLocation location{e.info.particle_set,
                                     e.info.name + component_suffix(e, c),
                                     i,
                                     c,
                                     expected_bits,
                                     actual_bits,
                                     e.real(c, i),
                                     a.real(c, i),
                                     e.info.unit};
        if (!result.first_difference) {
          result.first_difference = location;
        }
        ++difference.differing_values;
        const std::uint64_t ulps = units_in_last_place(e, expected_bits, actual_bits);
        if (ulps > difference.max_units_in_last_place) {
          difference.max_units_in_last_place = ulps;
          difference.worst = location;
        }
        const double abs_difference = std::fabs(e.real(c, i) - a.real(c, i));
        if (abs_difference > difference.max_abs_difference || std::isnan(abs_difference)) {
          difference.max_abs_difference = abs_difference;
        }
      }
    }
    result.compared_values += e.raw().size();
    if (difference.differing_values > 0) {
      result.identical = false;
      result.differences.push_back(std::move(difference));
    }
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
