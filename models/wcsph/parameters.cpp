#include "models/wcsph/parameters.hpp"

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>

namespace revsph::wcsph {

namespace {

// Every key of a WCSPH case file beyond common_case_keys(), including those the core's readers
// read (discretisation, walls, domain, particle blocks), in the reference's order.
struct Keys : KeySet {
  Keys() : KeySet("wcsph") {}
  const std::string dimension =
      declare({"dimension", KeyType::integer, "-", "required", "1, 2 or 3"});
  const Key<double> rest_density = number("physics.rest_density", "kg/m^3", "required",
                                          "rest density rho0; > 0", positive_or_why);
  const Key<double> sound_speed =
      number("physics.sound_speed", "m/s", "required",
             "numerical speed of sound c of the equation of state; > 0", positive_or_why);
  const Key<double> gravity = KeySet::gravity();
  const Key<double> gravity_reference_height = KeySet::gravity_reference_height();
  const Key<double> anti_clump_pressure =
      number("physics.anti_clump_pressure", "Pa", "0",
             "p0 of the anti-clump force of paper 1 App. A; >= 0 (0: off)",
             must<double>([](double p0) { return p0 >= 0.0; }, "must be >= 0"));
  const int discretisation =
      (declare(particle_discretisation_case_keys("kernel support radius h in units of dr",
                                                 "time step as a fraction of h / c: dt = "
                                                 "courant_number * h / c")),
       declare(wall_case_keys("eq. 7")), 0);
  const Key<std::int64_t> shepard_every = integer(
      "filter.shepard_every", "0", "steps between Shepard filters (paper 1 App. A); 0: no filter",
      must<std::int64_t>([](std::int64_t n) { return n >= 0; }, "must be >= 0 (0: no filter)"));
  const Choice<bool> shepard_active =
      choice<bool>("filter.mode", "\"passive\"",
                   "\"active\" replaces the velocities by the filtered ones (dissipative, not "
                   "reversible); \"passive\" only reports the filtered field",
                   {{"passive", false}, {"active", true}});
  const Choice<InitialField> initial_field = choice<InitialField>(
      "initial.field", "\"rest\"",
      "initial velocity and density: at rest with every density rho0, or the Gresho vortex "
      "(2D; its velocity, and the density whose Tait pressure is the vortex's pressure)",
      {{"rest", InitialField::rest}, {"gresho", InitialField::gresho_vortex}});
  const std::string centre = declare(
      {"initial.centre", KeyType::numbers, "m", "the origin", "centre of the Gresho vortex"});
  const Key<bool> isc_enabled =
      boolean("initial_state_correction.enabled", "false",
              "move the fluid particles at setup so that every density equals rho0 (paper 1 §3.2)");
  const Key<bool> isc_with_dummies = boolean("initial_state_correction.include_dummies", "true",
                                             "dummy particles count in the corrected densities");
  const Key<std::int64_t> isc_max_iterations = integer(
      "initial_state_correction.max_iterations", "20", "Newton iterations at most, 1 to 999",
      must<std::int64_t>([](std::int64_t n) { return n >= 1 && n <= 999; },
                         "must be between 1 and 999"));
  const Key<double> isc_tolerance =
      number("initial_state_correction.tolerance", "1", "1e-10",
             "relative density error at which the correction stops, between 0 and 1",
             must<double>([](double t) { return t > 0.0 && t < 1.0; }, "must be > 0 and < 1"));
  const Key<double> isc_jitter =
      number("initial_state_correction.jitter", "1", "0.1",
             "random displacement before correcting, as a fraction of dr, 0 to 0.5",
             must<double>([](double j) { return j >= 0.0 && j <= 0.5; },
                          "must be between 0 and 0.5 (a fraction of dr)"));
  const Key<double> isc_max_step =
      number("initial_state_correction.max_step", "1", "0",
             "largest Newton step as a fraction of dr, 0 to 10 (0: undamped)",
             must<double>([](double m) { return m >= 0.0 && m <= 10.0; },
                          "must be between 0 and 10 (a fraction of dr; 0: undamped Newton)"));
  const Key<std::int64_t> isc_seed =
      integer("initial_state_correction.seed", "1", "seed of the jitter; >= 0",
              must<std::int64_t>([](std::int64_t seed) { return seed >= 0; }, "must be >= 0"));
  const int regions = (declare(domain_case_keys()),
                       declare(particle_block_case_keys({"fluid", "wall", "dummy"})), 0);
  // Default scales: positions keep 52 fraction bits below the domain size, so the double view of
  // a position is exact; velocities resolve c * 2^-50 and reach 2^13 c; density sums resolve
  // rho0 * 2^-48; acceleration sums resolve (c^2 / h) * 2^-48.
  const PositionScaleKey position_exponent = position_scale();
  const ScaleKey velocity_exponent =
      scale("velocity", "c", 50, "velocities are stored as integers times 2^exponent");
  const ScaleKey density_exponent =
      scale("density", "rho0", 48, "scale of the density sums and the constants C_a");
  const ScaleKey acceleration_exponent =
      scale("acceleration", "c^2 / h", 48, "scale of the acceleration sums");
};

const Keys& keys() {
  static const Keys declared;
  return declared;
}

} // namespace

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  const Keys& k = keys();
  Parameters<D> p;
  p.rest_density = k.rest_density.read(case_file);
  p.sound_speed = k.sound_speed.read(case_file);
  p.gravity = k.gravity.read(case_file);
  p.gravity_reference_height = k.gravity_reference_height.read(case_file);

  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.sound_speed);
  p.dr = discretisation.dr;
  p.support_radius = discretisation.support_radius;
  p.dt = discretisation.dt;
  p.cell_size_factor = discretisation.cell_size_factor;
  p.wall = read_wall_settings(case_file, discretisation);

  p.anti_clump_pressure = k.anti_clump_pressure.read(case_file);
  p.shepard_every = k.shepard_every.read(case_file);
  p.shepard_active = k.shepard_active.read(case_file);
  if (p.shepard_active && p.shepard_every == 0) {
    case_file.fail(k.shepard_every.path(), "an active filter needs shepard_every >= 1");
  }
  p.initial_field = k.initial_field.read(case_file);
  if (p.initial_field == InitialField::gresho_vortex && D != 2) {
    case_file.fail(k.initial_field.path(), "the Gresho vortex is two-dimensional");
  }
  if (case_file.has(k.centre)) {
    const std::vector<double> centre = case_file.numbers(k.centre, D);
    std::copy(centre.begin(), centre.end(), p.centre.begin());
  }

  p.isc_enabled = k.isc_enabled.read(case_file);
  p.isc_with_dummies = k.isc_with_dummies.read(case_file);
  p.isc.max_iterations = static_cast<int>(k.isc_max_iterations.read(case_file));
  p.isc.tolerance = k.isc_tolerance.read(case_file);
  p.isc.jitter = k.isc_jitter.read(case_file);
  p.isc.max_step = k.isc_max_step.read(case_file);
  p.isc.spacing = p.dr;
  p.isc.seed = static_cast<std::uint64_t>(k.isc_seed.read(case_file));

  p.domain = read_domain<D>(case_file);
  p.position_scale = k.position_exponent.read(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.velocity_scale = k.velocity_exponent.read(case_file, p.sound_speed);
  p.density_scale = k.density_exponent.read(case_file, p.rest_density);
  p.acceleration_scale =
      k.acceleration_exponent.read(case_file, p.sound_speed * p.sound_speed / p.support_radius);
  return p;
}

const KeyTable& case_keys() {
  return keys().table();
}

template Parameters<1> read_parameters<1>(const CaseFile&);
template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::wcsph
