// Bad input to the entropic model (issue 16): each defect of the built-in expansion-small case,
// given with --set, ends the run with the one-line error "file: key: reason", exit status 2, and
// no output written.

#include "case_text.hpp"
#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using revsph::testing::error_prefix;
using revsph::testing::expect_clean_rejection;
using revsph::testing::Sandbox;

struct Defect {
  const char* name;
  const char* set;    // the --set argument
  const char* key;    // the key the error names
  const char* reason; // a part of the reason
};

std::vector<Defect> defects() {
  return {
      {"unknown_volume", "physics.particle_volume=massive", "physics.particle_volume",
       "expected \"mass\", \"entropic\", \"direct\", \"implicit\" or \"mixed\", got \"massive\""},
      {"entropic_volume_with_negative_entropy", "physics.particle_volume=entropic",
       "physics.particle_volume", "needs positive particle entropies"},
      {"gamma_not_above_one", "physics.gamma=0.9", "physics.gamma", "gamma must be > 1 (got 0.9)"},
      {"gamma_one", "physics.gamma=1", "physics.gamma", "gamma must be > 1 (got 1)"},
      {"zero_heat_capacity", "physics.heat_capacity=0", "physics.heat_capacity",
       "heat_capacity must be > 0 (got 0)"},
      {"stiffened_gas_without_its_constants", "physics.equation_of_state=stiffened_gas",
       "physics.rest_density", "missing required key"},
      {"unknown_equation_of_state", "physics.equation_of_state=van_der_waals",
       "physics.equation_of_state", "got \"van_der_waals\""},
      {"negative_pressure", "initial.pressure=-1", "initial.pressure", "must be > 0 (got -1)"},
      {"hyperbolic_heat_on_moving_particles", "hyperbolic_heat.energy_coefficient=0.05",
       "hyperbolic_heat.energy_coefficient", "set physics.particles_move = false"},
      {"negative_flux_energy", "hyperbolic_heat.energy_coefficient=-1",
       "hyperbolic_heat.energy_coefficient", "must be a finite number >= 0 (got -1"},
      {"zero_relaxation_time", "hyperbolic_heat.relaxation_time=0",
       "hyperbolic_heat.relaxation_time", "must be > 0"},
      {"temperature_on_a_gas_block", "particles[0].temperature=1.0", "particles[0].temperature",
       "only for kind = \"thermal\""},
      {"thermal_block_without_temperature", "particles[0].kind=thermal", "particles[0].temperature",
       "missing required key"},
      {"unknown_wall_slip", "physics.wall_slip=sticky", "physics.wall_slip",
       "expected \"free\" or \"no_slip\", got \"sticky\""},
      {"gradient_below_absolute_zero", "initial.temperature_gradient=[1000.0, 0.0]",
       "initial.temperature_gradient", "gives a temperature <= 0 K"},
      {"hydrostatic_not_a_boolean", "initial.hydrostatic=1", "initial.hydrostatic", ""},
      {"perturbation_below_absolute_zero", "initial.temperature_perturbation=-1000",
       "initial.temperature_perturbation", "gives a temperature <= 0 K"},
      {"unknown_buoyancy", "physics.buoyancy=boussinesque", "physics.buoyancy",
       "expected \"density\" or \"boussinesq\", got \"boussinesque\""},
      {"unknown_splitting", "step.splitting=leapfrog", "step.splitting",
       "expected \"strang\", \"midpoint\", \"after_centre\" or \"lie\", got \"leapfrog\""},
  };
}

class EntropicBadInput : public ::testing::TestWithParam<Defect> {};

TEST_P(EntropicBadInput, RunExitsWithOneLineAndWritesNothing) {
  const Defect& defect = GetParam();
  Sandbox sandbox;
  const std::string text = revsph::testing::builtin_case_text("expansion-small");
  const auto case_path = sandbox.write_case(text);
  const auto result = sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(),
                                      "--steps", "1", "--set", defect.set});
  expect_clean_rejection(
      sandbox, result, {"case.toml"},
      {defect.reason, error_prefix + case_path.string() + ": " + defect.key + ": "});
}

INSTANTIATE_TEST_SUITE_P(Defects, EntropicBadInput, ::testing::ValuesIn(defects()),
                         [](const ::testing::TestParamInfo<Defect>& param_info) {
                           return std::string(param_info.param.name);
                         });

} // namespace
