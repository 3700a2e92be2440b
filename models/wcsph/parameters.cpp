#include "models/wcsph/parameters.hpp"

#include "models/wcsph/case_keys.hpp" // generated from keys.toml

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>

namespace revsph::wcsph {

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  const Keys& k = keys();
  Parameters<D> p = k.read_fields<Parameters<D>>(case_file);

  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.sound_speed);
  static_cast<ParticleDiscretisation&>(p) = discretisation;
  p.wall = read_wall_settings(case_file, discretisation);

  if (p.shepard_active && p.shepard_every == 0) {
    case_file.fail(k.shepard_every.path(), "an active filter needs shepard_every >= 1");
  }
  // The viscosity's update is explicit: over a time tau it multiplies the approach speed of the
  // stiffest pattern by 1 - lambda tau, lambda ~ alpha c / h (h = support / 2). Measured on
  // stirred dam breaks and columns (tests/system/wcsph_viscosity_test.cpp), kinetic energy first
  // grows at alpha c tau / h = 1.5 in 1D, 2 in 2D, 3 in 3D: a case above 1 is refused.
  if (p.artificial_viscosity > 0.0) {
    const double tau = p.splitting == Splitting::strang ? 0.5 * p.dt : p.dt;
    const double stiffness =
        p.artificial_viscosity * p.sound_speed * tau / (0.5 * p.support_radius);
    if (stiffness > 1.0) {
      case_file.fail(k.artificial_viscosity.path(),
                     "alpha c tau / h = " + format_number(stiffness) +
                         " > 1 (tau = dt / 2 with step.splitting \"strang\", else dt; h = the "
                         "support radius / 2): the explicit update would amplify velocities; "
                         "lower alpha or dt");
    }
  }
  if (p.initial_field == InitialField::gresho_vortex && D != 2) {
    case_file.fail(k.initial_field.path(), "the Gresho vortex is two-dimensional");
  }
  if (case_file.has(k.centre)) {
    const std::vector<double> centre = case_file.numbers(k.centre, D);
    std::copy(centre.begin(), centre.end(), p.centre.begin());
  }

  p.isc.max_iterations = static_cast<int>(k.isc_max_iterations.read(case_file));
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

template Parameters<1> read_parameters<1>(const CaseFile&);
template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::wcsph
