#include "models/wcsph/parameters.hpp"

#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>

namespace revsph::wcsph {

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  Parameters<D> p;
  p.rest_density = case_file.positive_number("physics.rest_density");
  p.sound_speed = case_file.positive_number("physics.sound_speed");
  p.gravity = case_file.number_or("physics.gravity", 0.0);
  p.gravity_reference_height = case_file.number_or("physics.gravity_reference_height", 0.0);

  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.sound_speed);
  p.dr = discretisation.dr;
  p.support_radius = discretisation.support_radius;
  p.dt = discretisation.dt;
  p.cell_size_factor = discretisation.cell_size_factor;
  p.wall = read_wall_settings(case_file, discretisation);

  p.anti_clump_pressure = case_file.number_or("physics.anti_clump_pressure", 0.0);
  if (p.anti_clump_pressure < 0.0) {
    case_file.fail("physics.anti_clump_pressure", "must be >= 0");
  }
  p.shepard_every = case_file.integer_or("filter.shepard_every", 0);
  if (p.shepard_every < 0) {
    case_file.fail("filter.shepard_every", "must be >= 0 (0: no filter)");
  }
  const std::string filter_mode = case_file.string_or("filter.mode", "passive");
  if (filter_mode != "passive" && filter_mode != "active") {
    case_file.fail("filter.mode",
                   "expected \"passive\" or \"active\", got \"" + filter_mode + "\"");
  }
  p.shepard_active = filter_mode == "active";
  if (p.shepard_active && p.shepard_every == 0) {
    case_file.fail("filter.shepard_every", "an active filter needs shepard_every >= 1");
  }
  const std::string field = case_file.string_or("initial.field", "rest");
  if (field == "gresho") {
    p.initial_field = InitialField::gresho_vortex;
    if (D != 2) {
      case_file.fail("initial.field", "the Gresho vortex is two-dimensional");
    }
  } else if (field != "rest") {
    case_file.fail("initial.field", "expected \"rest\" or \"gresho\", got \"" + field + "\"");
  }
  if (case_file.has("initial.centre")) {
    const std::vector<double> centre = case_file.numbers("initial.centre", D);
    std::copy(centre.begin(), centre.end(), p.centre.begin());
  }

  p.isc_enabled = case_file.boolean_or("initial_state_correction.enabled", false);
  p.isc_with_dummies = case_file.boolean_or("initial_state_correction.include_dummies", true);
  const std::int64_t max_iterations =
      case_file.integer_or("initial_state_correction.max_iterations", 20);
  if (max_iterations < 1 || max_iterations > 999) {
    case_file.fail("initial_state_correction.max_iterations", "must be between 1 and 999");
  }
  p.isc.max_iterations = static_cast<int>(max_iterations);
  p.isc.tolerance = case_file.number_or("initial_state_correction.tolerance", 1e-10);
  if (!(p.isc.tolerance > 0.0 && p.isc.tolerance < 1.0)) {
    case_file.fail("initial_state_correction.tolerance", "must be > 0 and < 1");
  }
  p.isc.jitter = case_file.number_or("initial_state_correction.jitter", 0.1);
  if (!(p.isc.jitter >= 0.0 && p.isc.jitter <= 0.5)) {
    case_file.fail("initial_state_correction.jitter",
                   "must be between 0 and 0.5 (a fraction of dr)");
  }
  p.isc.max_step = case_file.number_or("initial_state_correction.max_step", 0.0);
  if (!(p.isc.max_step >= 0.0 && p.isc.max_step <= 10.0)) {
    case_file.fail("initial_state_correction.max_step",
                   "must be between 0 and 10 (a fraction of dr; 0: undamped Newton)");
  }
  p.isc.spacing = p.dr;
  const std::int64_t seed = case_file.integer_or("initial_state_correction.seed", 1);
  if (seed < 0) {
    case_file.fail("initial_state_correction.seed", "must be >= 0");
  }
  p.isc.seed = static_cast<std::uint64_t>(seed);

  p.domain = read_domain<D>(case_file);

  // Default scales: positions keep 52 fraction bits below the domain size, so the double view of
  // a position is exact; velocities resolve c * 2^-50 and reach 2^13 c; density sums resolve
  // rho0 * 2^-48; acceleration sums resolve (c^2 / h) * 2^-48.
  p.position_scale = position_scale_or(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.velocity_scale = scale_or(case_file, "fixed_point.velocity_exponent", p.sound_speed, 50);
  p.density_scale = scale_or(case_file, "fixed_point.density_exponent", p.rest_density, 48);
  p.acceleration_scale = scale_or(case_file, "fixed_point.acceleration_exponent",
                                  p.sound_speed * p.sound_speed / p.support_radius, 48);
  return p;
}

const KeyTable& case_keys() {
  static const KeyTable table = [] {
    using T = KeyType;
    KeyTable t("wcsph");
    t.add({"dimension", T::integer, "-", "required", "1, 2 or 3"});
    t.add({"physics.rest_density", T::number, "kg/m^3", "required", "rest density rho0; > 0"});
    t.add({"physics.sound_speed", T::number, "m/s", "required",
           "numerical speed of sound c of the equation of state; > 0"});
    t.add({"physics.gravity", T::number, "m/s^2", "0",
           "gravitational acceleration g, along minus the last axis"});
    t.add({"physics.gravity_reference_height", T::number, "m", "0",
           "height of zero gravitational potential (shifts the reported energy only)"});
    t.add({"physics.anti_clump_pressure", T::number, "Pa", "0",
           "p0 of the anti-clump force of paper 1 App. A; >= 0 (0: off)"});
    t.add(particle_discretisation_case_keys("kernel support radius h in units of dr",
                                            "time step as a fraction of h / c: dt = "
                                            "courant_number * h / c"));
    t.add(wall_case_keys("eq. 7"));
    t.add({"filter.shepard_every", T::integer, "-", "0",
           "steps between Shepard filters (paper 1 App. A); 0: no filter"});
    t.add({"filter.mode",
           T::string,
           "-",
           "\"passive\"",
           "\"active\" replaces the velocities by the filtered ones (dissipative, not "
           "reversible); \"passive\" only reports the filtered field",
           {"passive", "active"}});
    t.add({"initial.field",
           T::string,
           "-",
           "\"rest\"",
           "initial velocity and density: at rest with every density rho0, or the Gresho vortex "
           "(2D; its velocity, and the density whose Tait pressure is the vortex's pressure)",
           {"rest", "gresho"}});
    t.add({"initial.centre", T::numbers, "m", "the origin", "centre of the Gresho vortex"});
    t.add({"initial_state_correction.enabled", T::boolean, "-", "false",
           "move the fluid particles at setup so that every density equals rho0 (paper 1 §3.2)"});
    t.add({"initial_state_correction.include_dummies", T::boolean, "-", "true",
           "dummy particles count in the corrected densities"});
    t.add({"initial_state_correction.max_iterations", T::integer, "-", "20",
           "Newton iterations at most, 1 to 999"});
    t.add({"initial_state_correction.tolerance", T::number, "1", "1e-10",
           "relative density error at which the correction stops, between 0 and 1"});
    t.add({"initial_state_correction.jitter", T::number, "1", "0.1",
           "random displacement before correcting, as a fraction of dr, 0 to 0.5"});
    t.add({"initial_state_correction.max_step", T::number, "1", "0",
           "largest Newton step as a fraction of dr, 0 to 10 (0: undamped)"});
    t.add({"initial_state_correction.seed", T::integer, "-", "1", "seed of the jitter; >= 0"});
    t.add(domain_case_keys());
    t.add(particle_block_case_keys({"fluid", "wall", "dummy"}));
    t.add({"fixed_point.position_exponent", T::integer, "-",
           "covers the domain with 52 fraction bits",
           "positions are stored as integers times 2^exponent"});
    t.add({"fixed_point.velocity_exponent", T::integer, "-", "covers c with 50 fraction bits",
           "velocities are stored as integers times 2^exponent"});
    t.add({"fixed_point.density_exponent", T::integer, "-", "covers rho0 with 48 fraction bits",
           "scale of the density sums and the constants C_a"});
    t.add({"fixed_point.acceleration_exponent", T::integer, "-",
           "covers c^2 / h with 48 fraction bits", "scale of the acceleration sums"});
    return t;
  }();
  return table;
}

template Parameters<1> read_parameters<1>(const CaseFile&);
template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::wcsph
