// The generated read_fields (tools/keygen) reads a key with a `field` straight into the model's
// parameters, before the reader's own lines: a value given in a case must still be there when
// read_parameters returns (a later assignment of the enclosing struct would lose it; the
// two-fluid reader had one, found when the fields were introduced).

#include "case_text.hpp"
#include "core/case_file.hpp"
#include "models/entropic/parameters.hpp"
#include "models/two_fluid/parameters.hpp"
#include "models/wcsph/parameters.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace {

using revsph::CaseFile;

CaseFile case_with(const std::string& name,
                   const std::vector<std::pair<std::string, std::string>>& values) {
  CaseFile case_file = CaseFile::parse(revsph::testing::builtin_case_text(name), name);
  for (const auto& [key, value] : values) {
    case_file.set(key, value);
  }
  return case_file;
}

TEST(CaseFields, TwoFluidNestedFieldsKeepTheCasesValues) {
  const CaseFile case_file =
      case_with("rotating-cylinder-small", {{"mutual_friction.wall_line_density", "initial"},
                                            {"collision.on", "true"},
                                            {"collision.restitution", "0.5"},
                                            {"riemann.limiter", "2.5"}});
  const auto p = revsph::two_fluid::read_parameters<2>(case_file);
  EXPECT_TRUE(p.mutual_friction.wall_at_initial_line_density);
  EXPECT_TRUE(p.contact.collision);
  EXPECT_EQ(p.contact.restitution, 0.5);
  EXPECT_EQ(p.contact.limiter, 2.5);
}

TEST(CaseFields, WcsphAndEntropicRenamedFieldsKeepTheCasesValues) {
  const auto wcsph = revsph::wcsph::read_parameters<2>(
      case_with("dambreak-small", {{"initial_state_correction.tolerance", "0.001"},
                                   {"initial_state_correction.jitter", "0.25"}}));
  EXPECT_EQ(wcsph.isc.tolerance, 0.001);
  EXPECT_EQ(wcsph.isc.jitter, 0.25);
  const auto entropic = revsph::entropic::read_parameters<2>(
      case_with("rayleigh-benard", {{"initial.temperature_perturbation", "0.03"}}));
  EXPECT_EQ(entropic.initial_temperature_perturbation, 0.03);
}

} // namespace
