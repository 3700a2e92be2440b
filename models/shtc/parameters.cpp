#include "models/shtc/parameters.hpp"

#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"

#include <cmath>
#include <numbers>

namespace revsph::shtc {

namespace {

// Sound speeds from Young's modulus and Poisson's ratio (paper 2 eq. 61, corrected):
// rho0 cs^2 = Y / (2 (1 + nu)), the shear modulus, and rho0 c0^2 = nu Y / ((1 + nu)(1 - 2 nu)).
// Eq. (61) prints rho0 cs^2 = Y / (1 + nu); Table 1 (cs = 71.9 m/s for the twisting column)
// and the Neo-Hookean energy (eq. 35, shear modulus rho0 cs^2) need the factor 2.
void speeds_from_moduli(const CaseFile& case_file, ElasticMaterial& material) {
  const double young = case_file.positive_number("material.young_modulus");
  const double poisson = case_file.number_or("material.poisson_ratio", -1.0);
  if (!(poisson > 0.0 && poisson < 0.5)) {
    case_file.fail("material.poisson_ratio", "required with young_modulus, between 0 and 0.5");
  }
  material.shear_speed = std::sqrt(young / (2.0 * (1.0 + poisson) * material.rest_density));
  material.sound_speed = std::sqrt(
      poisson * young / ((1.0 + poisson) * (1.0 - 2.0 * poisson) * material.rest_density));
}

void read_material(const CaseFile& case_file, ElasticMaterial& material) {
  material.rest_density = case_file.positive_number("material.rest_density");
  const bool from_moduli = case_file.has("material.young_modulus");
  if (from_moduli &&
      (case_file.has("material.sound_speed") || case_file.has("material.shear_speed"))) {
    case_file.fail("material.young_modulus",
                   "give either young_modulus and poisson_ratio or sound_speed and shear_speed");
  }
  if (from_moduli) {
    speeds_from_moduli(case_file, material);
  } else {
    material.sound_speed = case_file.positive_number("material.sound_speed");
    material.shear_speed = case_file.number_or("material.shear_speed", 0.0);
    if (!(material.shear_speed >= 0.0) || !std::isfinite(material.shear_speed)) {
      case_file.fail("material.shear_speed", "must be >= 0 and finite");
    }
  }
  const std::string energy = case_file.string_or("material.shear_energy", "dprz");
  if (energy == "dprz") {
    material.shear_energy = ShearEnergy::dprz;
  } else if (energy == "neo_hookean") {
    material.shear_energy = ShearEnergy::neo_hookean;
  } else {
    case_file.fail("material.shear_energy",
                   "expected \"dprz\" (eq. 31) or \"neo_hookean\" (eq. 35), got \"" + energy +
                       "\"");
  }
}

// tau from relaxation_time or from the kinematic viscosity (eqs. 65, 69); absent: elastic.
std::optional<double> read_relaxation_time(const CaseFile& case_file,
                                           const ElasticMaterial& material) {
  const bool has_tau = case_file.has("material.relaxation_time");
  const bool has_viscosity = case_file.has("material.kinematic_viscosity");
  if (has_tau && has_viscosity) {
    case_file.fail("material.relaxation_time",
                   "give either relaxation_time or kinematic_viscosity, not both");
  }
  if (!has_tau && !has_viscosity) {
    return std::nullopt;
  }
  if (!(material.shear_speed > 0.0)) {
    case_file.fail(has_tau ? "material.relaxation_time" : "material.kinematic_viscosity",
                   "relaxation needs a shear energy: shear_speed must be > 0");
  }
  const double tau = has_tau ? case_file.positive_number("material.relaxation_time")
                             : 6.0 * case_file.positive_number("material.kinematic_viscosity") /
                                   (material.shear_speed * material.shear_speed);
  require_positive_finite(case_file,
                          has_tau ? "material.relaxation_time" : "material.kinematic_viscosity",
                          "the relaxation time tau", tau);
  return tau;
}

template <int D>
void read_initial_field(const CaseFile& case_file, Parameters<D>& p) {
  const std::string field = case_file.string_or("initial.field", "rest");
  if (field == "rest") {
    p.initial_field = InitialField::rest;
  } else if (field == "bending_plate") {
    if (D != 2) {
      case_file.fail("initial.field", "the bending plate (eq. 55) is two-dimensional");
    }
    p.initial_field = InitialField::bending_plate;
    p.plate.amplitude = case_file.positive_number("initial.amplitude");
    p.plate.omega = case_file.positive_number("initial.omega");
    p.plate.alpha = case_file.positive_number("initial.alpha");
    p.plate.a1 = case_file.number_or("initial.a1", 0.0);
    p.plate.a2 = case_file.number_or("initial.a2", 0.0);
    p.plate.x0 = case_file.number_or("initial.x0", 0.0);
  } else if (field == "twisting_column") {
    if (D != 3) {
      case_file.fail("initial.field", "the twisting column (eq. 60) is three-dimensional");
    }
    p.initial_field = InitialField::twisting_column;
    p.column.omega = case_file.number_or("initial.omega", 0.0);
    p.column.height = case_file.positive_number("initial.height");
  } else {
    case_file.fail("initial.field",
                   "expected \"rest\", \"bending_plate\" or \"twisting_column\", got \"" + field +
                       "\"");
  }
}

} // namespace

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  Parameters<D> p;
  read_material(case_file, p.material);
  p.relaxation_time = read_relaxation_time(case_file, p.material);
  p.penalty_speed = case_file.number_or("penalty.speed", 0.0);
  if (!(p.penalty_speed >= 0.0) || !std::isfinite(p.penalty_speed)) {
    case_file.fail("penalty.speed", "must be >= 0 and finite (0: no tensile penalty)");
  }

  p.dr = case_file.positive_number("discretisation.dr");
  p.smoothing_length = p.dr * case_file.positive_number("discretisation.smoothing_length_over_dr");
  require_positive_finite(case_file, "discretisation.smoothing_length_over_dr",
                          "the smoothing length h = dr * smoothing_length_over_dr",
                          p.smoothing_length);
  const bool has_factor = case_file.has("discretisation.time_step_factor");
  const bool has_dt = case_file.has("discretisation.dt");
  if (has_factor == has_dt) {
    case_file.fail("discretisation.dt",
                   has_dt ? "give either dt or time_step_factor, not both"
                          : "missing required key (or give discretisation.time_step_factor, "
                            "dt = time_step_factor * dr / sqrt(c0^2 + 4/3 cs^2), eq. 58)");
  }
  const double wave_speed = std::sqrt(p.material.sound_speed * p.material.sound_speed +
                                      4.0 / 3.0 * p.material.shear_speed * p.material.shear_speed);
  p.dt = has_dt ? case_file.positive_number("discretisation.dt")
                : case_file.positive_number("discretisation.time_step_factor") * p.dr / wave_speed;
  require_positive_finite(case_file,
                          has_dt ? "discretisation.dt" : "discretisation.time_step_factor",
                          "the time step dt", p.dt);
  p.cell_size_factor = case_file.number_or("discretisation.cell_size_factor", 1.0);
  if (!(p.cell_size_factor >= 1.0 && p.cell_size_factor <= 100.0)) {
    case_file.fail("discretisation.cell_size_factor", "must be between 1 and 100");
  }

  const std::string update = case_file.string_or("discretisation.distortion_update", "exact");
  if (update != "exact" && update != "cayley") {
    case_file.fail("discretisation.distortion_update",
                   "expected \"exact\" (exactly invertible, the default) or \"cayley\" (the "
                   "paper's eq. 49, not bit-reversible), got \"" +
                       update + "\"");
  }
  p.cayley_distortion_update = update == "cayley";

  const std::string splitting = case_file.string_or("material.relaxation_splitting", "paper");
  if (splitting != "paper" && splitting != "matched" && splitting != "step_ends") {
    case_file.fail("material.relaxation_splitting",
                   "expected \"paper\" (eq. 52), \"matched\" or \"step_ends\", got \"" + splitting +
                       "\"");
  }
  if (p.relaxation_time) {
    const double tau = *p.relaxation_time;
    if (splitting == "paper") {
      p.relaxation_splitting = paper_splitting(tau);
    } else if (splitting == "matched") {
      p.relaxation_splitting = matched_splitting(tau, p.dt);
    } else if (const auto at_ends = step_ends_splitting(tau, p.dt)) {
      p.relaxation_splitting = *at_ends;
    } else {
      case_file.fail("material.relaxation_splitting",
                     "\"step_ends\" needs dt / tau < 1/3 (here " + std::to_string(p.dt / tau) +
                         "): use a smaller time step or \"matched\"");
    }
  } else if (case_file.has("material.relaxation_splitting")) {
    case_file.fail(
        "material.relaxation_splitting",
        "needs relaxation_time or kinematic_viscosity (an elastic solid does not relax)");
  }

  read_initial_field<D>(case_file, p);
  p.ramp_time = case_file.number_or("walls.ramp_time", 0.0);
  if (!(p.ramp_time >= 0.0) || !std::isfinite(p.ramp_time)) {
    case_file.fail("walls.ramp_time",
                   "must be >= 0 and finite (0: walls move at full speed at once)");
  }
  const std::string no_slip = case_file.string_or("walls.no_slip", "pretended");
  if (no_slip != "pretended" && no_slip != "mirrored") {
    case_file.fail("walls.no_slip", "expected \"pretended\" (the walls' own velocity in L, paper "
                                    "2) or \"mirrored\" (2 v_wall - the fluid's velocity), got \"" +
                                        no_slip + "\"");
  }
  p.mirrored_walls = no_slip == "mirrored";
  if (case_file.has("probe.point")) {
    const std::vector<double> point = case_file.numbers("probe.point", D);
    Vec<D> probe{};
    std::copy(point.begin(), point.end(), probe.begin());
    p.probe = probe;
  }
  p.domain = read_domain<D>(case_file);

  // Default scales: positions keep 52 fraction bits below the domain size (their double view is
  // exact); velocities resolve c0 * 2^-50 and reach 2^13 c0; the constants resolve rho0 * 2^-48;
  // the dissipated energy per mass c0^2 2^-48; log det A resolves 2^-50 and U 2^-48 (|U| < 2^15).
  p.position_scale = position_scale_or(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.velocity_scale =
      scale_or(case_file, "fixed_point.velocity_exponent", p.material.sound_speed, 50);
  p.density_scale =
      scale_or(case_file, "fixed_point.density_exponent", p.material.rest_density, 48);
  p.dissipated_scale = scale_or(case_file, "fixed_point.dissipated_exponent",
                                p.material.sound_speed * p.material.sound_speed, 48);
  p.distortion_scales.log_det = scale_or(case_file, "fixed_point.log_det_exponent", 1.0, 50);
  p.distortion_scales.unimodular = scale_or(case_file, "fixed_point.unimodular_exponent", 1.0, 48);
  // The walls' clock resolves dt 2^-28 and runs 2^34 steps.
  p.drive_time_scale =
      scale_or(case_file, "fixed_point.drive_time_exponent", std::ldexp(p.dt, 24), 52);
  return p;
}

namespace {

std::vector<KeyDecl> material_keys() {
  using T = KeyType;
  return {
      {"material.rest_density", T::number, "kg/m^3", "required", "rest density rho0; > 0"},
      {"material.sound_speed", T::number, "m/s", "required (or young_modulus)",
       "bulk sound speed c0 (eq. 29); > 0"},
      {"material.shear_speed", T::number, "m/s", "0 (or from young_modulus)",
       "shear sound speed cs (eqs. 31, 35); >= 0"},
      {"material.young_modulus", T::number, "Pa", "none (or sound_speed, shear_speed)",
       "Young's modulus Y: c0 and cs from Y and poisson_ratio (eq. 61, with the factor 2 of the "
       "shear modulus)"},
      {"material.poisson_ratio", T::number, "1", "required with young_modulus",
       "Poisson's ratio nu, between 0 and 0.5"},
      {"material.shear_energy",
       T::string,
       "-",
       "\"dprz\"",
       "the shear energy: eq. (31) or the Neo-Hookean eq. (35)",
       {"dprz", "neo_hookean"}},
      {"material.relaxation_time", T::number, "s", "none: an elastic solid",
       "relaxation time tau of the distortion (eqs. 51-53); not with kinematic_viscosity"},
      {"material.kinematic_viscosity", T::number, "m^2/s", "none: an elastic solid",
       "a fluid of viscosity nu: tau = 6 nu / cs^2 (eqs. 65, 69); not with relaxation_time"},
      {"material.relaxation_splitting",
       T::string,
       "-",
       "\"paper\"",
       "how the relaxation is split from the reversible step (models/shtc/README.md): eq. (52), "
       "nu kept at any dt / tau, or RK4 at the step's ends (dt / tau < 1/3); only with "
       "relaxation",
       {"paper", "matched", "step_ends"}},
  };
}

std::vector<KeyDecl> initial_keys() {
  using T = KeyType;
  return {
      {"initial.field",
       T::string,
       "-",
       "\"rest\"",
       "initial velocity: at rest, the bending plate (eq. 55, 2D) or the twisting column "
       "(eq. 60, 3D)",
       {"rest", "bending_plate", "twisting_column"}},
      {"initial.amplitude", T::number, "m", "required for bending_plate", "A of eq. (55); > 0"},
      {"initial.omega", T::number, "1/s", "required for bending_plate; 0 for twisting_column",
       "omega of eq. (55) (> 0) or eq. (60)"},
      {"initial.alpha", T::number, "1/m", "required for bending_plate", "alpha of eq. (55); > 0"},
      {"initial.a1", T::number, "1", "0", "a1 of eq. (55)"},
      {"initial.a2", T::number, "1", "0", "a2 of eq. (55)"},
      {"initial.x0", T::number, "m", "0", "left end of the plate: s = alpha (x - x0) in eq. (55)"},
      {"initial.height", T::number, "m", "required for twisting_column",
       "the column's height H in eq. (60); > 0"},
  };
}

std::vector<KeyDecl> fixed_point_keys() {
  using T = KeyType;
  return {
      {"fixed_point.position_exponent", T::integer, "-", "covers the domain with 52 fraction bits",
       "positions are stored as integers times 2^exponent"},
      {"fixed_point.velocity_exponent", T::integer, "-", "covers c0 with 50 fraction bits",
       "velocities are stored as integers times 2^exponent"},
      {"fixed_point.density_exponent", T::integer, "-", "covers rho0 with 48 fraction bits",
       "scale of the constants C_rho and C_lambda"},
      {"fixed_point.dissipated_exponent", T::integer, "-", "covers c0^2 with 48 fraction bits",
       "scale of the energy per mass removed by the relaxation"},
      {"fixed_point.log_det_exponent", T::integer, "-", "covers 1 with 50 fraction bits",
       "scale of log det A, the volumetric part of the distortion"},
      {"fixed_point.unimodular_exponent", T::integer, "-", "covers 1 with 48 fraction bits",
       "scale of U, the unimodular part of the distortion"},
      {"fixed_point.drive_time_exponent", T::integer, "-", "resolves dt 2^-28",
       "scale of the moving walls' clock"},
  };
}

} // namespace

const KeyTable& case_keys() {
  static const KeyTable table = [] {
    using T = KeyType;
    KeyTable t("shtc");
    t.add({"dimension", T::integer, "-", "required", "2 or 3"});
    t.add(material_keys());
    t.add({"penalty.speed", T::number, "m/s", "0",
           "cp of the tensile penalty (eqs. 39-42); >= 0 (0: off)"});
    t.add({"discretisation.dr", T::number, "m", "required",
           "particle spacing: each particle stands for dr^D; > 0"});
    t.add({"discretisation.smoothing_length_over_dr", T::number, "1", "required",
           "h / dr; the kernel's support is 2 h (eq. 2)"});
    t.add({"discretisation.dt", T::number, "s", "required (or time_step_factor)",
           "time step; give dt or time_step_factor, not both"});
    t.add({"discretisation.time_step_factor", T::number, "1", "none (or dt)",
           "dt = factor dr / sqrt(c0^2 + 4/3 cs^2) (eq. 58)"});
    t.add({"discretisation.cell_size_factor", T::number, "1", "1",
           "neighbour-search cell size over the support, 1 to 100 (results do not depend on it)"});
    t.add({"discretisation.distortion_update",
           T::string,
           "-",
           "\"exact\"",
           "\"exact\": the exactly invertible update (bitwise reversible); \"cayley\": the "
           "paper's eq. (49) in doubles, for comparison (not reversible)",
           {"exact", "cayley"}});
    t.add(initial_keys());
    t.add({"walls.ramp_time", T::number, "s", "0",
           "moving walls reach full speed as sin^2(pi t / (2 ramp_time)); 0: at once"});
    t.add({"walls.no_slip",
           T::string,
           "-",
           "\"pretended\"",
           "\"pretended\": walls pretend their own velocity in L (the paper's); \"mirrored\": "
           "2 v_wall minus the fluid's velocity around them (beyond the paper)",
           {"pretended", "mirrored"}});
    t.add({"probe.point", T::numbers, "m", "none",
           "diagnostics.csv follows the material particle nearest to this point at t = 0"});
    t.add(domain_case_keys());
    t.add(particle_block_case_keys({"material", "boundary"}));
    t.add({"particles[].velocity", T::numbers, "m/s", "none: at rest",
           "a boundary block's velocity at full drive (a translating wall, the cavity's lid)"});
    t.add({"particles[].angular_velocity", T::number, "rad/s", "none: at rest",
           "a boundary block rotating rigidly, counterclockwise about rotation_centre (3D: about "
           "the z axis through it); not with velocity"});
    t.add({"particles[].rotation_centre", T::numbers, "m", "the origin",
           "centre of a rotating wall (2 numbers); needs angular_velocity"});
    t.add(fixed_point_keys());
    return t;
  }();
  return table;
}

template <int D>
double Parameters<D>::drive_ramp(double t) const {
  if (!(t < ramp_time)) {
    return 1.0;
  }
  const double s = std::sin(0.5 * std::numbers::pi * t / ramp_time);
  return s * s;
}

template struct Parameters<2>;
template struct Parameters<3>;

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::shtc
