#include "models/superfluid/parameters.hpp"

#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>
#include <sstream>

namespace revsph::superfluid {

namespace {

Helium read_helium(const CaseFile& case_file) {
  Helium he;
  he.rest_density = case_file.positive_number("physics.rest_density");
  he.first_sound_speed = case_file.positive_number("physics.first_sound_speed");
  he.reference_temperature = case_file.positive_number("physics.reference_temperature");
  he.reference_entropy = case_file.positive_number("physics.reference_entropy");
  he.normal_fraction = case_file.number("physics.normal_fraction");
  if (!(he.normal_fraction > 0.0 && he.normal_fraction <= 1.0)) {
    case_file.fail("physics.normal_fraction", "chi_n0 must be in (0, 1]");
  }
  he.normal_fraction_slope = case_file.number_or("physics.normal_fraction_slope", 0.0);
  // Eq. (14) ties C to u2: a case gives one of them.
  const bool has_capacity = case_file.has("physics.heat_capacity");
  const bool has_speed = case_file.has("physics.second_sound_speed");
  if (has_capacity == has_speed) {
    case_file.fail(has_capacity ? "physics.second_sound_speed" : "physics.heat_capacity",
                   "give exactly one of heat_capacity and second_sound_speed (eq. 14 relates "
                   "them)");
  }
  if (has_capacity) {
    he.heat_capacity = case_file.positive_number("physics.heat_capacity");
  } else {
    const double u2 = case_file.positive_number("physics.second_sound_speed");
    if (he.normal_fraction >= 1.0) {
      case_file.fail("physics.second_sound_speed",
                     "no second sound without a superfluid fraction (normal_fraction = 1): give "
                     "heat_capacity");
    }
    he.heat_capacity = (1.0 - he.normal_fraction) * he.reference_temperature *
                       he.reference_entropy * he.reference_entropy / (he.normal_fraction * u2 * u2);
    require_positive_finite(case_file, "physics.second_sound_speed", "the heat capacity C",
                            he.heat_capacity);
  }
  return he;
}

InitialFields read_initial(const CaseFile& case_file, int dimension) {
  InitialFields f;
  for (const auto& [key, target] :
       {std::pair{"initial.uniform_velocity", &f.uniform_velocity},
        std::pair{"initial.uniform_counterflow", &f.uniform_counterflow}}) {
    if (case_file.has(key)) {
      *target = case_file.numbers(key, static_cast<std::size_t>(dimension));
      for (const double value : *target) {
        if (!std::isfinite(value)) {
          case_file.fail(key, "must be finite");
        }
      }
    }
  }
  f.wave_amplitude = case_file.number_or("initial.entropy_wave_amplitude", 0.0);
  if (f.wave_amplitude != 0.0) {
    f.wave_length = case_file.positive_number("initial.entropy_wave_length");
  }
  const std::string shape = case_file.string_or("initial.entropy_wave_shape", "sine");
  if (shape != "sine" && shape != "cosine") {
    case_file.fail("initial.entropy_wave_shape",
                   "expected \"sine\" or \"cosine\", got \"" + shape + "\"");
  }
  f.wave_cosine = shape == "cosine";
  f.random_velocity = case_file.non_negative_number_or("initial.random_velocity", 0.0);
  f.random_counterflow = case_file.non_negative_number_or("initial.random_counterflow", 0.0);
  f.random_entropy = case_file.non_negative_number_or("initial.random_entropy", 0.0);
  if (case_file.has("initial.hydrostatic_surface")) {
    f.hydrostatic_surface = case_file.number("initial.hydrostatic_surface");
  }
  const std::int64_t seed = case_file.integer_or("initial.seed", 1);
  if (seed < 0) {
    case_file.fail("initial.seed", "must be >= 0");
  }
  f.seed = static_cast<std::uint64_t>(seed);
  return f;
}

template <int D>
Vec<D> read_point(const CaseFile& case_file, const char* key, const Box<D>& domain) {
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
  Superleak<D> s;
  s.rate = case_file.non_negative_number_or("superleak.rate", 0.0, "no superleak");
  if (s.rate == 0.0) {
    return s;
  }
  s.centre = read_point<D>(case_file, "superleak.centre", domain);
  s.half_width = case_file.positive_number("superleak.half_width");
  s.half_thickness = case_file.positive_number("superleak.half_thickness");
  for (int k = 0; k < D; ++k) {
    const double half = k == D - 1 ? s.half_thickness : s.half_width;
    if (s.centre[k] - half < domain.min[k] || s.centre[k] + half > domain.max[k]) {
      case_file.fail(k == D - 1 ? "superleak.half_thickness" : "superleak.half_width",
                     "the superleak reaches outside the domain ([domain] min, max)");
    }
  }
  return s;
}

template <int D>
Heater<D> read_heater(const CaseFile& case_file, const Box<D>& domain) {
  Heater<D> h;
  h.power = case_file.non_negative_number_or("heater.power", 0.0, "no heater");
  if (h.power == 0.0) {
    return h;
  }
  h.centre = read_point<D>(case_file, "heater.centre", domain);
  h.support = case_file.positive_number("heater.support");
  h.ramp_time = case_file.non_negative_number_or("heater.ramp_time", 0.0, "full power at once");
  return h;
}

} // namespace

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file) {
  Parameters<D> p;
  p.helium = read_helium(case_file);
  p.gravity = case_file.number_or("physics.gravity", 0.0);
  p.gravity_reference_height = case_file.number_or("physics.gravity_reference_height", 0.0);
  p.viscosity = case_file.non_negative_number_or("physics.viscosity", 0.0, "inviscid");
  p.heat_conductivity =
      case_file.non_negative_number_or("physics.heat_conductivity", 0.0, "no conduction");
  const std::string dummy_slip = case_file.string_or("physics.dummy_slip", "free");
  if (dummy_slip != "free" && dummy_slip != "no_slip") {
    case_file.fail("physics.dummy_slip",
                   "expected \"free\" or \"no_slip\", got \"" + dummy_slip + "\"");
  }
  p.dummy_no_slip = dummy_slip == "no_slip";
  const std::string cooler = case_file.string_or("physics.cooler", "conducting");
  if (cooler != "conducting" && cooler != "absorbing") {
    case_file.fail("physics.cooler",
                   "expected \"conducting\" or \"absorbing\", got \"" + cooler + "\"");
  }
  p.absorbing_walls = cooler == "absorbing";
  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.helium.first_sound_speed);
  p.dr = discretisation.dr;
  p.support_radius = discretisation.support_radius;
  p.dt = discretisation.dt;
  p.cell_size_factor = discretisation.cell_size_factor;
  p.initial = read_initial(case_file, D);
  p.domain = read_domain<D>(case_file);
  p.superleak = read_superleak<D>(case_file, p.domain);
  if (case_file.has("jet.height")) {
    p.jet_height = case_file.number("jet.height");
  }
  p.heater = read_heater<D>(case_file, p.domain);

  const Helium& he = p.helium;
  // Default scales: positions keep 52 fraction bits below the domain size; velocities resolve
  // u1 * 2^-50; entropies s0 * 2^-50 (room for 2^13 s0); density sums rho0 * 2^-48. The pair
  // increments of v, v_s and s are summed at the scales of v and s.
  p.position_scale = position_scale_or(case_file, p.domain.max_abs_coordinate(), p.dr);
  p.velocity_scale = scale_or(case_file, "fixed_point.velocity_exponent", he.first_sound_speed, 50);
  p.entropy_scale = scale_or(case_file, "fixed_point.entropy_exponent", he.reference_entropy, 50);
  p.density_scale = scale_or(case_file, "fixed_point.density_exponent", he.rest_density, 48);
  // The heat sums: a particle's thermal energy scale m T0 s0 (m = rho0 dr^D) with 60 bits.
  p.heat_scale = scale_or(
      case_file, "fixed_point.heat_exponent",
      he.rest_density * std::pow(p.dr, D) * he.reference_temperature * he.reference_entropy, 60);
  return p;
}

const KeyTable& case_keys() {
  static const KeyTable table = [] {
    using T = KeyType;
    KeyTable t("superfluid");
    t.add({"dimension", T::integer, "-", "required", "2 or 3"});
    t.add({"physics.rest_density", T::number, "kg/m^3", "required", "rho0 of eq. (12); > 0"});
    t.add({"physics.first_sound_speed", T::number, "m/s", "required",
           "u1 of eq. (12) (first sound); > 0"});
    t.add({"physics.reference_temperature", T::number, "K", "required", "T0 of eq. (13); > 0"});
    t.add({"physics.reference_entropy", T::number, "J/(kg K)", "required",
           "s0 of eqs. (8, 13); > 0"});
    t.add({"physics.gravity", T::number, "m/s^2", "0",
           "gravitational acceleration g (eq. 29) along minus the last axis, on v and v_s"});
    t.add({"physics.gravity_reference_height", T::number, "m", "0",
           "height of zero gravitational energy (shifts the reported energy only)"});
    t.add({"physics.viscosity", T::number, "Pa s", "0",
           "mu of the normal fluid (eq. 19, Monaghan's form B22, eta = h / 10); >= 0; "
           "irreversible"});
    t.add({"physics.heat_conductivity", T::number, "W/(m K)", "0",
           "beta of eq. (5) (B21, B23); >= 0; irreversible"});
    t.add({"physics.normal_fraction", T::number, "1", "required",
           "chi_n0 of eq. (8), in (0, 1] (1: a classical fluid)"});
    t.add({"physics.normal_fraction_slope", T::number, "kg K/J", "0", "chi' of eq. (8)"});
    t.add({"physics.heat_capacity", T::number, "J/(kg K)", "from second_sound_speed",
           "C of eq. (13); > 0; give this or second_sound_speed"});
    t.add({"physics.second_sound_speed", T::number, "m/s", "from heat_capacity",
           "u2 of eq. (14), which then gives C; > 0; give this or heat_capacity"});
    t.add({"physics.dummy_slip",
           T::string,
           "-",
           "\"free\"",
           "the normal fluid at dummy (adiabatic) walls: \"free\" (sec. III.C: dummies in the "
           "density and the pressure only) or \"no_slip\" (the viscosity also drags the normal "
           "fluid toward rest at them, as the authors' fountain code does; the heat stays in "
           "the fluid)",
           {"free", "no_slip"}});
    t.add({"physics.cooler",
           T::string,
           "-",
           "\"conducting\"",
           "what kind = \"wall\" particles are besides no-slip: \"conducting\" (they hold the "
           "fluid at T0 through the heat conduction only) or \"absorbing\" (the authors' "
           "fountain code: they keep s = s0 and v at their velocity but carry a free superflow "
           "velocity, and take part in the entropy flux and the thermomechanical force of eq. "
           "(19), so that second sound leaves through them; reversible, their exchange counted "
           "in wall_exchange)",
           {"conducting", "absorbing"}});
    t.add(particle_discretisation_case_keys(
        "kernel support radius in units of dr: Table I's h, the support as the authors' code uses "
        "it (h = 3 dr is 3; eq. 17 as printed, support 2h, would be 6)",
        "time step as a fraction of support / u1: dt = courant_number * support / u1 (the "
        "paper's dt = h / (M u1) is courant_number = 1 / M)"));
    t.add({"initial.entropy_wave_amplitude", T::number, "1", "0",
           "A of eq. (26): s = s0 (1 + A sin(pi x / L) sin(pi y / L)) [sin(pi z / L) in 3D]"});
    t.add({"initial.entropy_wave_shape",
           T::string,
           "-",
           "\"sine\"",
           "\"sine\": eq. (26) as printed, zero at the edges of the square [0, L]^D (eq. 25 "
           "assumes s = s0 there); \"cosine\": cos(pi x / L) cos(pi y / L), the standing mode "
           "of a square with adiabatic (free) edges",
           {"sine", "cosine"}});
    t.add({"initial.entropy_wave_length", T::number, "m", "required with an amplitude",
           "L of eq. (26); > 0"});
    t.add({"initial.uniform_velocity", T::numbers, "m/s", "zero",
           "coflow velocity v of every fluid particle (the random part adds to it)"});
    t.add({"initial.uniform_counterflow", T::numbers, "m/s", "zero",
           "v - v_s of every fluid particle (the random part adds to it)"});
    t.add({"initial.hydrostatic_surface", T::number, "m", "none (rho0 everywhere)",
           "height H of the free surface: the initial density is rho0 (1 + g (H - y) / u1^2), "
           "the pressure rho0 g (H - y) (eq. 12), for every particle"});
    t.add({"initial.random_velocity", T::number, "m/s", "0",
           "each component of v uniform in [-value, value]; >= 0"});
    t.add({"initial.random_counterflow", T::number, "m/s", "0",
           "each component of v - v_s uniform in [-value, value]; >= 0"});
    t.add({"initial.random_entropy", T::number, "1", "0",
           "s / s0 - 1 uniform in [-value, value] (added to the wave); >= 0"});
    t.add({"initial.seed", T::integer, "-", "1", "seed of the random fields; >= 0"});
    t.add({"superleak.rate", T::number, "1/s", "0",
           "friction rate of the superleak (eq. 30: its 1 / tau), applied exactly as v_n -> v_n "
           "exp(-rate dt) to the fluid in the slab; >= 0 (0: none); irreversible"});
    t.add({"superleak.centre", T::numbers, "m", "required with a rate",
           "centre of the superleak slab (inside the domain)"});
    t.add({"superleak.half_width", T::number, "m", "required with a rate",
           "half its extent along the axes but the last (r_sup of eq. 30); > 0"});
    t.add({"superleak.half_thickness", T::number, "m", "required with a rate",
           "half its extent along the last axis; > 0; no heat is conducted across its "
           "mid-plane"});
    t.add({"jet.height", T::number, "m", "none",
           "report the fluid volume (sum m / rho, per unit depth in 2D) above this height in "
           "diagnostics.csv as volume_above_jet_height: its rate over the capillary's width is "
           "the jet speed (sec. III.C)"});
    t.add({"heater.power", T::number, "W/m (2D), W (3D)", "0",
           "heater power W of eq. (30); >= 0 (0: none); irreversible, counted in the energy "
           "budget as heater_input"});
    t.add({"heater.centre", T::numbers, "m", "required with a power", "heater centre"});
    t.add({"heater.support", T::number, "m", "required with a power",
           "support radius of the Wendland kernel that spreads the power (2H of eq. 30); > 0"});
    t.add({"heater.ramp_time", T::number, "s", "0",
           "the power grows linearly from 0 over this time; >= 0"});
    t.add(domain_case_keys());
    t.add(particle_block_case_keys({"fluid", "dummy", "wall"}));
    t.add({"particles[].velocity", T::numbers, "m/s", "zero",
           "velocity of a kind = \"wall\" block (a lid): the no-slip velocity the viscosity "
           "drags the normal fluid toward"});
    t.add({"fixed_point.position_exponent", T::integer, "-",
           "covers the domain with 52 fraction bits",
           "positions are stored as integers times 2^exponent"});
    t.add({"fixed_point.velocity_exponent", T::integer, "-", "covers u1 with 50 fraction bits",
           "v and v_s are stored as integers times 2^exponent"});
    t.add({"fixed_point.entropy_exponent", T::integer, "-", "covers s0 with 50 fraction bits",
           "s is stored as integers times 2^exponent"});
    t.add({"fixed_point.heat_exponent", T::integer, "-",
           "covers rho0 dr^D T0 s0 with 60 fraction bits",
           "scale of the sums of the heat a particle receives in a dissipation sub-step"});
    t.add({"fixed_point.density_exponent", T::integer, "-", "covers rho0 with 48 fraction bits",
           "scale of the density sums and the constants C_a"});
    return t;
  }();
  return table;
}

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::superfluid
