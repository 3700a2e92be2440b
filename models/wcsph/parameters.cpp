#include "models/wcsph/parameters.hpp"

#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"

#include <cmath>

namespace revsph::wcsph {

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  Parameters<D> p;
  p.rest_density = case_file.positive_number("physics.rest_density");
  p.sound_speed = case_file.positive_number("physics.sound_speed");
  p.gravity = case_file.number_or("physics.gravity", 0.0);
  p.gravity_reference_height = case_file.number_or("physics.gravity_reference_height", 0.0);

  p.dr = case_file.positive_number("discretisation.dr");
  p.support_radius = p.dr * case_file.positive_number("discretisation.support_radius_over_dr");
  const bool has_courant = case_file.has("discretisation.courant_number");
  const bool has_dt = case_file.has("discretisation.dt");
  if (has_courant == has_dt) {
    case_file.fail("discretisation.dt",
                   has_dt ? "give either dt or courant_number, not both"
                          : "missing required key (or give discretisation.courant_number, "
                            "dt = courant_number * h / c)");
  }
  p.dt = has_dt ? case_file.positive_number("discretisation.dt")
                : case_file.positive_number("discretisation.courant_number") * p.support_radius /
                      p.sound_speed;
  p.cell_size_factor = case_file.number_or("discretisation.cell_size_factor", 1.0);
  if (!(p.cell_size_factor >= 1.0 && p.cell_size_factor <= 100.0)) {
    case_file.fail("discretisation.cell_size_factor", "must be between 1 and 100");
  }
  require_positive_finite(case_file, "discretisation.support_radius_over_dr",
                          "the support radius h = dr * support_radius_over_dr", p.support_radius);
  require_positive_finite(case_file, has_dt ? "discretisation.dt" : "discretisation.courant_number",
                          "the time step dt", p.dt);
  require_positive_finite(case_file, "discretisation.cell_size_factor",
                          "the search cell size h * cell_size_factor",
                          p.support_radius * p.cell_size_factor);

  p.wall_radius = p.dr * case_file.number_or("wall.radius_over_dr", 0.95);
  p.wall_energy_per_mass = case_file.number_or("wall.energy_per_mass", 0.0);
  p.wall_epsilon = case_file.number_or("wall.epsilon", 1e-6);
  if (!(p.wall_radius > 0.0)) {
    case_file.fail("wall.radius_over_dr", "must be > 0");
  }
  require_positive_finite(case_file, "wall.radius_over_dr",
                          "the wall search cell size dr * radius_over_dr * cell_size_factor",
                          p.wall_radius * p.cell_size_factor);
  if (p.wall_energy_per_mass < 0.0) {
    case_file.fail("wall.energy_per_mass", "must be >= 0");
  }
  if (p.wall_epsilon < 0.0) {
    case_file.fail("wall.epsilon", "must be >= 0");
  }

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
  p.position_scale =
      scale_or(case_file, "fixed_point.position_exponent", p.domain.max_abs_coordinate(), 52);
  p.velocity_scale = scale_or(case_file, "fixed_point.velocity_exponent", p.sound_speed, 50);
  p.density_scale = scale_or(case_file, "fixed_point.density_exponent", p.rest_density, 48);
  p.acceleration_scale = scale_or(case_file, "fixed_point.acceleration_exponent",
                                  p.sound_speed * p.sound_speed / p.support_radius, 48);
  return p;
}

template Parameters<1> read_parameters<1>(const CaseFile&);
template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::wcsph
