#include "models/shtc/parameters.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "models/shtc/case_keys.hpp" // generated from keys.toml

#include "core/case_key.hpp"
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
  Parameters<D> p = k.read_fields<Parameters<D>>(case_file);
  read_material(case_file, p.material);
  p.relaxation_time = read_relaxation_time(case_file, p.material);

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

  const RelaxationRate rate = k.relaxation_rate.read(case_file);
  if (p.relaxation_time) {
    p.relaxation_splitting = relaxation_splitting(case_file, k, rate, p);
  } else if (case_file.has(k.relaxation_rate.path())) {
    case_file.fail(
        k.relaxation_rate.path(),
        "needs relaxation_time or kinematic_viscosity (an elastic solid does not relax)");
  }

  read_initial_field<D>(case_file, p);
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

template <int D>
double Parameters<D>::drive_ramp(double t) const {
  if (!(t < ramp_time)) {
    return 1.0;
  }
  const double s = dmath::sin(0.5 * std::numbers::pi * t / ramp_time);
  return s * s;
}

template struct Parameters<2>;
template struct Parameters<3>;

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::shtc
