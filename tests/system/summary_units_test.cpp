// summary.json gives every reported quantity its unit (issue 33's fault list: unitless names):
// `units.energy` for the energy terms and `units.NAME` for each diagnostic of diagnostics.csv,
// per metre of depth in 2D. One small case of each model that reports diagnostics.

#include "cli_sandbox.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <ostream>
#include <string>

namespace {

using revsph::testing::CommandResult;
using revsph::testing::Sandbox;

struct UnitsCase {
  std::string case_name;
  std::string energy_unit;
  std::map<std::string, std::string> some_units; // diagnostic -> its unit
};

void PrintTo(const UnitsCase& units_case, std::ostream* out) {
  *out << units_case.case_name;
}

class SummaryUnits : public ::testing::TestWithParam<UnitsCase> {};

TEST_P(SummaryUnits, EveryDiagnosticAndTheEnergyHaveTheirUnit) {
  const UnitsCase& expected = GetParam();
  Sandbox sandbox;
  const CommandResult result =
      sandbox.revsph({"run", expected.case_name, "--steps", "4", "--out", sandbox.out().string()});
  ASSERT_EQ(result.exit_status, 0) << result;
  std::ifstream file(sandbox.out() / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(file);
  ASSERT_TRUE(summary.contains("units")) << summary.dump(2);
  const nlohmann::json& units = summary["units"];
  EXPECT_EQ(units["energy"], expected.energy_unit);
  ASSERT_TRUE(summary.contains("diagnostics"));
  int diagnostics = 0;
  for (const auto& [key, value] : summary["diagnostics"].items()) {
    if (key.rfind("max_", 0) != 0) {
      continue;
    }
    ++diagnostics;
    const std::string name = key.substr(4);
    ASSERT_TRUE(units.contains(name)) << name;
    EXPECT_FALSE(units[name].get<std::string>().empty()) << name;
  }
  EXPECT_GT(diagnostics, 0);
  for (const auto& [name, unit] : expected.some_units) {
    EXPECT_EQ(units[name], unit) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    ModelsWithDiagnostics, SummaryUnits,
    ::testing::Values(UnitsCase{"cavity-small",
                                "J/m",
                                {{"momentum_x", "kg/s"},
                                 {"entropy", "J/(K m)"},
                                 {"thermal_wall_entropy", "J/(K m)"},
                                 {"heat_into_cold_walls", "J/m"}}},
                      UnitsCase{"twisting-column-small", "J", {{"angular_momentum_z", "kg m^2/s"}}},
                      UnitsCase{"second-sound-small",
                                "J/m",
                                {{"probe_entropy", "J/(kg K)"},
                                 {"second_sound_error", "1"},
                                 {"total_entropy", "J/(K m)"},
                                 {"copy_velocity_difference", "m/s"}}},
                      UnitsCase{"gresho", "J/m", {{"velocity_error", "1"}}}),
    [](const ::testing::TestParamInfo<UnitsCase>& param_info) {
      std::string name = param_info.param.case_name;
      for (char& c : name) {
        c = c == '-' ? '_' : c;
      }
      return name;
    });

} // namespace
