// Bad input to the superfluid model (issue 17): each defect of a built-in case ends the run with
// the one-line error "file: key: reason", exit status 2, and no output written. Defects are
// given with --set, or as an edited line where a key must be removed.

#include "case_defect.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using Defect = revsph::testing::CaseDefect;

std::vector<Defect> defects() {
  constexpr const char* capacity = "heat_capacity = 3902.0";
  return {
      {"normal_fraction_above_one", "droplet-small", "", "", "physics.normal_fraction=1.5",
       "physics.normal_fraction", "chi_n0 must be in (0, 1]"},
      {"negative_heat_capacity", "droplet-small", "", "", "physics.heat_capacity=-1",
       "physics.heat_capacity", "must be > 0"},
      {"negative_second_sound_speed", "droplet-small", capacity, "second_sound_speed = -18.83", "",
       "physics.second_sound_speed", "must be > 0"},
      {"both_heat_capacity_and_second_sound_speed", "droplet-small", "", "",
       "physics.second_sound_speed=18.83", "physics.second_sound_speed", "give exactly one"},
      {"neither_heat_capacity_nor_second_sound_speed", "droplet-small", capacity, "", "",
       "physics.heat_capacity", "give exactly one"},
      // chi_n = chi_n0 + chi' (s - s0) leaves (0, 1] where s / s0 - 1 reaches -1.5.
      {"normal_fraction_negative_at_the_start", "droplet-small", "", "", "initial.random_entropy=3",
       "initial.random_entropy", "chi_n must stay in (0, 1]"},
      {"normal_fraction_above_one_in_the_wave", "second-sound-small", "", "",
       "initial.entropy_wave_amplitude=4", "initial.entropy_wave_amplitude",
       "chi_n must stay in (0, 1]"},
      {"unknown_wave_shape", "second-sound-small", "", "", "initial.entropy_wave_shape=square",
       "initial.entropy_wave_shape", "expected \"sine\" or \"cosine\", got \"square\""},
      {"unknown_dummy_slip", "droplet-small", "", "", "physics.dummy_slip=sticky",
       "physics.dummy_slip", "expected \"free\" or \"no_slip\", got \"sticky\""},
      {"unknown_cooler", "cooler-small", "", "", "physics.cooler=cold", "physics.cooler",
       "expected \"conducting\" or \"absorbing\", got \"cold\""},
      {"negative_random_velocity", "droplet-small", "", "", "initial.random_velocity=-0.1",
       "initial.random_velocity", "must be a finite number >= 0"},
      {"superleak_centre_outside_the_domain", "droplet-small", "[run]",
       "[superleak]\nrate = 1e6\ncentre = [1.0, 1.0]\nhalf_width = 0.004\n"
       "half_thickness = 0.002\n\n[run]",
       "", "superleak.centre", "lies outside the domain"},
      {"superleak_reaching_outside_the_domain", "droplet-small", "[run]",
       "[superleak]\nrate = 1e6\ncentre = [0.008, 0.008]\nhalf_width = 0.1\n"
       "half_thickness = 0.002\n\n[run]",
       "", "superleak.half_width", "reaches outside the domain"},
      {"superleak_without_centre", "droplet-small", "", "", "superleak.rate=1e6",
       "superleak.centre", "missing required key"},
      {"heater_without_support", "droplet-small", "", "", "heater.power=10", "heater.centre",
       "missing required key"},
      {"wave_without_length", "second-sound-small", "entropy_wave_length = 0.01", "", "",
       "initial.entropy_wave_length", "missing required key"},
  };
}

REVSPH_CASE_DEFECT_TESTS(SuperfluidBadInput, defects());

} // namespace
