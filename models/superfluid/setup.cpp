#include "models/superfluid/setup.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/case_values.hpp"
#include "core/dimension.hpp"
#include "core/particle_blocks.hpp"
#include "core/portable_random.hpp"
#include "core/run_settings.hpp"
#include "core/state_fill.hpp"
#include "models/superfluid/model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

namespace revsph::superfluid {

namespace {

constexpr std::string_view particle_kinds[] = {"fluid", "dummy", "wall"};
// State (2 x (2D + 1) + D + 2 values), derived arrays (~4D + 8) and cell lists, plus neighbours.

// Copy 1 of the initial fields: rest at s0, plus the standing wave of eq. (26) and the seeded
// random perturbations.
template <int D>
struct InitialCopy {
  std::vector<Vec<D>> velocity, superflow_velocity;
  std::vector<double> entropy;
};

template <int D>
InitialCopy<D> initial_copy(const CaseFile& case_file, const Parameters<D>& parameters,
                            const std::vector<Vec<D>>& positions) {
  const InitialFields& f = parameters.initial;
  const Helium& he = parameters.helium;
  std::mt19937_64 generator(f.seed);
  InitialCopy<D> copy;
  for (const Vec<D>& x : positions) {
    Vec<D> v{}, u{};
    for (int k = 0; k < D; ++k) {
      v[k] = (f.uniform_velocity.empty() ? 0.0 : f.uniform_velocity[k]) +
             f.random_velocity * symmetric_uniform(generator);
    }
    for (int k = 0; k < D; ++k) {
      u[k] = (f.uniform_counterflow.empty() ? 0.0 : f.uniform_counterflow[k]) +
             f.random_counterflow * symmetric_uniform(generator);
    }
    double wave = f.wave_amplitude;
    for (int k = 0; k < D && wave != 0.0; ++k) {
      const double angle = std::numbers::pi * x[k] / f.wave_length;
      wave *= f.wave_cosine ? dmath::cos(angle) : dmath::sin(angle); // eq. (26)
    }
    const double s =
        he.reference_entropy * (1.0 + wave + f.random_entropy * symmetric_uniform(generator));
    const double chi_n = he.chi_n(s);
    if (!(chi_n > 0.0 && chi_n <= 1.0)) {
      std::ostringstream reason;
      reason << "gives s = " << s << " J/(kg K) and chi_n = " << chi_n
             << " (eq. 8) at a particle: chi_n must stay in (0, 1]";
      case_file.fail(f.random_entropy > 0.0 ? "initial.random_entropy"
                     : wave != 0.0          ? "initial.entropy_wave_amplitude"
                                            : "physics.normal_fraction",
                     reason.str());
    }
    Vec<D> v_s{};
    for (int k = 0; k < D; ++k) {
      v_s[k] = v[k] - u[k];
    }
    copy.velocity.push_back(v);
    copy.superflow_velocity.push_back(v_s);
    copy.entropy.push_back(s);
  }
  return copy;
}

template <int D, class Arith>
std::unique_ptr<Simulation> create_in(const CaseFile& case_file, const SimulationOptions& options) {
  using Raw = typename Arith::Raw;
  const Parameters<D> parameters = read_parameters<D>(case_file);
  const double reach = parameters.support_radius / parameters.dr;
  const auto blocks =
      read_particle_blocks<D>(case_file, parameters.dr, parameters.domain, particle_kinds,
                              particle_budget(D, reach, 400.0, options.memory_budget_bytes));
  std::vector<Vec<D>> fluid_positions, dummy_positions, wall_positions, wall_velocities;
  std::vector<double> fluid_masses, dummy_masses, wall_masses;
  const double rho0 = parameters.helium.rest_density;
  for (const auto& block : blocks) {
    const std::string velocity_key = block.key + ".velocity";
    Vec<D> velocity{};
    if (case_file.has(velocity_key)) {
      if (block.kind != "wall") {
        case_file.fail(velocity_key, "only for kind = \"wall\" (a moving no-slip wall: a lid)");
      }
      const std::vector<double> given = case_file.numbers(velocity_key, D);
      std::copy(given.begin(), given.end(), velocity.begin());
    }
    auto& positions = block.kind == "fluid"   ? fluid_positions
                      : block.kind == "dummy" ? dummy_positions
                                              : wall_positions;
    auto& masses = block.kind == "fluid"   ? fluid_masses
                   : block.kind == "dummy" ? dummy_masses
                                           : wall_masses;
    positions.insert(positions.end(), block.positions.begin(), block.positions.end());
    masses.insert(masses.end(), block.positions.size(), rho0 * block.volume_per_particle);
    if (block.kind == "wall") {
      wall_velocities.insert(wall_velocities.end(), block.positions.size(), velocity);
    }
  }
  if (fluid_positions.empty()) {
    case_file.fail("particles", "the case has no fluid particles");
  }
  const fixedpoint::Scale masses =
      mass_scale(case_file, "physics.rest_density", {fluid_masses, dummy_masses, wall_masses});
  const InitialCopy<D> initial = initial_copy<D>(case_file, parameters, fluid_positions);

  State<D, Raw> state;
  auto& fluid = state.fluid;
  set_scales(state, {{"position", parameters.position_scale},
                     {"velocity", parameters.velocity_scale},
                     {"entropy", parameters.entropy_scale},
                     {"mass", masses},
                     {"density", parameters.density_scale}});

  // Both copies start equal, raw for raw; the density constants at zero
  // (initialise_density_constants sets them).
  fill_set<Arith, D>(
      case_file, fluid, fluid_positions.size(),
      {{"position", "particles", fluid_positions},
       {"velocity", "initial.random_velocity", initial.velocity},
       {"velocity_copy", "initial.random_velocity", initial.velocity},
       {"superflow_velocity", "initial.random_counterflow", initial.superflow_velocity},
       {"superflow_velocity_copy", "initial.random_counterflow", initial.superflow_velocity},
       {"entropy", "physics.reference_entropy", initial.entropy},
       {"entropy_copy", "physics.reference_entropy", initial.entropy},
       {"mass", "physics.rest_density", fluid_masses},
       {"density_constant", "particles", 0.0}});
  fill_set<Arith, D>(case_file, state.dummy, dummy_positions.size(),
                     {{"position", "particles", dummy_positions},
                      {"mass", "physics.rest_density", dummy_masses},
                      {"density_constant", "particles", 0.0}});
  // No counterflow at the start: v_s = v.
  fill_set<Arith, D>(case_file, state.wall, wall_positions.size(),
                     {{"position", "particles", wall_positions},
                      {"velocity", "particles", wall_velocities},
                      {"superflow_velocity", "particles", wall_velocities},
                      {"superflow_velocity_copy", "particles", wall_velocities},
                      {"mass", "physics.rest_density", wall_masses},
                      {"density_constant", "particles", 0.0}});

  SimulationInfo info =
      simulation_info(case_file, "superfluid", D, options.arithmetic, parameters.dt);
  info.splitting = parameters.splitting;
  info.sound_speed = parameters.helium.first_sound_speed;
  // u2 of eq. (14) exists only with a superfluid fraction (not in the classical cavity).
  if (parameters.helium.normal_fraction < 1.0) {
    info.setup_report.emplace_back("second_sound_speed",
                                   format_scientific(parameters.helium.second_sound_speed(), 4));
  }
  info.setup_report.emplace_back("heat_capacity",
                                 format_scientific(parameters.helium.heat_capacity, 4));
  info.setup_report.emplace_back("dt", format_scientific(parameters.dt, 4));
  Model<D, Arith> model(parameters, std::move(info), std::move(state));
  model.initialise_density_constants();
  return std::make_unique<ModelSimulation<Model<D, Arith>>>(std::move(model));
}

} // namespace

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options) {
  return with_dimension_and_arithmetic<2, 3>(
      case_file, options.arithmetic,
      [&]<int D, class Arith>() { return create_in<D, Arith>(case_file, options); });
}

} // namespace revsph::superfluid
