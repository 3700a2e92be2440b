#pragma once
// The spacing, kernel reach, time step and search cells of a particle case, and paper 1's
// conservative wall (eq. 7): read and checked the same way by every model whose kernel is given
// by its support radius (wcsph, entropic), with their case keys.

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/wall_potential.hpp"

#include <string>
#include <vector>

namespace revsph {

struct ParticleDiscretisation {
  double dr = 0.0;               // particle spacing (m)
  double support_radius = 0.0;   // kernel support radius h (m)
  double dt = 0.0;               // time step (s)
  double cell_size_factor = 1.0; // neighbour-search cell size / search radius, 1 to 100
};

// discretisation.dr, support_radius_over_dr, dt or courant_number (dt = courant_number h / c
// with c = sound_speed), cell_size_factor; one-line case errors for bad values.
ParticleDiscretisation read_particle_discretisation(const CaseFile& case_file, double sound_speed);

// Paper 1 eq. (7): range r_wall, strength E_wall / m and regularisation eps.
struct WallSettings {
  double radius = 0.0;          // r_wall (m)
  double energy_per_mass = 0.0; // E_wall / m (J/kg)
  double epsilon = 0.0;         // eps (m)

  WallPotential potential() const {
    return {radius * radius + epsilon * epsilon, epsilon * epsilon, energy_per_mass};
  }
};

// wall.radius_over_dr, energy_per_mass, epsilon.
WallSettings read_wall_settings(const CaseFile& case_file, const ParticleDiscretisation& d);

// Their keys; the meanings of support_radius_over_dr and of c in courant_number are the model's.
std::vector<KeyDecl> particle_discretisation_case_keys(const std::string& support_radius_meaning,
                                                       const std::string& courant_meaning);
std::vector<KeyDecl> wall_case_keys(const std::string& equation);

} // namespace revsph
