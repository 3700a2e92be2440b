#include "models/two_fluid/parameters.hpp"

#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>
#include <string>

namespace revsph::two_fluid {

namespace {

PressureForm read_pressure_form(const CaseFile& case_file) {
  const std::string form = case_file.string_or("pressure.form", "hu_adams");
  if (form == "hu_adams") {
    return PressureForm::hu_adams;
  }
  if (form == "standard") {
    return PressureForm::standard;
  }
  if (form == "variational") {
    return PressureForm::variational;
  }
  case_file.fail("pressure.form",
                 "expected \"hu_adams\", \"standard\" or \"variational\", got \"" + form + "\"");
}

MutualFriction read_mutual_friction(const CaseFile& case_file, double superfluid_density) {
  MutualFriction f;
  f.superfluid_density = superfluid_density;
  f.alpha = case_file.non_negative_number_or("mutual_friction.alpha", 0.0, "no mutual friction");
  // Read whenever given, so that a case can switch the friction off with alpha alone.
  if (f.alpha == 0.0 && !case_file.has("mutual_friction.circulation_quantum") &&
      !case_file.has("mutual_friction.initial_line_density")) {
    return f;
  }
  f.circulation_quantum = case_file.positive_number("mutual_friction.circulation_quantum");
  f.initial_line_density = case_file.positive_number("mutual_friction.initial_line_density");
  f.vinen_beta =
      case_file.non_negative_number_or("mutual_friction.vinen_beta", 0.0, "L stays at L0");
  return f;
}

// Read whether or not the friction is on, so that a bad value is never passed over.
bool read_wall_line_density(const CaseFile& case_file) {
  const std::string value = case_file.string_or("mutual_friction.wall_line_density", "decaying");
  if (value != "decaying" && value != "initial") {
    case_file.fail("mutual_friction.wall_line_density",
                   "expected \"decaying\" or \"initial\", got \"" + value + "\"");
  }
  return value == "initial";
}

bool read_undiluted_viscosity(const CaseFile& case_file, bool interpenetrating) {
  const std::string value = case_file.string_or("physics.separate_phase_viscosity", "diluted");
  if (value != "diluted" && value != "undiluted") {
    case_file.fail("physics.separate_phase_viscosity",
                   "expected \"diluted\" or \"undiluted\", got \"" + value + "\"");
  }
  if (value == "undiluted" && interpenetrating) {
    case_file.fail("physics.separate_phase_viscosity",
                   "interpenetrating phases are undiluted already (phase volumes); remove it");
  }
  return value == "undiluted";
}

// Sec. IV.1: dt below the CFL, diffusion and body-force limits of its ref. [54] (Morris, Fox &
// Zhu 1997): courant_number h_s / c (read_particle_discretisation), viscous_number h^2 / nu and
// force_number sqrt(h / g), h = support / 2 the Wendland kernel's smoothing length and nu the
// normal fluid's (eta_bar + eta_r) / rho_n.
template <int D>
void limit_time_step(const CaseFile& case_file, Parameters<D>& p) {
  const double h = 0.5 * p.support_radius;
  const double viscous_number = case_file.number_or("discretisation.viscous_number", 0.125);
  require_positive_finite(case_file, "discretisation.viscous_number", "a time-step factor",
                          viscous_number);
  const double force_number = case_file.number_or("discretisation.force_number", 0.25);
  require_positive_finite(case_file, "discretisation.force_number", "a time-step factor",
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
  Parameters<D> p;
  p.superfluid_density = case_file.positive_number("physics.superfluid_density");
  p.normal_density = case_file.positive_number("physics.normal_density");
  p.sound_speed = case_file.positive_number("physics.sound_speed");
  p.tait_exponent = case_file.number_or("physics.tait_exponent", 7.0);
  if (!(p.tait_exponent >= 1.0 && p.tait_exponent <= 20.0)) {
    case_file.fail("physics.tait_exponent", "must be in [1, 20]");
  }
  p.background_pressure = case_file.non_negative_number_or("physics.background_pressure", 0.0);
  p.temperature = case_file.positive_number("physics.temperature");
  p.gravity = case_file.number_or("physics.gravity", 0.0);
  p.gravity_reference_height = case_file.number_or("physics.gravity_reference_height", 0.0);
  p.pressure_form = read_pressure_form(case_file);
  const std::string phases = case_file.string_or("physics.phases", "separate");
  if (phases != "separate" && phases != "interpenetrating") {
    case_file.fail("physics.phases",
                   "expected \"separate\" or \"interpenetrating\", got \"" + phases + "\"");
  }
  p.interpenetrating = phases == "interpenetrating";

  Thermomechanical& t = p.thermomechanical;
  t.entropy_scale =
      case_file.non_negative_number_or("thermomechanical.entropy_scale", 0.0, "no force");
  // Read whenever given, so that a case can switch the force off with the scale alone.
  if (t.entropy_scale > 0.0 || case_file.has("thermomechanical.first_sound_speed")) {
    t.first_sound_speed = case_file.positive_number("thermomechanical.first_sound_speed");
    t.reference_density = case_file.number_or("thermomechanical.reference_density",
                                              p.superfluid_density + p.normal_density);
    require_positive_finite(case_file, "thermomechanical.reference_density",
                            "the reference density", t.reference_density);
  }
  // Read whether or not the force is on, so that a bad value is never passed over.
  const std::string form = case_file.string_or("thermomechanical.form", "symmetric");
  if (form != "symmetric" && form != "difference") {
    case_file.fail("thermomechanical.form",
                   "expected \"symmetric\" or \"difference\", got \"" + form + "\"");
  }
  t.difference_form = form == "difference";
  if (p.interpenetrating && t.entropy_scale > 0.0) {
    case_file.fail("physics.phases", "the thermomechanical force (eq. 27) is written for "
                                     "separate phases; set thermomechanical.entropy_scale = 0");
  }
  p.rotational_viscosity =
      case_file.non_negative_number_or("physics.rotational_viscosity", 0.0, "no spin term");
  p.normal_viscosity = case_file.non_negative_number_or("physics.normal_viscosity", 0.0);
  const std::string viscosity_form = case_file.string_or("physics.viscosity_form", "laplacian");
  if (viscosity_form != "laplacian" && viscosity_form != "central") {
    case_file.fail("physics.viscosity_form",
                   "expected \"laplacian\" or \"central\", got \"" + viscosity_form + "\"");
  }
  p.central_viscosity = viscosity_form == "central";
  p.undiluted_viscosity = read_undiluted_viscosity(case_file, p.interpenetrating);
  p.mutual_friction = read_mutual_friction(case_file, p.superfluid_density);
  p.mutual_friction.wall_at_initial_line_density = read_wall_line_density(case_file);
  p.contact.collision = case_file.boolean_or("collision.on", false);
  p.contact.restitution = case_file.number_or("collision.restitution", p.contact.restitution);
  if (!(p.contact.restitution >= 0.0 && p.contact.restitution <= 1.0)) {
    case_file.fail("collision.restitution", "must be in [0, 1]");
  }
  p.contact.riemann = case_file.boolean_or("riemann.on", false);
  p.contact.limiter = case_file.number_or("riemann.limiter", p.contact.limiter);
  require_positive_finite(case_file, "riemann.limiter", "the dissipation limiter",
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
      case_file.fail("mutual_friction.initial_line_density",
                     "the friction rate (2/3) alpha kappa L0 rho_s / min(rho_s, rho_n) = " +
                         std::to_string(rate) + " 1/s relaxes more than 10 % per step of " +
                         std::to_string(p.dt) + " s");
    }
  }
  // Eq. (40)'s initial spin, C_omega v_max / (0.5 d), held fixed (README).
  const double spin_coefficient = case_file.non_negative_number_or("spin.coefficient", 0.0);
  if (spin_coefficient > 0.0 || case_file.has("spin.max_speed")) {
    p.spin = spin_coefficient * case_file.positive_number("spin.max_speed") / (0.5 * p.dr);
    if (spin_coefficient > 0.0) {
      require_positive_finite(case_file, "spin.max_speed", "the spin C_omega v_max / (0.5 dr)",
                              p.spin);
    }
  }
  p.domain = read_domain<D>(case_file);
  p.random_velocity = case_file.non_negative_number_or("initial.random_velocity", 0.0);
  const std::int64_t seed = case_file.integer_or("initial.seed", 1);
  if (seed < 0) {
    case_file.fail("initial.seed", "must be >= 0");
  }
  p.seed = static_cast<std::uint64_t>(seed);
  if (case_file.has("interface.height")) {
    p.interface.given = true;
    p.interface.height = case_file.number("interface.height");
    p.interface.amplitude = case_file.number_or("interface.amplitude", 0.0);
    p.interface.wavelength = case_file.positive_number("interface.wavelength");
  }

  // Default scales: positions 52 fraction bits below the domain size; momenta resolve
  // m c 2^-50 of the heavier kind's particle; number densities dr^-D 2^-48.
  const double heavier = std::max(p.rest_density(true), p.rest_density(false)) * std::pow(p.dr, D);
  p.position_scale = position_scale_or(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.momentum_scale =
      scale_or(case_file, "fixed_point.momentum_exponent", heavier * p.sound_speed, 50);
  p.density_scale = scale_or(case_file, "fixed_point.density_exponent", std::pow(p.dr, -D), 48);
  p.energy_scale = scale_or(case_file, "fixed_point.energy_exponent",
                            heavier * p.sound_speed * p.sound_speed, 60);
  return p;
}

const KeyTable& case_keys() {
  static const KeyTable table = [] {
    using T = KeyType;
    KeyTable t("two_fluid");
    t.add({"dimension", T::integer, "-", "required", "2 or 3"});
    t.add({"physics.superfluid_density", T::number, "kg/m^3", "required",
           "rho_s: reference density of the superfluid particles (Tait, mass rho_s dr^D); "
           "> 0"});
    t.add({"physics.normal_density", T::number, "kg/m^3", "required",
           "rho_n: reference density of the normal and wall particles; > 0"});
    t.add({"physics.phases",
           T::string,
           "-",
           "\"separate\"",
           "\"separate\": a particle carries its kind's density (layers, sec. V.1); "
           "\"interpenetrating\": every particle carries rho_s + rho_n and a phase's partial "
           "density is its particles' share, viscosity, friction and spin using the phase's "
           "volume V rho / rho_k (a random mixture as a two-fluid continuum, README)",
           {"separate", "interpenetrating"}});
    t.add({"physics.sound_speed", T::number, "m/s", "required",
           "c of the Tait equation p = rho_k c^2 / gamma ((rho / rho_k)^gamma - 1) (not given "
           "by the paper: a numerical speed, 10 times the largest expected flow speed); > 0"});
    t.add({"physics.tait_exponent", T::number, "1", "7", "gamma of the Tait equation, 1 to 20"});
    t.add({"physics.background_pressure", T::number, "Pa", "0",
           "added to every Tait pressure (keeps a closed box's top in compression); >= 0"});
    t.add({"physics.temperature", T::number, "K", "required",
           "T0: every particle's temperature, kept (sec. IV.4); > 0"});
    t.add({"physics.gravity", T::number, "m/s^2", "0",
           "gravitational acceleration g along minus the last axis"});
    t.add({"physics.gravity_reference_height", T::number, "m", "0",
           "height of zero gravitational energy (shifts the reported energy only)"});
    t.add({"physics.rotational_viscosity", T::number, "Pa s", "0",
           "eta_r of eq. (39): the spin term 2 eta_r curl omega (eq. 40), with the viscosity "
           "eta_bar + eta_r; >= 0"});
    t.add({"physics.normal_viscosity", T::number, "Pa s", "0",
           "eta_bar = eta_n of eqs. (34, 39): the Laplacian viscosity (eta_bar + eta_r) on "
           "normal-normal and normal-wall pairs; >= 0 (0: no Laplacian viscosity, eta_r's "
           "share included); irreversible"});
    t.add({"physics.viscosity_form",
           T::string,
           "-",
           "\"laplacian\"",
           "\"laplacian\": eq. (34), the pair force along v_a - v_b; \"central\": Monaghan's, "
           "along x_ab, which keeps angular momentum (README)",
           {"laplacian", "central"}});
    t.add({"physics.separate_phase_viscosity",
           T::string,
           "-",
           "\"diluted\"",
           "with separate phases: \"diluted\": eq. (34) as is, so that in a random mixture the "
           "normal particles, N_n / N of all, diffuse momentum at N_n / N of nu_n; \"undiluted\": "
           "the normal-normal pairs' coefficient times N / N_n (normal-wall pairs unchanged), "
           "nu_n = (eta_bar + eta_r) / rho_n as the interpenetrating phases' volumes give "
           "(README, \"Wall grip\")",
           {"diluted", "undiluted"}});
    t.add({"pressure.form",
           T::string,
           "-",
           "\"hu_adams\"",
           "\"hu_adams\": eqs. (37-38); \"standard\": eq. (26); \"variational\": the gradient "
           "of sum m e(rho) (README)",
           {"hu_adams", "standard", "variational"}});
    t.add({"thermomechanical.entropy_scale", T::number, "1", "0",
           "C_e of eq. (41): sigma = C_e S(T) / reference_density, S of eq. (21); >= 0 (0: no "
           "thermomechanical force)"});
    t.add({"thermomechanical.first_sound_speed", T::number, "m/s", "required with a scale",
           "c of eq. (21) (the phonons' sound speed); > 0"});
    t.add({"thermomechanical.form",
           T::string,
           "-",
           "\"symmetric\"",
           "\"symmetric\": eq. (27) as printed; \"difference\": sigma_i sum_j V_j (T_j - T_i) "
           "grad W_ij, which vanishes for a uniform T (README)",
           {"symmetric", "difference"}});
    t.add({"thermomechanical.reference_density", T::number, "kg/m^3",
           "superfluid_density + normal_density",
           "turns eq. (21)'s entropy per volume into sigma per mass; > 0"});
    t.add({"spin.coefficient", T::number, "1", "0",
           "C_omega of sec. IV.2: every fluid particle's spin is C_omega max_speed / (0.5 dr), "
           "held fixed; >= 0"});
    t.add({"spin.max_speed", T::number, "m/s", "required with a coefficient",
           "v_max of sec. IV.2; > 0"});
    t.add({"mutual_friction.alpha", T::number, "1", "0",
           "alpha of eq. (8); >= 0 (0: no mutual friction); irreversible"});
    t.add({"mutual_friction.circulation_quantum", T::number, "m^2/s", "required with alpha",
           "kappa = h / m4 of eq. (8); > 0"});
    t.add({"mutual_friction.initial_line_density", T::number, "1/m^2", "required with alpha",
           "L0 of eq. (9); > 0"});
    t.add({"mutual_friction.vinen_beta", T::number, "m^2/s", "0",
           "beta_v of eq. (9): 1 / L(t) = 1 / L0 + beta_v t; >= 0"});
    t.add({"mutual_friction.wall_line_density",
           T::string,
           "-",
           "\"decaying\"",
           "L of the friction against wall particles: \"decaying\": Vinen's L(t) as the fluid's; "
           "\"initial\": L0 for the whole run (a wall that keeps its grip on the superfluid, "
           "README, \"Wall grip\")",
           {"decaying", "initial"}});
    t.add({"collision.on", T::boolean, "-", "false",
           "the pair collision of sec. IV.1 (ref. [40]) for r < dr, approaching pairs only; "
           "irreversible"});
    t.add({"collision.restitution", T::number, "1", "0.2",
           "e: an approaching pair leaves at e times its normal speed; in [0, 1] (not given)"});
    t.add({"riemann.on", T::boolean, "-", "false",
           "the pairwise Riemann dissipation of sec. IV.1 (ref. [41], Zhang, Hu & Adams 2017) "
           "for r < dr, approaching pairs only; irreversible"});
    t.add({"riemann.limiter", T::number, "1", "3",
           "beta = min(limiter (U_L - U_R), c) of ref. [41]; > 0"});
    t.add({"initial.random_velocity", T::number, "m/s", "0",
           "each velocity component of every superfluid and normal particle uniform in "
           "[-value, value] at the start (a test state exercising every term); >= 0"});
    t.add({"initial.seed", T::integer, "-", "1", "seed of the random velocities; >= 0"});
    t.add({"interface.height", T::number, "m", "none",
           "with it, the particles of superfluid and normal blocks are superfluid above "
           "y = height - amplitude sin(2 pi x / wavelength) and normal below (sec. V.1)"});
    t.add({"interface.amplitude", T::number, "m", "0", "the interface's amplitude"});
    t.add({"interface.wavelength", T::number, "m", "required with a height",
           "the interface's wavelength; > 0"});
    t.add(particle_discretisation_case_keys(
        "kernel support radius in units of dr (not given by the paper; 3 as Hu & Adams)",
        "time step as a fraction of support / c (the CFL limit of sec. IV.1)"));
    t.add(domain_case_keys());
    t.add(particle_block_case_keys({"superfluid", "normal", "mixed", "wall"}));
    t.add({"particles[].superfluid_fraction", T::number, "1",
           "required for kind = \"mixed\" (interpenetrating phases: rho_s / (rho_s + rho_n))",
           "share of a mixed block's lattice points that are superfluid (drawn at random, "
           "sec. V.3); in (0, 1); with interpenetrating phases rho_s / (rho_s + rho_n)"});
    t.add({"particles[].seed", T::integer, "-", "1", "seed of a mixed block's draw; >= 0"});
    t.add({"particles[].velocity", T::numbers, "m/s", "zero",
           "velocity of a wall block (a lid), seen by the irreversible terms only"});
    t.add({"particles[].rotation_rate", T::number, "1/s", "0",
           "a wall block turning about rotation_centre (counterclockwise): its velocity "
           "omega x (x - centre), seen by the irreversible terms only"});
    t.add({"particles[].rotation_centre", T::numbers, "m", "origin",
           "centre of a turning wall block"});
    t.add({"particles[].wall_motion",
           T::string,
           "-",
           "\"frozen\"",
           "a turning wall block: \"frozen\": its particles stay where they are, their velocity "
           "omega x (x - centre) seen by the irreversible terms only; \"rigid\": they turn with "
           "it, position and velocity rotated by dt omega about rotation_centre in each drift "
           "(exactly reversible, README, \"Wall grip\"); 2D, no velocity key",
           {"frozen", "rigid"}});
    t.add({"discretisation.viscous_number", T::number, "1", "0.125",
           "dt <= viscous_number h^2 / nu (h = support / 2, nu = (eta_bar + eta_r) / rho_n) "
           "where dt comes from courant_number (sec. IV.1, Morris et al. 1997); > 0"});
    t.add({"discretisation.force_number", T::number, "1", "0.25",
           "dt <= force_number sqrt(h / g) where dt comes from courant_number; > 0"});
    t.add({"fixed_point.position_exponent", T::integer, "-",
           "covers the domain with 52 fraction bits",
           "positions are stored as integers times 2^exponent"});
    t.add({"fixed_point.momentum_exponent", T::integer, "-",
           "covers max(rho_s, rho_n) dr^D c with 50 fraction bits",
           "momenta are stored as integers times 2^exponent"});
    t.add({"fixed_point.density_exponent", T::integer, "-", "covers dr^-D with 48 fraction bits",
           "scale of the number-density sums sum_j W_ij"});
    t.add({"fixed_point.energy_exponent", T::integer, "-",
           "covers max(rho_s, rho_n) dr^D c^2 with 60 fraction bits",
           "scale of the walls' work summed over pairs (an energy account)"});
    return t;
  }();
  return table;
}

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::two_fluid
