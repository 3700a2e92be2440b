#include "models/two_fluid/parameters.hpp"

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>
#include <string>

namespace revsph::two_fluid {

namespace {

// Every key of a two-fluid case file beyond common_case_keys(), including those the core's
// readers and setup.cpp read, in the reference's order.
struct Keys : KeySet {
  Keys() : KeySet("two_fluid") {}
  const std::string dimension = declare({"dimension", KeyType::integer, "-", "required", "2 or 3"});
  const Key<double> superfluid_density =
      number("physics.superfluid_density", "kg/m^3", "required",
             "rho_s: reference density of the superfluid particles (Tait, mass rho_s dr^D); "
             "> 0",
             positive_or_why);
  const Key<double> normal_density =
      number("physics.normal_density", "kg/m^3", "required",
             "rho_n: reference density of the normal and wall particles; > 0", positive_or_why);
  const Choice<bool> interpenetrating = choice<bool>(
      "physics.phases", "\"separate\"",
      "\"separate\": a particle carries its kind's density (layers, sec. V.1); "
      "\"interpenetrating\": every particle carries rho_s + rho_n and a phase's partial "
      "density is its particles' share, viscosity, friction and spin using the phase's "
      "volume V rho / rho_k (a random mixture as a two-fluid continuum, README)",
      {{"separate", false}, {"interpenetrating", true}});
  const Key<double> sound_speed =
      number("physics.sound_speed", "m/s", "required",
             "c of the Tait equation p = rho_k c^2 / gamma ((rho / rho_k)^gamma - 1) (not given "
             "by the paper: a numerical speed, 10 times the largest expected flow speed); > 0",
             positive_or_why);
  const Key<double> tait_exponent =
      number("physics.tait_exponent", "1", "7", "gamma of the Tait equation, 1 to 20",
             must<double>([](double g) { return g >= 1.0 && g <= 20.0; }, "must be in [1, 20]"));
  const Key<double> background_pressure =
      number("physics.background_pressure", "Pa", "0",
             "added to every Tait pressure (keeps a closed box's top in compression); >= 0",
             non_negative());
  const Key<double> temperature =
      number("physics.temperature", "K", "required",
             "T0: every particle's temperature, kept (sec. IV.4); > 0", positive_or_why);
  const Key<double> gravity = KeySet::gravity();
  const Key<double> gravity_reference_height = KeySet::gravity_reference_height();
  const Choice<Splitting> splitting = KeySet::splitting("strang");
  const Key<double> rotational_viscosity =
      number("physics.rotational_viscosity", "Pa s", "0",
             "eta_r of eq. (39): the spin term 2 eta_r curl omega (eq. 40), with the viscosity "
             "eta_bar + eta_r; >= 0",
             non_negative("no spin term"));
  const Key<double> normal_viscosity =
      number("physics.normal_viscosity", "Pa s", "0",
             "eta_bar = eta_n of eqs. (34, 39): the Laplacian viscosity (eta_bar + eta_r) on "
             "normal-normal and normal-wall pairs; >= 0 (0: no Laplacian viscosity, eta_r's "
             "share included); irreversible",
             non_negative());
  const Choice<bool> central_viscosity = choice<bool>(
      "physics.viscosity_form", "\"laplacian\"",
      "\"laplacian\": eq. (34), the pair force along v_a - v_b; \"central\": Monaghan's, "
      "along x_ab, which keeps angular momentum (README)",
      {{"laplacian", false}, {"central", true}});
  const Choice<bool> undiluted_viscosity = choice<bool>(
      "physics.separate_phase_viscosity", "\"diluted\"",
      "with separate phases: \"diluted\": eq. (34) as is, so that in a random mixture the "
      "normal particles, N_n / N of all, diffuse momentum at N_n / N of nu_n; \"undiluted\": "
      "the normal-normal pairs' coefficient times N / N_n (normal-wall pairs unchanged), "
      "nu_n = (eta_bar + eta_r) / rho_n as the interpenetrating phases' volumes give "
      "(README, \"Wall grip\")",
      {{"diluted", false}, {"undiluted", true}});
  const Choice<PressureForm> pressure_form = choice<PressureForm>(
      "pressure.form", "\"hu_adams\"",
      "\"hu_adams\": eqs. (37-38); \"standard\": eq. (26); \"variational\": the gradient "
      "of sum m e(rho) (README)",
      {{"hu_adams", PressureForm::hu_adams},
       {"standard", PressureForm::standard},
       {"variational", PressureForm::variational}});
  const Key<double> entropy_scale =
      number("thermomechanical.entropy_scale", "1", "0",
             "C_e of eq. (41): sigma = C_e S(T) / reference_density, S of eq. (21); >= 0 (0: no "
             "thermomechanical force)",
             non_negative("no force"));
  const Key<double> first_sound_speed =
      number("thermomechanical.first_sound_speed", "m/s", "required with a scale",
             "c of eq. (21) (the phonons' sound speed); > 0", positive_or_why);
  const Choice<bool> difference_form = choice<bool>(
      "thermomechanical.form", "\"symmetric\"",
      "\"symmetric\": eq. (27) as printed; \"difference\": sigma_i sum_j V_j (T_j - T_i) "
      "grad W_ij, which vanishes for a uniform T (README)",
      {{"symmetric", false}, {"difference", true}});
  const Key<double> reference_density =
      number("thermomechanical.reference_density", "kg/m^3", "superfluid_density + normal_density",
             "turns eq. (21)'s entropy per volume into sigma per mass; > 0");
  const Key<double> spin_coefficient =
      number("spin.coefficient", "1", "0",
             "C_omega of sec. IV.2: every fluid particle's spin is C_omega max_speed / (0.5 dr), "
             "held fixed; >= 0",
             non_negative());
  const Key<double> spin_max_speed = number("spin.max_speed", "m/s", "required with a coefficient",
                                            "v_max of sec. IV.2; > 0", positive_or_why);
  const Key<double> alpha = number("mutual_friction.alpha", "1", "0",
                                   "alpha of eq. (8); >= 0 (0: no mutual friction); irreversible",
                                   non_negative("no mutual friction"));
  const Key<double> circulation_quantum =
      number("mutual_friction.circulation_quantum", "m^2/s", "required with alpha",
             "kappa = h / m4 of eq. (8); > 0", positive_or_why);
  const Key<double> initial_line_density =
      number("mutual_friction.initial_line_density", "1/m^2", "required with alpha",
             "L0 of eq. (9); > 0", positive_or_why);
  const Key<double> vinen_beta = number("mutual_friction.vinen_beta", "m^2/s", "0",
                                        "beta_v of eq. (9): 1 / L(t) = 1 / L0 + beta_v t; >= 0",
                                        non_negative("L stays at L0"));
  const Choice<bool> wall_at_initial_line_density = choice<bool>(
      "mutual_friction.wall_line_density", "\"decaying\"",
      "L of the friction against wall particles: \"decaying\": Vinen's L(t) as the fluid's; "
      "\"initial\": L0 for the whole run (a wall that keeps its grip on the superfluid, "
      "README, \"Wall grip\")",
      {{"decaying", false}, {"initial", true}});
  const Key<bool> collision =
      boolean("collision.on", "false",
              "the pair collision of sec. IV.1 (ref. [40]) for r < dr, approaching pairs only; "
              "irreversible");
  const Key<double> restitution =
      number("collision.restitution", "1", "0.2",
             "e: an approaching pair leaves at e times its normal speed; in [0, 1] (not given)",
             must<double>([](double e) { return e >= 0.0 && e <= 1.0; }, "must be in [0, 1]"));
  const Key<bool> riemann =
      boolean("riemann.on", "false",
              "the pairwise Riemann dissipation of sec. IV.1 (ref. [41], Zhang, Hu & Adams 2017) "
              "for r < dr, approaching pairs only; irreversible");
  const Key<double> limiter =
      number("riemann.limiter", "1", "3", "beta = min(limiter (U_L - U_R), c) of ref. [41]; > 0");
  const Key<double> random_velocity =
      number("initial.random_velocity", "m/s", "0",
             "each velocity component of every superfluid and normal particle uniform in "
             "[-value, value] at the start (a test state exercising every term); >= 0",
             non_negative());
  const Key<std::int64_t> seed =
      integer("initial.seed", "1", "seed of the random velocities; >= 0",
              must<std::int64_t>([](std::int64_t n) { return n >= 0; }, "must be >= 0"));
  const Key<double> interface_height =
      number("interface.height", "m", "none",
             "with it, the particles of superfluid and normal blocks are superfluid above "
             "y = height - amplitude sin(2 pi x / wavelength) and normal below (sec. V.1)");
  const Key<double> interface_amplitude =
      number("interface.amplitude", "m", "0", "the interface's amplitude");
  const Key<double> interface_wavelength =
      number("interface.wavelength", "m", "required with a height",
             "the interface's wavelength; > 0", positive_or_why);
  const int discretisation = declare(particle_discretisation_case_keys(
      "kernel support radius in units of dr (not given by the paper; 3 as Hu & Adams)",
      "time step as a fraction of support / c (the CFL limit of sec. IV.1)"));
  const int regions =
      (declare(domain_case_keys()),
       declare(particle_block_case_keys({"superfluid", "normal", "mixed", "wall"})), 0);
  // Per-block keys, read by setup.cpp.
  const int blocks =
      (declare({"particles[].superfluid_fraction", KeyType::number, "1",
                "required for kind = \"mixed\" (interpenetrating phases: rho_s / (rho_s + rho_n))",
                "share of a mixed block's lattice points that are superfluid (drawn at random, "
                "sec. V.3); in (0, 1); with interpenetrating phases rho_s / (rho_s + rho_n)"}),
       declare(
           {"particles[].seed", KeyType::integer, "-", "1", "seed of a mixed block's draw; >= 0"}),
       declare({"particles[].velocity", KeyType::numbers, "m/s", "zero",
                "velocity of a wall block (a lid), seen by the irreversible terms only"}),
       declare({"particles[].rotation_rate", KeyType::number, "1/s", "0",
                "a wall block turning about rotation_centre (counterclockwise): its velocity "
                "omega x (x - centre), seen by the irreversible terms only"}),
       declare({"particles[].rotation_centre", KeyType::numbers, "m", "origin",
                "centre of a turning wall block"}),
       declare({"particles[].wall_motion",
                KeyType::string,
                "-",
                "\"frozen\"",
                "a turning wall block: \"frozen\": its particles stay where they are, their "
                "velocity omega x (x - centre) seen by the irreversible terms only; \"rigid\": "
                "they turn with it, position and velocity rotated by dt omega about "
                "rotation_centre in each drift (exactly reversible, README, \"Wall grip\"); 2D, "
                "no velocity key",
                {"frozen", "rigid"}}),
       0);
  const Key<double> viscous_number =
      number("discretisation.viscous_number", "1", "0.125",
             "dt <= viscous_number h^2 / nu (h = support / 2, nu = (eta_bar + eta_r) / rho_n) "
             "where dt comes from courant_number (sec. IV.1, Morris et al. 1997); > 0");
  const Key<double> force_number =
      number("discretisation.force_number", "1", "0.25",
             "dt <= force_number sqrt(h / g) where dt comes from courant_number; > 0");
  // Default scales: positions 52 fraction bits below the domain size; momenta resolve
  // m c 2^-50 of the heavier kind's particle; number densities dr^-D 2^-48.
  const PositionScaleKey position_exponent = position_scale();
  const ScaleKey momentum_exponent = scale("momentum", "max(rho_s, rho_n) dr^D c", 50,
                                           "momenta are stored as integers times 2^exponent");
  const ScaleKey density_exponent =
      scale("density", "dr^-D", 48, "scale of the number-density sums sum_j W_ij");
  const ScaleKey energy_exponent =
      scale("energy", "max(rho_s, rho_n) dr^D c^2", 60,
            "scale of the walls' work summed over pairs (an energy account)");
};

const Keys& keys() {
  static const Keys declared;
  return declared;
}

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
  Parameters<D> p;
  p.superfluid_density = k.superfluid_density.read(case_file);
  p.normal_density = k.normal_density.read(case_file);
  p.sound_speed = k.sound_speed.read(case_file);
  p.tait_exponent = k.tait_exponent.read(case_file);
  p.background_pressure = k.background_pressure.read(case_file);
  p.temperature = k.temperature.read(case_file);
  p.gravity = k.gravity.read(case_file);
  p.gravity_reference_height = k.gravity_reference_height.read(case_file);
  p.splitting = k.splitting.read(case_file);
  p.pressure_form = k.pressure_form.read(case_file);
  p.interpenetrating = k.interpenetrating.read(case_file);

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
  p.rotational_viscosity = k.rotational_viscosity.read(case_file);
  p.normal_viscosity = k.normal_viscosity.read(case_file);
  p.central_viscosity = k.central_viscosity.read(case_file);
  p.undiluted_viscosity = k.undiluted_viscosity.read(case_file);
  if (p.undiluted_viscosity && p.interpenetrating) {
    case_file.fail(k.undiluted_viscosity.path(),
                   "interpenetrating phases are undiluted already (phase volumes); remove it");
  }
  p.mutual_friction = read_mutual_friction(case_file, p.superfluid_density);
  // Read whether or not the friction is on, so that a bad value is never passed over.
  p.mutual_friction.wall_at_initial_line_density = k.wall_at_initial_line_density.read(case_file);
  p.contact.collision = k.collision.read(case_file);
  p.contact.restitution = k.restitution.read(case_file);
  p.contact.riemann = k.riemann.read(case_file);
  p.contact.limiter = k.limiter.read(case_file);
  require_positive_finite(case_file, k.limiter.path().c_str(), "the dissipation limiter",
                          p.contact.limiter);
  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.sound_speed);
  p.dr = discretisation.dr;
  p.support_radius = discretisation.support_radius;
  p.dt = discretisation.dt;
  if (!case_file.has("discretisation.dt")) {
    limit_time_step(case_file, p);
  }
  p.cell_size_factor = discretisation.cell_size_factor;
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
  p.random_velocity = k.random_velocity.read(case_file);
  p.seed = static_cast<std::uint64_t>(k.seed.read(case_file));
  if (const std::optional<double> height = k.interface_height.read_optional(case_file)) {
    p.interface.given = true;
    p.interface.height = *height;
    p.interface.amplitude = k.interface_amplitude.read(case_file);
    p.interface.wavelength = k.interface_wavelength.require(case_file);
  }

  const double heavier = std::max(p.rest_density(true), p.rest_density(false)) * std::pow(p.dr, D);
  p.position_scale = k.position_exponent.read(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.momentum_scale = k.momentum_exponent.read(case_file, heavier * p.sound_speed);
  p.density_scale = k.density_exponent.read(case_file, std::pow(p.dr, -D));
  p.energy_scale = k.energy_exponent.read(case_file, heavier * p.sound_speed * p.sound_speed);
  return p;
}

const KeyTable& case_keys() {
  return keys().table();
}

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::two_fluid
