#include "core/case_key.hpp"
#include "core/step_splitting.hpp"

namespace revsph {

std::string expected_one_of(const std::vector<std::string>& names, const std::string& got) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) {
      list += i + 1 == names.size() ? " or " : ", ";
    }
    list += "\"" + names[i] + "\"";
  }
  return "expected " + list + ", got \"" + got + "\"";
}

KeyCheck<double> non_negative(std::string zero_means) {
  return [zero_means = std::move(zero_means)](const double& value) {
    return non_negative_or_why(value, zero_means);
  };
}

ScaleKey KeySet::scale(const std::string& quantity, const std::string& magnitude, int fraction_bits,
                       std::string meaning, const std::string& note) {
  std::string covers =
      "covers " + magnitude + " with " + std::to_string(fraction_bits) + " fraction bits";
  if (!note.empty()) {
    covers += " " + note;
  }
  return {declare({"fixed_point." + quantity + "_exponent", KeyType::integer, "-",
                   std::move(covers), std::move(meaning)}),
          fraction_bits};
}

PositionScaleKey KeySet::position_scale() {
  declare({"fixed_point.position_exponent", KeyType::integer, "-",
           "covers the domain with " + std::to_string(position_fraction_bits) + " fraction bits",
           "positions are stored as integers times 2^exponent"});
  return {};
}

Key<double> KeySet::gravity(std::string_view detail) {
  return number("physics.gravity", "m/s^2", "0",
                "gravitational acceleration g along minus the last axis" +
                    (detail.empty() ? std::string() : "; " + std::string(detail)));
}

Key<double> KeySet::gravity_reference_height() {
  return number("physics.gravity_reference_height", "m", "0",
                "height of zero gravitational energy (shifts the reported energy only)");
}

Choice<Splitting> KeySet::splitting(const std::string& default_name) {
  return choice<Splitting>(
      "step.splitting", "\"" + default_name + "\"",
      "where the irreversible operators (dissipation, relaxation) go in the step "
      "(core/step_splitting.hpp): \"strang\", half updates at the step's ends (or the sites "
      "the model marks), second order; \"midpoint\", one update between the halves of the "
      "central sub-step, second order; \"after_centre\", one update after the central "
      "sub-step (paper 2 eq. 52), first order; \"lie\", one update after the step, first order",
      {{"strang", Splitting::strang},
       {"midpoint", Splitting::midpoint},
       {"after_centre", Splitting::after_centre},
       {"lie", Splitting::lie}});
}

const KeyDecl& KeySet::add(KeyDecl decl) {
  table_.add(std::move(decl));
  return table_.keys().back();
}

Key<double> KeySet::number(std::string path, std::string unit, std::string default_value,
                           std::string meaning, KeyCheck<double> check) {
  return {add({std::move(path), KeyType::number, std::move(unit), std::move(default_value),
               std::move(meaning)}),
          std::move(check)};
}

Key<std::int64_t> KeySet::integer(std::string path, std::string default_value, std::string meaning,
                                  KeyCheck<std::int64_t> check) {
  return {
      add({std::move(path), KeyType::integer, "-", std::move(default_value), std::move(meaning)}),
      std::move(check)};
}

Key<bool> KeySet::boolean(std::string path, std::string default_value, std::string meaning) {
  return {
      add({std::move(path), KeyType::boolean, "-", std::move(default_value), std::move(meaning)}),
      {}};
}

Key<std::string> KeySet::text(std::string path, std::string default_value, std::string meaning,
                              KeyCheck<std::string> check) {
  return {
      add({std::move(path), KeyType::string, "-", std::move(default_value), std::move(meaning)}),
      std::move(check)};
}

} // namespace revsph
