#include "models/two_fluid/parameters.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "models/two_fluid/case_keys.hpp" // generated from keys.toml

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>
#include <string>

namespace revsph::two_fluid {

namespace {

MutualFriction read_mutual_friction(const CaseFile& case_file, double superfluid_density) {
  const Keys& k = keys();
  MutualFriction f;
  f.superfluid_density = superfluid_density;
  f.alpha = k.alpha.read(case_file);
  // Read whenever given, so that a case can switch the friction off with alpha alone.
  if (f.alpha == 0.0 && !case_file.has(k.circulation_quantum.path()) &&
      !case_file.has(k.initial_line_density.path())) {
    return f;
  }
  f.circulation_quantum = k.circulation_quantum.require(case_file);
  f.initial_line_density = k.initial_line_density.require(case_file);
  f.vinen_beta = k.vinen_beta.read(case_file);
  return f;
}

// Sec. IV.1: dt below the CFL, diffusion and body-force limits of its ref. [54] (Morris, Fox &
// Zhu 1997): courant_number h_s / c (read_particle_discretisation), viscous_number h^2 / nu and
// force_number sqrt(h / g), h = support / 2 the Wendland kernel's smoothing length and nu the
// normal fluid's (eta_bar + eta_r) / rho_n.
template <int D>
void limit_time_step(const CaseFile& case_file, Parameters<D>& p) {
  const Keys& k = keys();
  const double h = 0.5 * p.support_radius;
  const double viscous_number = k.viscous_number.read(case_file);
  require_positive_finite(case_file, k.viscous_number.path().c_str(), "a time-step factor",
                          viscous_number);
  const double force_number = k.force_number.read(case_file);
  require_positive_finite(case_file, k.force_number.path().c_str(), "a time-step factor",
                          force_number);
  if (p.normal_viscosity > 0.0) {
    const double nu = (p.normal_viscosity + p.rotational_viscosity) / p.normal_density;
    p.dt = std::min(p.dt, viscous_number * h * h / nu);
  }
  if (p.gravity != 0.0) {
    p.dt = std::min(p.dt, force_number * std::sqrt(h / std::abs(p.gravity)));
  }
}

} // namespace

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  const Keys& k = keys();
  Parameters<D> p = k.read_fields<Parameters<D>>(case_file);

  Thermomechanical& t = p.thermomechanical;
  t.entropy_scale = k.entropy_scale.read(case_file);
  // Read whenever given, so that a case can switch the force off with the scale alone.
  if (t.entropy_scale > 0.0 || case_file.has(k.first_sound_speed.path())) {
    t.first_sound_speed = k.first_sound_speed.require(case_file);
    t.reference_density =
        k.reference_density.read_or(case_file, p.superfluid_density + p.normal_density);
    require_positive_finite(case_file, k.reference_density.path().c_str(), "the reference density",
                            t.reference_density);
  }
  // Read whether or not the force is on, so that a bad value is never passed over.
  t.difference_form = k.difference_form.read(case_file);
  if (p.interpenetrating && t.entropy_scale > 0.0) {
    case_file.fail(k.interpenetrating.path(),
                   "the thermomechanical force (eq. 27) is written for "
                   "separate phases; set thermomechanical.entropy_scale = 0");
  }
  if (p.undiluted_viscosity && p.interpenetrating) {
    case_file.fail(k.undiluted_viscosity.path(),
                   "interpenetrating phases are undiluted already (phase volumes); remove it");
  }
  p.mutual_friction = read_mutual_friction(case_file, p.superfluid_density);
  // Read whether or not the friction is on, so that a bad value is never passed over.
  p.mutual_friction.wall_at_initial_line_density = k.wall_at_initial_line_density.read(case_file);
  require_positive_finite(case_file, k.limiter.path().c_str(), "the dissipation limiter",
                          p.contact.limiter);
  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.sound_speed);
  static_cast<ParticleDiscretisation&>(p) = discretisation;
  if (!case_file.has("discretisation.dt")) {
    limit_time_step(case_file, p);
  }
  // The friction is an explicit exchange: over a half step it must relax the relative velocity
  // by a small fraction, not overshoot it (C_L / rho is largest at t = 0, where L = L0).
  if (p.mutual_friction.active()) {
    const double rate =
        p.mutual_friction.coefficient(0.0) / std::min(p.superfluid_density, p.normal_density);
    if (!(rate * p.dt < 0.1)) {
      case_file.fail(k.initial_line_density.path(),
                     "the friction rate (2/3) alpha kappa L0 rho_s / min(rho_s, rho_n) = " +
                         std::to_string(rate) + " 1/s relaxes more than 10 % per step of " +
                         std::to_string(p.dt) + " s");
    }
  }
  // Eq. (40)'s initial spin, C_omega v_max / (0.5 d), held fixed (README).
  const double spin_coefficient = k.spin_coefficient.read(case_file);
  if (spin_coefficient > 0.0 || case_file.has(k.spin_max_speed.path())) {
    p.spin = spin_coefficient * k.spin_max_speed.require(case_file) / (0.5 * p.dr);
    if (spin_coefficient > 0.0) {
      require_positive_finite(case_file, k.spin_max_speed.path().c_str(),
                              "the spin C_omega v_max / (0.5 dr)", p.spin);
    }
  }
  p.domain = read_domain<D>(case_file);
  p.seed = static_cast<std::uint64_t>(k.seed.read(case_file));
  if (const std::optional<double> height = k.interface_height.read_optional(case_file)) {
    p.interface.given = true;
    p.interface.height = *height;
    p.interface.amplitude = k.interface_amplitude.read(case_file);
    p.interface.wavelength = k.interface_wavelength.require(case_file);
  }

  const double heavier =
      std::max(p.rest_density(true), p.rest_density(false)) * dmath::integer_power(p.dr, D);
  p.position_scale = k.position_exponent.read(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.momentum_scale = k.momentum_exponent.read(case_file, heavier * p.sound_speed);
  p.density_scale = k.density_exponent.read(case_file, dmath::integer_power(p.dr, -D));
  p.energy_scale = k.energy_exponent.read(case_file, heavier * p.sound_speed * p.sound_speed);
  return p;
}

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::two_fluid
