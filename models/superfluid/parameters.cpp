#include "models/superfluid/parameters.hpp"

#include "core/case_key.hpp"
#include "core/case_values.hpp"
#include "core/particle_blocks.hpp"
#include "core/particle_discretisation.hpp"

#include <cmath>
#include <sstream>

namespace revsph::superfluid {

namespace {

// Every key of a superfluid case file beyond common_case_keys(), including those the core's
// readers and setup.cpp read, in the reference's order.
struct Keys : KeySet {
  Keys() : KeySet("superfluid") {}
  const std::string dimension = declare({"dimension", KeyType::integer, "-", "required", "2 or 3"});
  const Key<double> rest_density = number("physics.rest_density", "kg/m^3", "required",
                                          "rho0 of eq. (12); > 0", positive_or_why);
  const Key<double> first_sound_speed =
      number("physics.first_sound_speed", "m/s", "required", "u1 of eq. (12) (first sound); > 0",
             positive_or_why);
  const Key<double> reference_temperature = number("physics.reference_temperature", "K", "required",
                                                   "T0 of eq. (13); > 0", positive_or_why);
  const Key<double> reference_entropy = number("physics.reference_entropy", "J/(kg K)", "required",
                                               "s0 of eqs. (8, 13); > 0", positive_or_why);
  const Key<double> gravity = KeySet::gravity("eq. (29), on v and v_s");
  const Key<double> gravity_reference_height = KeySet::gravity_reference_height();
  const Choice<Splitting> splitting = KeySet::splitting("strang");
  const Key<double> viscosity =
      number("physics.viscosity", "Pa s", "0",
             "mu of the normal fluid (eq. 19, Monaghan's form B22, eta = h / 10); >= 0; "
             "irreversible",
             non_negative("inviscid"));
  const Key<double> heat_conductivity =
      number("physics.heat_conductivity", "W/(m K)", "0",
             "beta of eq. (5) (B21, B23); >= 0; irreversible", non_negative("no conduction"));
  const Key<double> normal_fraction = number(
      "physics.normal_fraction", "1", "required",
      "chi_n0 of eq. (8), in (0, 1] (1: a classical fluid)",
      must<double>([](double chi) { return chi > 0.0 && chi <= 1.0; }, "chi_n0 must be in (0, 1]"));
  const Key<double> normal_fraction_slope =
      number("physics.normal_fraction_slope", "kg K/J", "0", "chi' of eq. (8)");
  const Key<double> heat_capacity =
      number("physics.heat_capacity", "J/(kg K)", "from second_sound_speed",
             "C of eq. (13); > 0; give this or second_sound_speed", positive_or_why);
  const Key<double> second_sound_speed = number(
      "physics.second_sound_speed", "m/s", "from heat_capacity",
      "u2 of eq. (14), which then gives C; > 0; give this or heat_capacity", positive_or_why);
  const Choice<bool> dummy_no_slip = choice<bool>(
      "physics.dummy_slip", "\"free\"",
      "the normal fluid at dummy (adiabatic) walls: \"free\" (sec. III.C: dummies in the "
      "density and the pressure only) or \"no_slip\" (the viscosity also drags the normal "
      "fluid toward rest at them, as the authors' fountain code does; the heat stays in "
      "the fluid)",
      {{"free", false}, {"no_slip", true}});
  const Choice<bool> absorbing_walls = choice<bool>(
      "physics.cooler", "\"conducting\"",
      "what kind = \"wall\" particles are besides no-slip: \"conducting\" (they hold the "
      "fluid at T0 through the heat conduction only) or \"absorbing\" (the authors' "
      "fountain code: they keep s = s0 and v at their velocity but carry a free superflow "
      "velocity, and take part in the entropy flux and the thermomechanical force of eq. "
      "(19), so that second sound leaves through them; reversible, their exchange counted "
      "in wall_exchange)",
      {{"conducting", false}, {"absorbing", true}});
  const int discretisation = declare(particle_discretisation_case_keys(
      "kernel support radius in units of dr: Table I's h, the support as the authors' code uses "
      "it (h = 3 dr is 3; eq. 17 as printed, support 2h, would be 6)",
      "time step as a fraction of support / u1: dt = courant_number * support / u1 (the "
      "paper's dt = h / (M u1) is courant_number = 1 / M)"));
  const Key<double> wave_amplitude =
      number("initial.entropy_wave_amplitude", "1", "0",
             "A of eq. (26): s = s0 (1 + A sin(pi x / L) sin(pi y / L)) [sin(pi z / L) in 3D]");
  const Choice<bool> wave_cosine = choice<bool>(
      "initial.entropy_wave_shape", "\"sine\"",
      "\"sine\": eq. (26) as printed, zero at the edges of the square [0, L]^D (eq. 25 "
      "assumes s = s0 there); \"cosine\": cos(pi x / L) cos(pi y / L), the standing mode "
      "of a square with adiabatic (free) edges",
      {{"sine", false}, {"cosine", true}});
  const Key<double> wave_length =
      number("initial.entropy_wave_length", "m", "required with an amplitude", "L of eq. (26); > 0",
             positive_or_why);
  const std::string uniform_velocity =
      declare({"initial.uniform_velocity", KeyType::numbers, "m/s", "zero",
               "coflow velocity v of every fluid particle (the random part adds to it)"});
  const std::string uniform_counterflow =
      declare({"initial.uniform_counterflow", KeyType::numbers, "m/s", "zero",
               "v - v_s of every fluid particle (the random part adds to it)"});
  const Key<double> hydrostatic_surface =
      number("initial.hydrostatic_surface", "m", "none (rho0 everywhere)",
             "height H of the free surface: the initial density is rho0 (1 + g (H - y) / u1^2), "
             "the pressure rho0 g (H - y) (eq. 12), for every particle");
  const Key<double> random_velocity =
      number("initial.random_velocity", "m/s", "0",
             "each component of v uniform in [-value, value]; >= 0", non_negative());
  const Key<double> random_counterflow =
      number("initial.random_counterflow", "m/s", "0",
             "each component of v - v_s uniform in [-value, value]; >= 0", non_negative());
  const Key<double> random_entropy =
      number("initial.random_entropy", "1", "0",
             "s / s0 - 1 uniform in [-value, value] (added to the wave); >= 0", non_negative());
  const Key<std::int64_t> seed =
      integer("initial.seed", "1", "seed of the random fields; >= 0",
              must<std::int64_t>([](std::int64_t n) { return n >= 0; }, "must be >= 0"));
  const Key<double> superleak_rate =
      number("superleak.rate", "1/s", "0",
             "friction rate of the superleak (eq. 30: its 1 / tau), applied exactly as v_n -> v_n "
             "exp(-rate dt) to the fluid in the slab; >= 0 (0: none); irreversible",
             non_negative("no superleak"));
  const std::string superleak_centre =
      declare({"superleak.centre", KeyType::numbers, "m", "required with a rate",
               "centre of the superleak slab (inside the domain)"});
  const Key<double> superleak_half_width =
      number("superleak.half_width", "m", "required with a rate",
             "half its extent along the axes but the last (r_sup of eq. 30); > 0", positive_or_why);
  const Key<double> superleak_half_thickness =
      number("superleak.half_thickness", "m", "required with a rate",
             "half its extent along the last axis; > 0; no heat is conducted across its "
             "mid-plane",
             positive_or_why);
  const Key<double> jet_height =
      number("jet.height", "m", "none",
             "report the fluid volume (sum m / rho, per unit depth in 2D) above this height in "
             "diagnostics.csv as volume_above_jet_height: its rate over the capillary's width is "
             "the jet speed (sec. III.C)");
  const Key<double> heater_power =
      number("heater.power", "W/m (2D), W (3D)", "0",
             "heater power W of eq. (30); >= 0 (0: none); irreversible, counted in the energy "
             "budget as heater_input",
             non_negative("no heater"));
  const std::string heater_centre =
      declare({"heater.centre", KeyType::numbers, "m", "required with a power", "heater centre"});
  const Key<double> heater_support =
      number("heater.support", "m", "required with a power",
             "support radius of the Wendland kernel that spreads the power (2H of eq. 30); > 0",
             positive_or_why);
  const Key<double> heater_ramp_time =
      number("heater.ramp_time", "s", "0", "the power grows linearly from 0 over this time; >= 0",
             non_negative("full power at once"));
  const int regions = (declare(domain_case_keys()),
                       declare(particle_block_case_keys({"fluid", "dummy", "wall"})), 0);
  const std::string wall_velocity =
      declare({"particles[].velocity", KeyType::numbers, "m/s", "zero",
               "velocity of a kind = \"wall\" block (a lid): the no-slip velocity the viscosity "
               "drags the normal fluid toward"});
  // Default scales: positions keep 52 fraction bits below the domain size; velocities resolve
  // u1 * 2^-50; entropies s0 * 2^-50 (room for 2^13 s0); density sums rho0 * 2^-48. The pair
  // increments of v, v_s and s are summed at the scales of v and s. The heat sums: a particle's
  // thermal energy scale m T0 s0 (m = rho0 dr^D) with 60 bits.
  const PositionScaleKey position_exponent = position_scale();
  const ScaleKey velocity_exponent =
      scale("velocity", "u1", 50, "v and v_s are stored as integers times 2^exponent");
  const ScaleKey entropy_exponent =
      scale("entropy", "s0", 50, "s is stored as integers times 2^exponent");
  const ScaleKey heat_exponent =
      scale("heat", "rho0 dr^D T0 s0", 60,
            "scale of the sums of the heat a particle receives in a dissipation sub-step");
  const ScaleKey density_exponent =
      scale("density", "rho0", 48, "scale of the density sums and the constants C_a");
};

const Keys& keys() {
  static const Keys declared;
  return declared;
}

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
  Parameters<D> p;
  p.helium = read_helium(case_file);
  p.gravity = k.gravity.read(case_file);
  p.gravity_reference_height = k.gravity_reference_height.read(case_file);
  p.splitting = k.splitting.read(case_file);
  p.viscosity = k.viscosity.read(case_file);
  p.heat_conductivity = k.heat_conductivity.read(case_file);
  p.dummy_no_slip = k.dummy_no_slip.read(case_file);
  p.absorbing_walls = k.absorbing_walls.read(case_file);
  const ParticleDiscretisation discretisation =
      read_particle_discretisation(case_file, p.helium.first_sound_speed);
  p.dr = discretisation.dr;
  p.support_radius = discretisation.support_radius;
  p.dt = discretisation.dt;
  p.cell_size_factor = discretisation.cell_size_factor;
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
      k.heat_exponent.read(case_file, he.rest_density * std::pow(p.dr, D) *
                                          he.reference_temperature * he.reference_entropy);
  return p;
}

const KeyTable& case_keys() {
  return keys().table();
}

template Parameters<2> read_parameters<2>(const CaseFile&);
template Parameters<3> read_parameters<3>(const CaseFile&);

} // namespace revsph::superfluid
