// What `revsph run` counts as a moving particle inside a wall (core/wall_penetration.hpp, through
// ParticleChecks): on a sloped stl wall, whose particles make a staircase under the smooth
// surface, a fluid particle in a notch of the staircase (inside the surface, in no wall
// particle's cell) or just above the surface, within 0.4 dr of a wall particle, is in no wall; one
// inside the surface and in a wall particle's cell is. Each shipped case counts none at step 0.

#include "core/case_file.hpp"
#include "core/model_registry.hpp"
#include "fixedpoint/conversion.hpp"
#include "tools/revsph/particle_checks.hpp"

#include "ramp_stl.hpp"
#include "simulation_fixture.hpp"
#include "temp_directory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace revsph {
namespace {

// The state with fluid particle 0 moved to p.
StateSnapshot with_first_fluid_at(StateSnapshot state, const Vec<3>& p) {
  for (FieldSnapshot& field : state.fields) {
    if (field.info.particle_set == "fluid" && field.info.name == "position") {
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(fixedpoint::try_to_fixed(p[k], field.info.scale, field.bits[k * field.count]));
      }
    }
  }
  return state;
}

TEST(WallPenetration, ASlopedStlWallHoldsWhatIsInItsParticlesCells) {
  testing::TempDirectory directory("revsph-wall-penetration");
  const std::string stl = (directory.path() / "ramp.stl").string();
  std::ofstream(stl) << testing::ramp_stl();
  const std::string text = testing::ramp_case(stl);
  auto simulation = testing::make_simulation_from_text(text);
  const CaseFile case_file = CaseFile::parse(text, "ramp.toml");
  const cli::ParticleChecks checks(case_file, simulation->info());
  const StateSnapshot state = simulation->capture_state();
  EXPECT_EQ(checks.count_in_walls(state).total, 0u);

  // Inside the surface (under z = 0.0457 at x = 0.019) in the cell of the lattice point
  // (0.01, 0.05, 0.05), which lies above the surface (0.043 at x = 0.01): a notch, no wall's.
  EXPECT_EQ(checks.count_in_walls(with_first_fluid_at(state, {0.019, 0.05, 0.045})).total, 0u);
  // Above the surface (0.073 at x = 0.11), 0.4 dr from the wall particle (0.11, 0.05, 0.07).
  EXPECT_EQ(checks.count_in_walls(with_first_fluid_at(state, {0.11, 0.05, 0.078})).total, 0u);
  // Under the surface in that wall particle's cell: in the ramp, particles[2].
  const cli::WallCount in_ramp =
      checks.count_in_walls(with_first_fluid_at(state, {0.11, 0.05, 0.065}));
  EXPECT_EQ(in_ramp.total, 1u);
  EXPECT_EQ(in_ramp.per_region, (std::vector<std::uint64_t>{0, 1}));
  // Deep in the ramp, between its particles: in a cell all the same.
  EXPECT_EQ(checks.count_in_walls(with_first_fluid_at(state, {0.205, 0.045, 0.025})).total, 1u);
  // In the container's floor.
  EXPECT_EQ(checks.count_in_walls(with_first_fluid_at(state, {0.305, 0.05, -0.005})).per_region,
            (std::vector<std::uint64_t>{1, 0}));
}

// Every shipped case's moving particles start outside its walls.
class ShippedCase : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedCase, CountsNoParticleInAWallAtStepZero) {
  auto simulation = testing::make_simulation(GetParam());
  const cli::ParticleChecks checks(load_case(GetParam()), simulation->info());
  const cli::WallCount count = checks.count_in_walls(simulation->capture_state());
  EXPECT_EQ(count.total, 0u);
}

// The built-in cases and the worked examples' case files.
std::vector<std::string> shipped_cases() {
  std::vector<std::string> names;
  for (const BuiltinCase& c : builtin_cases()) {
    names.emplace_back(c.name);
  }
  for (const auto& folder :
       std::filesystem::directory_iterator(std::string(REVSPH_SOURCE_DIR) + "/docs/examples")) {
    for (const auto& file : std::filesystem::directory_iterator(folder.path())) {
      if (file.path().extension() == ".toml") {
        names.push_back(file.path().string());
      }
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Every, ShippedCase, ::testing::ValuesIn(shipped_cases()),
                         [](const ::testing::TestParamInfo<std::string>& test_info) {
                           std::string name = std::filesystem::path(test_info.param).stem();
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

} // namespace
} // namespace revsph
