#include "models/shtc/parameters.hpp"

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"

#include <cmath>
#include <numbers>

namespace revsph::shtc {

namespace {

enum class RelaxationRate { paper, matched };

// Every key of an SHTC case file beyond common_case_keys(), including those setup.cpp reads, in
// the reference's order.
struct Keys : KeySet {
  Keys() : KeySet("shtc") {}
  const std::string dimension = declare({"dimension", KeyType::integer, "-", "required", "2 or 3"});
  const Key<double> rest_density = number("material.rest_density", "kg/m^3", "required",
                                          "rest density rho0; > 0", positive_or_why);
  const Key<double> sound_speed =
      number("material.sound_speed", "m/s", "required (or young_modulus)",
             "bulk sound speed c0 (eq. 29); > 0", positive_or_why);
  const Key<double> shear_speed =
      number("material.shear_speed", "m/s", "0 (or from young_modulus)",
             "shear sound speed cs (eqs. 31, 35); >= 0",
             must<double>([](double cs) { return cs >= 0.0 && std::isfinite(cs); },
                          "must be >= 0 and finite"));
  const Key<double> young_modulus =
      number("material.young_modulus", "Pa", "none (or sound_speed, shear_speed)",
             "Young's modulus Y: c0 and cs from Y and poisson_ratio (eq. 61, with the factor 2 of "
             "the shear modulus)",
             positive_or_why);
  const Key<double> poisson_ratio =
      number("material.poisson_ratio", "1", "required with young_modulus",
             "Poisson's ratio nu, between 0 and 0.5",
             must<double>([](double nu) { return nu > 0.0 && nu < 0.5; },
                          "required with young_modulus, between 0 and 0.5"));
  const Choice<ShearEnergy> shear_energy = choice<ShearEnergy>(
      "material.shear_energy", "\"dprz\"", "the shear energy: eq. (31) or the Neo-Hookean eq. (35)",
      {{"dprz", ShearEnergy::dprz}, {"neo_hookean", ShearEnergy::neo_hookean}});
  const Key<double> relaxation_time =
      number("material.relaxation_time", "s", "none: an elastic solid",
             "relaxation time tau of the distortion (eqs. 51-53); not with kinematic_viscosity",
             positive_or_why);
  const Key<double> kinematic_viscosity =
      number("material.kinematic_viscosity", "m^2/s", "none: an elastic solid",
             "a fluid of viscosity nu: tau = 6 nu / cs^2 (eqs. 65, 69); not with relaxation_time",
             positive_or_why);
  const Choice<RelaxationRate> relaxation_rate = choice<RelaxationRate>(
      "material.relaxation_rate", "\"paper\"",
      "the rate of the RK4 relaxation (models/shtc/README.md): \"paper\", eq. (53)'s tau; "
      "\"matched\", the rate that keeps nu at any dt / tau for the case's step.splitting "
      "(strang and midpoint: dt / tau < 1/3); only with relaxation",
      {{"paper", RelaxationRate::paper}, {"matched", RelaxationRate::matched}});
  const Choice<Splitting> splitting = KeySet::splitting("after_centre");
  const Key<double> penalty_speed =
      number("penalty.speed", "m/s", "0", "cp of the tensile penalty (eqs. 39-42); >= 0 (0: off)",
             must<double>([](double cp) { return cp >= 0.0 && std::isfinite(cp); },
                          "must be >= 0 and finite (0: no tensile penalty)"));
  const Key<double> dr =
      number("discretisation.dr", "m", "required",
             "particle spacing: each particle stands for dr^D; > 0", positive_or_why);
  const Key<double> smoothing_length_over_dr =
      number("discretisation.smoothing_length_over_dr", "1", "required",
             "h / dr; the kernel's support is 2 h (eq. 2)", positive_or_why);
  const Key<double> dt =
      number("discretisation.dt", "s", "required (or time_step_factor)",
             "time step; give dt or time_step_factor, not both", positive_or_why);
  const Key<double> time_step_factor =
      number("discretisation.time_step_factor", "1", "none (or dt)",
             "dt = factor dr / sqrt(c0^2 + 4/3 cs^2) (eq. 58)", positive_or_why);
  const Key<double> cell_size_factor = number(
      "discretisation.cell_size_factor", "1", "1",
      "neighbour-search cell size over the support, 1 to 100 (results do not depend on it)",
      must<double>([](double f) { return f >= 1.0 && f <= 100.0; }, "must be between 1 and 100"));
  const Choice<bool> cayley_distortion_update =
      choice<bool>("discretisation.distortion_update", "\"exact\"",
                   "\"exact\": the exactly invertible update (bitwise reversible); \"cayley\": the "
                   "paper's eq. (49) in doubles, for comparison (not reversible)",
                   {{"exact", false}, {"cayley", true}});
  const Choice<InitialField> initial_field = choice<InitialField>(
      "initial.field", "\"rest\"",
      "initial velocity: at rest, the bending plate (eq. 55, 2D) or the twisting column "
      "(eq. 60, 3D)",
      {{"rest", InitialField::rest},
       {"bending_plate", InitialField::bending_plate},
       {"twisting_column", InitialField::twisting_column}});
  const Key<double> amplitude = number("initial.amplitude", "m", "required for bending_plate",
                                       "A of eq. (55); > 0", positive_or_why);
  const Key<double> omega =
      number("initial.omega", "1/s", "required for bending_plate; 0 for twisting_column",
             "omega of eq. (55) (> 0) or eq. (60)");
  const Key<double> alpha = number("initial.alpha", "1/m", "required for bending_plate",
                                   "alpha of eq. (55); > 0", positive_or_why);
  const Key<double> a1 = number("initial.a1", "1", "0", "a1 of eq. (55)");
  const Key<double> a2 = number("initial.a2", "1", "0", "a2 of eq. (55)");
  const Key<double> x0 =
      number("initial.x0", "m", "0", "left end of the plate: s = alpha (x - x0) in eq. (55)");
  const Key<double> height = number("initial.height", "m", "required for twisting_column",
                                    "the column's height H in eq. (60); > 0", positive_or_why);
  const Key<double> ramp_time =
      number("walls.ramp_time", "s", "0",
             "moving walls reach full speed as sin^2(pi t / (2 ramp_time)); 0: at once",
             must<double>([](double t) { return t >= 0.0 && std::isfinite(t); },
                          "must be >= 0 and finite (0: walls move at full speed at once)"));
  const Choice<bool> mirrored_walls = choice<bool>(
      "walls.no_slip", "\"pretended\"",
      "\"pretended\": walls pretend their own velocity in L (the paper's); \"mirrored\": "
      "2 v_wall minus the fluid's velocity around them (beyond the paper)",
      {{"pretended", false}, {"mirrored", true}});
  const std::string probe_point =
      declare({"probe.point", KeyType::numbers, "m", "none",
               "diagnostics.csv follows the material particle nearest to this point at t = 0"});
  const int regions =
      (declare(domain_case_keys()), declare(particle_block_case_keys({"material", "boundary"})),
       declare({"particles[].velocity", KeyType::numbers, "m/s", "none: at rest",
                "a boundary block's velocity at full drive (a translating wall, the cavity's "
                "lid)"}),
       declare({"particles[].angular_velocity", KeyType::number, "rad/s", "none: at rest",
                "a boundary block rotating rigidly, counterclockwise about rotation_centre (3D: "
                "about the z axis through it); not with velocity"}),
       declare({"particles[].rotation_centre", KeyType::numbers, "m", "the origin",
                "centre of a rotating wall (2 numbers); needs angular_velocity"}),
       0);
  // Default scales: positions keep 52 fraction bits below the domain size (their double view
  // is exact); velocities resolve c0 * 2^-50 and reach 2^13 c0; the constants resolve
  // rho0 * 2^-48; the dissipated energy per mass c0^2 2^-48; log det A resolves 2^-50 and U
  // 2^-48 (|U| < 2^15); the walls' clock resolves dt 2^-28 and runs 2^34 steps.
  const PositionScaleKey position_exponent = position_scale();
  const ScaleKey velocity_exponent =
      scale("velocity", "c0", 50, "velocities are stored as integers times 2^exponent");
  const ScaleKey density_exponent =
      scale("density", "rho0", 48, "scale of the constants C_rho and C_lambda");
  const ScaleKey dissipated_exponent =
      scale("dissipated", "c0^2", 48, "scale of the energy per mass removed by the relaxation");
  const ScaleKey log_det_exponent =
      scale("log_det", "1", 50, "scale of log det A, the volumetric part of the distortion");
  const ScaleKey unimodular_exponent =
      scale("unimodular", "1", 48, "scale of U, the unimodular part of the distortion");
  const ScaleKey drive_time_exponent{
      declare({"fixed_point.drive_time_exponent", KeyType::integer, "-", "resolves dt 2^-28",
               "scale of the moving walls' clock"}),
      52};
};

const Keys& keys() {
  static const Keys declared;
  return declared;
}

// Sound speeds from Young's modulus and Poisson's ratio (paper 2 eq. 61, corrected):
// rho0 cs^2 = Y / (2 (1 + nu)), the shear modulus, and rho0 c0^2 = nu Y / ((1 + nu)(1 - 2 nu)).
// Eq. (61) prints rho0 cs^2 = Y / (1 + nu); Table 1 (cs = 71.9 m/s for the twisting column)
// and the Neo-Hookean energy (eq. 35, shear modulus rho0 cs^2) need the factor 2.
void speeds_from_moduli(const CaseFile& case_file, ElasticMaterial& material) {
  const Keys& k = keys();
  const double young = k.young_modulus.require(case_file);
  const double poisson = k.poisson_ratio.read_or(case_file, -1.0);
  material.shear_speed = std::sqrt(young / (2.0 * (1.0 + poisson) * material.rest_density));
  material.sound_speed = std::sqrt(
      poisson * young / ((1.0 + poisson) * (1.0 - 2.0 * poisson) * material.rest_density));
}

void read_material(const CaseFile& case_file, ElasticMaterial& material) {
  const Keys& k = keys();
  material.rest_density = k.rest_density.read(case_file);
  const bool from_moduli = case_file.has(k.young_modulus.path());
  if (from_moduli && (case_file.has(k.sound_speed.path()) || case_file.has(k.shear_speed.path()))) {
    case_file.fail(k.young_modulus.path(),
                   "give either young_modulus and poisson_ratio or sound_speed and shear_speed");
  }
  if (from_moduli) {
    speeds_from_moduli(case_file, material);
  } else {
    material.sound_speed = k.sound_speed.require(case_file);
    material.shear_speed = k.shear_speed.read_or(case_file, 0.0);
  }
  material.shear_energy = k.shear_energy.read(case_file);
}

// tau from relaxation_time or from the kinematic viscosity (eqs. 65, 69); absent: elastic.
std::optional<double> read_relaxation_time(const CaseFile& case_file,
                                           const ElasticMaterial& material) {
  const Keys& k = keys();
  const bool has_tau = case_file.has(k.relaxation_time.path());
  const bool has_viscosity = case_file.has(k.kinematic_viscosity.path());
  if (has_tau && has_viscosity) {
    case_file.fail(k.relaxation_time.path(),
                   "give either relaxation_time or kinematic_viscosity, not both");
  }
  if (!has_tau && !has_viscosity) {
    return std::nullopt;
  }
  const Key<double>& given = has_tau ? k.relaxation_time : k.kinematic_viscosity;
  if (!(material.shear_speed > 0.0)) {
    case_file.fail(given.path(), "relaxation needs a shear energy: shear_speed must be > 0");
  }
  const double tau = has_tau ? k.relaxation_time.require(case_file)
                             : 6.0 * k.kinematic_viscosity.require(case_file) /
                                   (material.shear_speed * material.shear_speed);
  require_positive_finite(case_file, given.path().c_str(), "the relaxation time tau", tau);
  return tau;
}

template <int D>
void read_initial_field(const CaseFile& case_file, Parameters<D>& p) {
  const Keys& k = keys();
  p.initial_field = k.initial_field.read(case_file);
  if (p.initial_field == InitialField::bending_plate) {
    if (D != 2) {
      case_file.fail(k.initial_field.path(), "the bending plate (eq. 55) is two-dimensional");
    }
    p.plate.amplitude = k.amplitude.require(case_file);
    p.plate.omega = k.omega.require(case_file);
    if (const std::string why = positive_or_why(p.plate.omega); !why.empty()) {
      case_file.fail(k.omega.path(), why);
    }
    p.plate.alpha = k.alpha.require(case_file);
    p.plate.a1 = k.a1.read(case_file);
    p.plate.a2 = k.a2.read(case_file);
    p.plate.x0 = k.x0.read(case_file);
  } else if (p.initial_field == InitialField::twisting_column) {
    if (D != 3) {
      case_file.fail(k.initial_field.path(), "the twisting column (eq. 60) is three-dimensional");
    }
    p.column.omega = k.omega.read_or(case_file, 0.0);
    p.column.height = k.height.require(case_file);
  }
}

// The relaxation's RK4 rate for where step.splitting puts it (relaxation.hpp): the paper's tau
// anywhere; matched, the rate that keeps nu for that placement.
template <int D>
RelaxationSplitting relaxation_splitting(const CaseFile& case_file, const Keys& k,
                                         RelaxationRate rate, const Parameters<D>& p) {
  const double tau = *p.relaxation_time;
  if (rate == RelaxationRate::paper) {
    return paper_splitting(tau);
  }
  if (p.splitting == Splitting::after_centre || p.splitting == Splitting::lie) {
    return matched_splitting(tau, p.dt);
  }
  const auto matched = p.splitting == Splitting::strang ? step_ends_splitting(tau, p.dt)
                                                        : midpoint_splitting(tau, p.dt);
  if (!matched) {
    case_file.fail(k.relaxation_rate.path(),
                   "\"matched\" with step.splitting \"strang\" or \"midpoint\" needs dt / tau "
                   "< 1/3 (here " +
                       std::to_string(p.dt / tau) +
                       "): use a smaller time step or step.splitting = \"after_centre\"");
  }
  return *matched;
}

} // namespace

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  const Keys& k = keys();
  Parameters<D> p;
  read_material(case_file, p.material);
  p.relaxation_time = read_relaxation_time(case_file, p.material);
  p.penalty_speed = k.penalty_speed.read(case_file);

  p.dr = k.dr.read(case_file);
  p.smoothing_length = p.dr * k.smoothing_length_over_dr.read(case_file);
  require_positive_finite(case_file, k.smoothing_length_over_dr.path().c_str(),
                          "the smoothing length h = dr * smoothing_length_over_dr",
                          p.smoothing_length);
  const bool has_factor = case_file.has(k.time_step_factor.path());
  const bool has_dt = case_file.has(k.dt.path());
  if (has_factor == has_dt) {
    case_file.fail(k.dt.path(),
                   has_dt ? "give either dt or time_step_factor, not both"
                          : "missing required key (or give discretisation.time_step_factor, "
                            "dt = time_step_factor * dr / sqrt(c0^2 + 4/3 cs^2), eq. 58)");
  }
  const double wave_speed = std::sqrt(p.material.sound_speed * p.material.sound_speed +
                                      4.0 / 3.0 * p.material.shear_speed * p.material.shear_speed);
  p.dt =
      has_dt ? k.dt.require(case_file) : k.time_step_factor.require(case_file) * p.dr / wave_speed;
  require_positive_finite(case_file, (has_dt ? k.dt : k.time_step_factor).path().c_str(),
                          "the time step dt", p.dt);
  p.cell_size_factor = k.cell_size_factor.read(case_file);
  p.cayley_distortion_update = k.cayley_distortion_update.read(case_file);

  p.splitting = k.splitting.read(case_file);
  const RelaxationRate rate = k.relaxation_rate.read(case_file);
  if (p.relaxation_time) {
    p.relaxation_splitting = relaxation_splitting(case_file, k, rate, p);
  } else if (case_file.has(k.relaxation_rate.path())) {
    case_file.fail(
        k.relaxation_rate.path(),
        "needs relaxation_time or kinematic_viscosity (an elastic solid does not relax)");
  }

  read_initial_field<D>(case_file, p);
  p.ramp_time = k.ramp_time.read(case_file);
  p.mirrored_walls = k.mirrored_walls.read(case_file);
  if (case_file.has(k.probe_point)) {
    const std::vector<double> point = case_file.numbers(k.probe_point, D);
    Vec<D> probe{};
    std::copy(point.begin(), point.end(), probe.begin());
    p.probe = probe;
  }
  p.domain = read_domain<D>(case_file);

  p.position_scale = k.position_exponent.read(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.velocity_scale = k.velocity_exponent.read(case_file, p.material.sound_speed);
  p.density_scale = k.density_exponent.read(case_file, p.material.rest_density);
  p.dissipated_scale =
      k.dissipated_exponent.read(case_file, p.material.sound_speed * p.material.sound_speed);
  p.distortion_scales.log_det = k.log_det_exponent.read(case_file, 1.0);
  p.distortion_scales.unimodular = k.unimodular_exponent.read(case_file, 1.0);
  p.drive_time_scale = k.drive_time_exponent.read(case_file, std::ldexp(p.dt, 24));
  return p;
}

const KeyTable& case_keys() {
  return keys().table();
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
