#include "models/superfluid/parameters.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "models/superfluid/case_keys.hpp" // generated from keys.toml

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>
#include <sstream>

namespace revsph::superfluid {

namespace {

Helium read_helium(const CaseFile& case_file) {
  const Keys& k = keys();
  Helium he;
  he.rest_density = k.rest_density.read(case_file);
  he.first_sound_speed = k.first_sound_speed.read(case_file);
  he.reference_temperature = k.reference_temperature.read(case_file);
  he.reference_entropy = k.reference_entropy.read(case_file);
  he.normal_fraction = k.normal_fraction.read(case_file);
  he.normal_fraction_slope = k.normal_fraction_slope.read(case_file);
  // Eq. (14) ties C to u2: a case gives one of them.
  const bool has_capacity = case_file.has(k.heat_capacity.path());
  const bool has_speed = case_file.has(k.second_sound_speed.path());
  if (has_capacity == has_speed) {
    case_file.fail(has_capacity ? k.second_sound_speed.path() : k.heat_capacity.path(),
                   "give exactly one of heat_capacity and second_sound_speed (eq. 14 relates "
                   "them)");
  }
  if (has_capacity) {
    he.heat_capacity = k.heat_capacity.require(case_file);
  } else {
    const double u2 = k.second_sound_speed.require(case_file);
    if (he.normal_fraction >= 1.0) {
      case_file.fail(k.second_sound_speed.path(),
                     "no second sound without a superfluid fraction (normal_fraction = 1): give "
                     "heat_capacity");
    }
    he.heat_capacity = (1.0 - he.normal_fraction) * he.reference_temperature *
                       he.reference_entropy * he.reference_entropy / (he.normal_fraction * u2 * u2);
    require_positive_finite(case_file, k.second_sound_speed.path().c_str(), "the heat capacity C",
                            he.heat_capacity);
  }
  return he;
}

InitialFields read_initial(const CaseFile& case_file, int dimension) {
  const Keys& k = keys();
  InitialFields f;
  for (const auto& [key, target] : {std::pair{&k.uniform_velocity, &f.uniform_velocity},
                                    std::pair{&k.uniform_counterflow, &f.uniform_counterflow}}) {
    if (case_file.has(*key)) {
      *target = case_file.numbers(*key, static_cast<std::size_t>(dimension));
      for (const double value : *target) {
        if (!std::isfinite(value)) {
          case_file.fail(*key, "must be finite");
        }
      }
    }
  }
  f.wave_amplitude = k.wave_amplitude.read(case_file);
  if (f.wave_amplitude != 0.0) {
    f.wave_length = k.wave_length.require(case_file);
  }
  f.wave_cosine = k.wave_cosine.read(case_file);
  f.random_velocity = k.random_velocity.read(case_file);
  f.random_counterflow = k.random_counterflow.read(case_file);
  f.random_entropy = k.random_entropy.read(case_file);
  f.hydrostatic_surface =
      k.hydrostatic_surface.read_optional(case_file).value_or(f.hydrostatic_surface);
  f.seed = static_cast<std::uint64_t>(k.seed.read(case_file));
  return f;
}

template <int D>
Vec<D> read_point(const CaseFile& case_file, const std::string& key, const Box<D>& domain) {
  const std::vector<double> given = case_file.numbers(key, D);
  Vec<D> point{};
  for (int k = 0; k < D; ++k) {
    point[k] = given[k];
    if (!(given[k] >= domain.min[k] && given[k] <= domain.max[k])) {
      case_file.fail(key, "lies outside the domain ([domain] min, max)");
    }
  }
  return point;
}

template <int D>
Superleak<D> read_superleak(const CaseFile& case_file, const Box<D>& domain) {
  const Keys& k = keys();
  Superleak<D> s;
  s.rate = k.superleak_rate.read(case_file);
  if (s.rate == 0.0) {
    return s;
  }
  s.centre = read_point<D>(case_file, k.superleak_centre, domain);
  s.half_width = k.superleak_half_width.require(case_file);
  s.half_thickness = k.superleak_half_thickness.require(case_file);
  for (int axis = 0; axis < D; ++axis) {
    const double half = axis == D - 1 ? s.half_thickness : s.half_width;
    if (s.centre[axis] - half < domain.min[axis] || s.centre[axis] + half > domain.max[axis]) {
      case_file.fail(axis == D - 1 ? k.superleak_half_thickness.path()
                                   : k.superleak_half_width.path(),
                     "the superleak reaches outside the domain ([domain] min, max)");
    }
  }
  return s;
}

template <int D>
Heater<D> read_heater(const CaseFile& case_file, const Box<D>& domain) {
  const Keys& k = keys();
  Heater<D> h;
  h.power = k.heater_power.read(case_file);
  if (h.power == 0.0) {
    return h;
  }
  h.centre = read_point<D>(case_file, k.heater_centre, domain);
  h.support = k.heater_support.require(case_file);
  h.ramp_time = k.heater_ramp_time.read(case_file);
  return h;
}

} // namespace

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  const Keys& k = keys();
  Parameters<D> p = k.read_fields<Parameters<D>>(case_file);
  p.helium = read_helium(case_file);
  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.helium.first_sound_speed);
  static_cast<ParticleDiscretisation&>(p) = discretisation;
  p.initial = read_initial(case_file, D);
  p.domain = read_domain<D>(case_file);
  p.superleak = read_superleak<D>(case_file, p.domain);
  p.jet_height = k.jet_height.read_optional(case_file).value_or(p.jet_height);
  p.heater = read_heater<D>(case_file, p.domain);

  const Helium& he = p.helium;
  p.position_scale = k.position_exponent.read(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.velocity_scale = k.velocity_exponent.read(case_file, he.first_sound_speed);
  p.entropy_scale = k.entropy_exponent.read(case_file, he.reference_entropy);
  p.density_scale = k.density_exponent.read(case_file, he.rest_density);
  p.heat_scale =
      k.heat_exponent.read(case_file, he.rest_density * dmath::integer_power(p.dr, D) *
                                          he.reference_temperature * he.reference_entropy);
  return p;
}

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::superfluid
