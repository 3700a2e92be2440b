// fill_set (core/state_fill.hpp): a setup fills a set's fields by the names its state table
// declares, from per-particle values or one number; a value that does not fit its scale is a
// one-line case error naming the key, and a name or length the set does not have is a bug.

#include "core/arithmetic.hpp"
#include "core/case_file.hpp"
#include "core/common_fields.hpp"
#include "core/state_fill.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace revsph {
namespace {

struct Probe {
  static constexpr SetInfo set{.name = "probe", .motion = Motion::moving};
  StateField<std::int64_t> position{position_field<2>()};
  StateField<std::int64_t> mass{mass_field<2>()};
  StateField<std::int64_t> density_constant{density_constant_field()};
  auto fields() { return std::tie(position, mass, density_constant); }
};

Probe scaled_probe() {
  Probe probe;
  probe.position.set_scale(fixedpoint::Scale(-40));
  probe.mass.set_scale(fixedpoint::Scale(-40));
  probe.density_constant.set_scale(fixedpoint::Scale(-40));
  return probe;
}

TEST(FillSet, FillsTheNamedFieldsFromValuesAndOneNumber) {
  const CaseFile case_file = CaseFile::parse("model = \"x\"\n", "probe.toml");
  Probe probe = scaled_probe();
  const std::vector<Vec<2>> positions = {{0.5, -1.0}, {2.0, 3.25}};
  const std::vector<double> masses = {1.5, 2.5};
  fill_set<FixedArithmetic, 2>(case_file, probe, 2,
                               {{"position", "particles", positions},
                                {"mass", "physics.rest_density", masses},
                                {"density_constant", "particles", 0.0}});
  EXPECT_EQ(fixedpoint::to_real(probe.position.at(1, 1), probe.position.info().scale), 3.25);
  EXPECT_EQ(fixedpoint::to_real(probe.mass.at(0, 0), probe.mass.info().scale), 1.5);
  EXPECT_EQ(probe.density_constant.count(), 2u);
  EXPECT_EQ(probe.density_constant.at(0, 1), 0);
}

TEST(FillSet, AValueOutsideItsScaleIsACaseErrorOnTheKey) {
  const CaseFile case_file = CaseFile::parse("model = \"x\"\n", "probe.toml");
  Probe probe = scaled_probe();
  const std::vector<double> masses = {1.0, 1e30};
  try {
    fill_set<FixedArithmetic, 2>(case_file, probe, 2, {{"mass", "physics.rest_density", masses}});
    FAIL() << "no error";
  } catch (const CaseError& error) {
    EXPECT_NE(std::string(error.what()).find("physics.rest_density"), std::string::npos)
        << error.what();
  }
}

TEST(FillSet, AnUnknownNameOrAWrongLengthIsALogicError) {
  const CaseFile case_file = CaseFile::parse("model = \"x\"\n", "probe.toml");
  Probe probe = scaled_probe();
  const std::vector<double> one = {1.0};
  const std::vector<Vec<2>> point = {{1.0, 2.0}};
  EXPECT_THROW((fill_set<FixedArithmetic, 2>(case_file, probe, 1, {{"velocity", "k", 0.0}})),
               std::logic_error);
  EXPECT_THROW((fill_set<FixedArithmetic, 2>(case_file, probe, 2, {{"mass", "k", one}})),
               std::logic_error);
  EXPECT_THROW((fill_set<FixedArithmetic, 2>(case_file, probe, 1, {{"mass", "k", point}})),
               std::logic_error);
}

} // namespace
} // namespace revsph
