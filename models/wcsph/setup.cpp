#include "models/wcsph/setup.hpp"

#include "core/particle_blocks.hpp"
#include "core/run_settings.hpp"
#include "models/wcsph/model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace revsph::wcsph {

namespace {

constexpr std::string_view particle_kinds[] = {"fluid", "wall"};
// Memory per particle, generously: state, positions, derived arrays and cell lists ~250 B, plus
// 4 B per neighbour in the lists and as much again while they are built. Measured about 220 B per
// particle in 2D at h = 3 dr (~28 neighbours; tools/bench/results).
double bytes_per_particle(int dimension, double support_radius_over_dr) {
  const double r = support_radius_over_dr;
  const double neighbours =
      dimension == 2 ? std::numbers::pi * r * r : 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return 250.0 + 8.0 * neighbours;
}
// Masses are constants of the setup; 52 bits keep their double view exact.
constexpr int mass_fraction_bits = 52;

template <class Arith, int D>
void fill_positions(const CaseFile& case_file, const ParticleBlock<D>& block,
                    StateField<typename Arith::Raw>& field, std::size_t first) {
  for (std::size_t i = 0; i < block.positions.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      if (!Arith::try_from_real(block.positions[i][k], field.info().scale,
                                field.at(k, first + i))) {
        case_file.fail(block.key, "a particle position does not fit the position scale "
                                  "(see fixed_point.position_exponent)");
      }
    }
  }
}

template <int D, class Arith>
std::unique_ptr<Simulation> create_in(const CaseFile& case_file, const SimulationOptions& options) {
  using Raw = typename Arith::Raw;
  const Parameters<D> parameters = read_parameters<D>(case_file);
  const auto blocks =
      read_particle_blocks<D>(case_file, parameters.dr, parameters.domain, particle_kinds,
                              {bytes_per_particle(D, parameters.support_radius / parameters.dr),
                               options.memory_budget_bytes});
  std::size_t fluid_count = 0;
  std::size_t wall_count = 0;
  double largest_mass = 0.0;
  for (const auto& block : blocks) {
    if (block.kind == "fluid") {
      fluid_count += block.positions.size();
      largest_mass = std::max(largest_mass, parameters.rest_density * block.volume_per_particle);
    } else {
      wall_count += block.positions.size();
    }
  }
  if (fluid_count == 0) {
    case_file.fail("particles", "the case has no fluid particles");
  }
  // rest_density * lattice cell volume can overflow or underflow even when both are valid.
  if (!(largest_mass > 0.0) || !std::isfinite(largest_mass)) {
    std::ostringstream reason;
    reason << "the particle mass rest_density * (lattice cell volume) is " << largest_mass
           << ": it must be positive and finite";
    case_file.fail("physics.rest_density", reason.str());
  }

  State<D, Raw> state;
  state.position.info().scale = parameters.position_scale;
  state.velocity.info().scale = parameters.velocity_scale;
  state.mass.info().scale = fixedpoint::Scale::covering(largest_mass, mass_fraction_bits);
  state.density_constant.info().scale = parameters.density_scale;
  state.wall_position.info().scale = parameters.position_scale;
  state.position.resize(fluid_count);
  state.velocity.resize(fluid_count);
  state.mass.resize(fluid_count);
  state.density_constant.resize(fluid_count);
  state.wall_position.resize(wall_count);

  std::size_t next_fluid = 0;
  std::size_t next_wall = 0;
  for (const auto& block : blocks) {
    if (block.kind == "fluid") {
      fill_positions<Arith, D>(case_file, block, state.position, next_fluid);
      for (std::size_t i = 0; i < block.positions.size(); ++i) {
        Arith::try_from_real(parameters.rest_density * block.volume_per_particle,
                             state.mass.info().scale, state.mass.at(0, next_fluid + i));
      }
      next_fluid += block.positions.size();
    } else {
      fill_positions<Arith, D>(case_file, block, state.wall_position, next_wall);
      next_wall += block.positions.size();
    }
  }

  SimulationInfo info;
  info.case_name = case_name(case_file);
  info.model = "wcsph";
  info.dimension = D;
  info.arithmetic = options.arithmetic;
  info.dt = parameters.dt;
  info.particles = {{"fluid", fluid_count, true}, {"wall", wall_count, false}};
  return std::make_unique<ModelSimulation<Model<D, Arith>>>(
      Model<D, Arith>(parameters, std::move(info), std::move(state)));
}

template <int D>
std::unique_ptr<Simulation> create_with_arithmetic(const CaseFile& case_file,
                                                   const SimulationOptions& options) {
  if (options.arithmetic == Arithmetic::fixed) {
    return create_in<D, FixedArithmetic>(case_file, options);
  }
  return create_in<D, FloatArithmetic>(case_file, options);
}

} // namespace

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options) {
  const std::int64_t dimension = case_file.integer("dimension");
  if (dimension == 2) {
    return create_with_arithmetic<2>(case_file, options);
  }
  if (dimension == 3) {
    return create_with_arithmetic<3>(case_file, options);
  }
  case_file.fail("dimension", "must be 2 or 3 (got " + std::to_string(dimension) + ")");
}

} // namespace revsph::wcsph
