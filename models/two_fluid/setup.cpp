#include "models/two_fluid/setup.hpp"

#include "core/case_values.hpp"
#include "core/dimension.hpp"
#include "core/particle_blocks.hpp"
#include "core/portable_random.hpp"
#include "core/run_settings.hpp"
#include "core/state_fill.hpp"
#include "models/two_fluid/hydrostatic_start.hpp"
#include "models/two_fluid/model.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace revsph::two_fluid {

namespace {

constexpr std::string_view particle_kinds[] = {"superfluid", "normal", "mixed", "wall"};
// State (2D + 3 values), a dozen per-slot arrays and cell lists, plus neighbours.

// The particles of one kind as the setup collects them.
template <int D>
struct KindParticles {
  std::vector<Vec<D>> position, velocity;
  std::vector<double> mass;
};

// p = m v with v's components uniform in [-amplitude, amplitude] (initial.random_velocity).
template <int D>
std::vector<Vec<D>> initial_momenta(const KindParticles<D>& kind, double amplitude,
                                    std::mt19937_64& generator) {
  std::vector<Vec<D>> momenta(kind.position.size());
  for (std::size_t i = 0; i < momenta.size(); ++i) {
    for (int k = 0; k < D && amplitude > 0.0; ++k) {
      momenta[i][k] = kind.mass[i] * amplitude * symmetric_uniform(generator);
    }
  }
  return momenta;
}

// A wall block's velocity: `velocity`, or omega x (x - centre) for a turning one (2D).
template <int D>
Vec<D> wall_velocity(const CaseFile& case_file, const std::string& key, const Vec<D>& x) {
  Vec<D> v{};
  if (case_file.has(key + ".velocity")) {
    const std::vector<double> given = case_file.numbers(key + ".velocity", D);
    std::copy(given.begin(), given.end(), v.begin());
  }
  const double rate = case_file.number_or(key + ".rotation_rate", 0.0);
  if (rate != 0.0) {
    if (D != 2) {
      case_file.fail(key + ".rotation_rate", "a turning wall is 2D only");
    }
    std::vector<double> centre(D, 0.0);
    if (case_file.has(key + ".rotation_centre")) {
      centre = case_file.numbers(key + ".rotation_centre", D);
    }
    v[0] += -rate * (x[1] - centre[1]);
    v[1] += rate * (x[0] - centre[0]);
  }
  return v;
}

// A block's `wall_motion`: true for "rigid" (the particles turn with the block, README "Wall
// grip"), false for "frozen" (the default). Read on every block, so that a bad value is named
// before the check that the key belongs to walls.
bool rigid_wall(const CaseFile& case_file, const std::string& key) {
  const std::string motion = case_file.string_or(key + ".wall_motion", "frozen");
  if (motion != "frozen" && motion != "rigid") {
    case_file.fail(key + ".wall_motion",
                   "expected \"frozen\" or \"rigid\", got \"" + motion + "\"");
  }
  return motion == "rigid";
}

// The rate |omega| of a rigid wall block.
template <int D>
double rigid_rate(const CaseFile& case_file, const std::string& key) {
  if (D != 2) {
    case_file.fail(key + ".wall_motion", "a rigid turning wall is 2D only");
  }
  if (case_file.has(key + ".velocity")) {
    case_file.fail(key + ".wall_motion",
                   "a rigid wall moves by its rotation only: remove velocity");
  }
  const double rate = case_file.number_or(key + ".rotation_rate", 0.0);
  if (!(std::isfinite(rate) && rate != 0.0)) {
    case_file.fail(key + ".wall_motion", "a rigid wall needs a non-zero rotation_rate");
  }
  return std::abs(rate);
}

template <int D, class Arith>
std::unique_ptr<Simulation> create_in(const CaseFile& case_file, const SimulationOptions& options) {
  using Raw = typename Arith::Raw;
  Parameters<D> parameters = read_parameters<D>(case_file);
  if (D != 2 && parameters.spin != 0.0) {
    case_file.fail("spin.coefficient", "the spin term (eq. 40) is implemented in 2D only");
  }
  const double reach = parameters.support_radius / parameters.dr;
  const auto blocks =
      read_particle_blocks<D>(case_file, parameters.dr, parameters.domain, particle_kinds,
                              particle_budget(D, reach, 300.0, options.memory_budget_bytes));
  KindParticles<D> superfluid, normal, wall;
  for (const auto& block : blocks) {
    const bool rigid = rigid_wall(case_file, block.key);
    for (const char* wall_only :
         {".velocity", ".rotation_rate", ".rotation_centre", ".wall_motion"}) {
      if (block.kind != "wall" && case_file.has(block.key + wall_only)) {
        case_file.fail(block.key + wall_only, "only for kind = \"wall\"");
      }
    }
    const std::string fraction_key = block.key + ".superfluid_fraction";
    for (const std::string& mixed_only : {fraction_key, block.key + ".seed"}) {
      if (block.kind != "mixed" && case_file.has(mixed_only)) {
        case_file.fail(mixed_only, "only for kind = \"mixed\"");
      }
    }
    const double volume = block.volume_per_particle;
    if (block.kind == "wall") {
      const double rate = rigid ? rigid_rate<D>(case_file, block.key) : 0.0;
      std::array<double, 2> centre{};
      if (rate > 0.0 && case_file.has(block.key + ".rotation_centre")) {
        const std::vector<double> given = case_file.numbers(block.key + ".rotation_centre", D);
        centre = {given[0], given[1]};
      }
      for (const Vec<D>& x : block.positions) {
        wall.position.push_back(x);
        wall.velocity.push_back(wall_velocity<D>(case_file, block.key, x));
        wall.mass.push_back(parameters.rest_density(false) * volume);
        parameters.rigid_walls.rate.push_back(rate);
        parameters.rigid_walls.centre.push_back(centre);
      }
      continue;
    }
    double fraction = block.kind == "superfluid" ? 1.0 : 0.0;
    std::mt19937_64 generator(1);
    // Interpenetrating phases (README): a phase's partial density is its share of the particles
    // times rho_s + rho_n, so only a mixed block drawn at rho_s / rho gives the physical ones.
    const double physical_fraction =
        parameters.superfluid_density / (parameters.superfluid_density + parameters.normal_density);
    if (parameters.interpenetrating && block.kind != "mixed") {
      case_file.fail(block.key + ".kind", "with physics.phases = \"interpenetrating\" the fluid "
                                          "is given as mixed blocks");
    }
    if (block.kind == "mixed") {
      fraction = parameters.interpenetrating ? case_file.number_or(fraction_key, physical_fraction)
                                             : case_file.number(fraction_key);
      if (!(fraction > 0.0 && fraction < 1.0)) {
        case_file.fail(fraction_key, "must be in (0, 1)");
      }
      if (parameters.interpenetrating && std::abs(fraction / physical_fraction - 1.0) > 1e-3) {
        case_file.fail(fraction_key, "with interpenetrating phases it must be rho_s / (rho_s + "
                                     "rho_n) = " +
                                         std::to_string(physical_fraction) +
                                         " (the partial densities come from the draw)");
      }
      const std::int64_t seed = case_file.integer_or(block.key + ".seed", 1);
      if (seed < 0) {
        case_file.fail(block.key + ".seed", "must be >= 0");
      }
      generator.seed(static_cast<std::uint64_t>(seed));
    }
    for (const Vec<D>& x : block.positions) {
      const bool is_superfluid = block.kind == "mixed" ? unit_uniform(generator) < fraction
                                 : parameters.interface.given
                                     ? parameters.interface.superfluid_at(x[0], x[D - 1])
                                     : block.kind == "superfluid";
      KindParticles<D>& kind = is_superfluid ? superfluid : normal;
      kind.position.push_back(x);
      kind.mass.push_back(parameters.rest_density(is_superfluid) * volume);
    }
  }
  if (parameters.hydrostatic_start) {
    if (parameters.interpenetrating || !(parameters.gravity > 0.0)) {
      case_file.fail("initial.hydrostatic", "needs separate phases and physics.gravity > 0");
    }
    hydrostatic_masses<D>(parameters, {superfluid.position, normal.position, wall.position},
                          {superfluid.mass, normal.mass, wall.mass});
  }
  // The interface's displacement moves the particles after the masses are set: each carries the
  // mass (and so the pressure) of its place in the flat column, as a fluid displaced at rest.
  if (parameters.interface.given && parameters.interface.displaced) {
    for (KindParticles<D>* kind : {&superfluid, &normal}) {
      for (Vec<D>& x : kind->position) {
        const auto [along, up] = parameters.interface.displacement(x[0], x[D - 1]);
        x[0] += along;
        x[D - 1] += up;
      }
    }
  }
  // N / N_n is the normal share of a random mixture (model.hpp, normal_pair_factor): it means
  // nothing for layers of pure kinds.
  const bool any_mixed = std::any_of(blocks.begin(), blocks.end(),
                                     [](const auto& block) { return block.kind == "mixed"; });
  if (parameters.undiluted_viscosity && !any_mixed) {
    case_file.fail("physics.separate_phase_viscosity",
                   "\"undiluted\" is for a random mixture: the case has no mixed block");
  }
  if (superfluid.position.empty() && normal.position.empty()) {
    case_file.fail("particles", "the case has no superfluid or normal particles");
  }
  const fixedpoint::Scale masses = mass_scale(case_file, "physics.superfluid_density",
                                              {superfluid.mass, normal.mass, wall.mass});
  const fixedpoint::Scale temperature_scale =
      fixedpoint::Scale::covering(parameters.temperature, 52);
  const fixedpoint::Scale spin_scale =
      fixedpoint::Scale::covering(std::max(std::abs(parameters.spin), 1.0), 50);

  State<D, Raw> state;
  set_scales(state,
             {{"position", parameters.position_scale},
              {"momentum", parameters.momentum_scale},
              {"velocity", fixedpoint::Scale::covering(std::max(parameters.sound_speed, 1.0), 50)},
              {"mass", masses},
              {"temperature", temperature_scale},
              {"spin", spin_scale}});
  std::mt19937_64 velocity_generator(parameters.seed);
  auto fill_moving = [&](auto& set, const KindParticles<D>& kind) {
    fill_set<Arith, D>(case_file, set, kind.position.size(),
                       {{"position", "particles", kind.position},
                        {"momentum", "initial.random_velocity",
                         initial_momenta<D>(kind, parameters.random_velocity, velocity_generator)},
                        {"mass", "physics.superfluid_density", kind.mass},
                        {"temperature", "physics.temperature", parameters.temperature},
                        {"spin", "spin.coefficient", parameters.spin}});
  };
  fill_moving(state.superfluid, superfluid);
  fill_moving(state.normal, normal);
  // Walls carry no spin (README).
  fill_set<Arith, D>(case_file, state.wall, wall.position.size(),
                     {{"position", "particles", wall.position},
                      {"velocity", "particles", wall.velocity},
                      {"mass", "physics.normal_density", wall.mass},
                      {"temperature", "physics.temperature", parameters.temperature},
                      {"spin", "particles", 0.0}});

  SimulationInfo info =
      simulation_info(case_file, "two_fluid", D, options.arithmetic, parameters.dt);
  info.splitting = parameters.splitting;
  info.sound_speed = parameters.sound_speed;
  info.setup_report.emplace_back("dt", format_scientific(parameters.dt, 4));
  if (parameters.thermomechanical.entropy_scale > 0.0) {
    const Thermomechanical& t = parameters.thermomechanical;
    info.setup_report.emplace_back(
        "sigma",
        format_scientific(t.entropy_scale *
                              phonon_roton_entropy(parameters.temperature, t.first_sound_speed) /
                              t.reference_density,
                          4));
  }
  if (parameters.spin != 0.0) {
    info.setup_report.emplace_back("spin", format_scientific(parameters.spin, 4));
  }
  return std::make_unique<ModelSimulation<Model<D, Arith>>>(
      Model<D, Arith>(parameters, std::move(info), std::move(state)));
}

} // namespace

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options) {
  return with_dimension_and_arithmetic<2, 3>(
      case_file, options.arithmetic,
      [&]<int D, class Arith>() { return create_in<D, Arith>(case_file, options); });
}

} // namespace revsph::two_fluid
