// Bad input to the two-fluid model (issue 18): each defect of a built-in case ends the run with
// the one-line error "file: key: reason", exit status 2, and no output written.

#include "case_defect.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using Defect = revsph::testing::CaseDefect;

std::vector<Defect> defects() {
  constexpr const char* cylinder = "rotating-cylinder-small";
  constexpr const char* mixture = "two-fluid-mixture-small";
  return {
      {"superfluid_fraction_above_one", mixture, "", "", "particles[0].superfluid_fraction=1.2",
       "particles[0].superfluid_fraction", "must be in (0, 1)"},
      {"superfluid_fraction_zero", cylinder, "", "", "particles[0].superfluid_fraction=0",
       "particles[0].superfluid_fraction", "must be in (0, 1)"},
      {"superfluid_fraction_on_a_wall", cylinder, "", "", "particles[1].superfluid_fraction=0.5",
       "particles[1].superfluid_fraction", "only for kind = \"mixed\""},
      {"seed_on_a_wall", cylinder, "", "", "particles[1].seed=3", "particles[1].seed",
       "only for kind = \"mixed\""},
      {"negative_friction_coefficient", cylinder, "", "", "mutual_friction.alpha=-0.1",
       "mutual_friction.alpha", "must be a finite number >= 0"},
      {"friction_without_circulation", cylinder, "circulation_quantum = 9.9693e-8", "", "",
       "mutual_friction.circulation_quantum", "missing required key"},
      {"friction_too_strong_for_the_step", cylinder, "", "",
       "mutual_friction.initial_line_density=1e14", "mutual_friction.initial_line_density",
       "relaxes more than 10 % per step"},
      {"negative_temperature", cylinder, "", "", "physics.temperature=-1.6", "physics.temperature",
       "must be > 0"},
      {"negative_viscosity", cylinder, "", "", "physics.normal_viscosity=-1e-6",
       "physics.normal_viscosity", "must be a finite number >= 0"},
      {"unknown_particle_kind", cylinder, "kind = \"mixed\"", "kind = \"vortex\"", "",
       "particles[0].kind", "unknown particle kind \"vortex\""},
      {"unknown_pressure_form", mixture, "", "", "pressure.form=riemann", "pressure.form",
       "expected \"hu_adams\", \"standard\" or \"variational\", got \"riemann\""},
      {"spin_without_max_speed", mixture, "max_speed = 0.05", "", "", "spin.max_speed",
       "missing required key"},
      {"unknown_phases", mixture, "", "", "physics.phases=emulsion", "physics.phases",
       "expected \"separate\" or \"interpenetrating\", got \"emulsion\""},
      {"interpenetrating_with_the_thermomechanical_force", mixture, "", "",
       "physics.phases=interpenetrating", "physics.phases", "written for separate phases"},
      {"interpenetrating_with_a_pure_block", "rayleigh-taylor-small", "", "",
       "physics.phases=interpenetrating", "particles[0].kind", "given as mixed blocks"},
      {"interpenetrating_at_another_fraction", cylinder, "superfluid_fraction = 0.834",
       "superfluid_fraction = 0.5", "physics.phases=interpenetrating",
       "particles[0].superfluid_fraction", "it must be rho_s / (rho_s + rho_n)"},
      {"unknown_wall_line_density", cylinder, "", "", "mutual_friction.wall_line_density=frozen",
       "mutual_friction.wall_line_density", "expected \"decaying\" or \"initial\", got \"frozen\""},
      {"unknown_separate_phase_viscosity", mixture, "", "",
       "physics.separate_phase_viscosity=emulsion", "physics.separate_phase_viscosity",
       "expected \"diluted\" or \"undiluted\", got \"emulsion\""},
      {"undiluted_with_interpenetrating_phases", cylinder, "[physics]",
       "[physics]\nphases = \"interpenetrating\"", "physics.separate_phase_viscosity=undiluted",
       "physics.separate_phase_viscosity", "undiluted already"},
      {"undiluted_without_a_mixture", "rayleigh-taylor-small", "", "",
       "physics.separate_phase_viscosity=undiluted", "physics.separate_phase_viscosity",
       "the case has no mixed block"},
      {"unknown_wall_motion", cylinder, "", "", "particles[1].wall_motion=spinning",
       "particles[1].wall_motion", "expected \"frozen\" or \"rigid\", got \"spinning\""},
      {"wall_motion_on_a_fluid_block", cylinder, "", "", "particles[0].wall_motion=rigid",
       "particles[0].wall_motion", "only for kind = \"wall\""},
      {"rigid_wall_without_rotation", mixture, "", "", "particles[1].wall_motion=rigid",
       "particles[1].wall_motion", "needs a non-zero rotation_rate"},
  };
}

REVSPH_CASE_DEFECT_TESTS(TwoFluidBadInput, defects());

} // namespace
