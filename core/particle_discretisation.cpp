#include "core/particle_discretisation.hpp"

#include "core/case_values.hpp"

namespace revsph {

ParticleDiscretisation read_particle_discretisation(const CaseFile& case_file, double sound_speed) {
  ParticleDiscretisation d;
  d.dr = case_file.positive_number("discretisation.dr");
  d.support_radius = d.dr * case_file.positive_number("discretisation.support_radius_over_dr");
  const bool has_courant = case_file.has("discretisation.courant_number");
  const bool has_dt = case_file.has("discretisation.dt");
  if (has_courant == has_dt) {
    case_file.fail("discretisation.dt",
                   has_dt ? "give either dt or courant_number, not both"
                          : "missing required key (or give discretisation.courant_number, "
                            "dt = courant_number * h / c)");
  }
  d.dt = has_dt ? case_file.positive_number("discretisation.dt")
                : case_file.positive_number("discretisation.courant_number") * d.support_radius /
                      sound_speed;
  d.cell_size_factor = case_file.number_or("discretisation.cell_size_factor", 1.0);
  if (!(d.cell_size_factor >= 1.0 && d.cell_size_factor <= 100.0)) {
    case_file.fail("discretisation.cell_size_factor", "must be between 1 and 100");
  }
  require_positive_finite(case_file, "discretisation.support_radius_over_dr",
                          "the support radius h = dr * support_radius_over_dr", d.support_radius);
  require_positive_finite(case_file, has_dt ? "discretisation.dt" : "discretisation.courant_number",
                          "the time step dt", d.dt);
  require_positive_finite(case_file, "discretisation.cell_size_factor",
                          "the search cell size h * cell_size_factor",
                          d.support_radius * d.cell_size_factor);
  return d;
}

WallSettings read_wall_settings(const CaseFile& case_file, const ParticleDiscretisation& d) {
  WallSettings wall;
  wall.radius = d.dr * case_file.number_or("wall.radius_over_dr", 0.95);
  wall.energy_per_mass = case_file.number_or("wall.energy_per_mass", 0.0);
  wall.epsilon = case_file.number_or("wall.epsilon", 1e-6);
  if (!(wall.radius > 0.0)) {
    case_file.fail("wall.radius_over_dr", "must be > 0");
  }
  require_positive_finite(case_file, "wall.radius_over_dr",
                          "the wall search cell size dr * radius_over_dr * cell_size_factor",
                          wall.radius * d.cell_size_factor);
  if (!(wall.energy_per_mass >= 0.0)) {
    case_file.fail("wall.energy_per_mass", "must be >= 0");
  }
  if (!(wall.epsilon >= 0.0)) {
    case_file.fail("wall.epsilon", "must be >= 0");
  }
  return wall;
}

} // namespace revsph
