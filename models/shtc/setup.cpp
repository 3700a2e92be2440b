#include "models/shtc/setup.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/case_values.hpp"
#include "core/dimension.hpp"
#include "core/particle_blocks.hpp"
#include "core/run_settings.hpp"
#include "core/state_fill.hpp"
#include "models/shtc/model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace revsph::shtc {

namespace {

constexpr std::string_view particle_kinds[] = {"material", "boundary"};

// Memory per particle, generously: state (~(2 D + D^2 + 5) * 8 B), slot copies, the matrices H,
// H^-1, stress, L and its sum (5 D^2 doubles), cell list, plus 4 B per neighbour in the half list
// and as much again while it is built.

// Paper 2 eqs. (55) and (60).
template <int D>
Vec<D> initial_velocity(const Parameters<D>& p, const Vec<D>& x) {
  Vec<D> v{};
  if (p.initial_field == InitialField::bending_plate) {
    const BendingPlateField& f = p.plate;
    const double s = f.alpha * (x[0] - f.x0);
    v[1] = f.amplitude * f.omega *
           (f.a1 * (dmath::sinh(s) + dmath::sin(s)) - f.a2 * (dmath::cosh(s) + dmath::cos(s)));
  } else if (p.initial_field == InitialField::twisting_column) {
    if constexpr (D == 3) {
      const double factor =
          p.column.omega * dmath::sin(std::numbers::pi * x[2] / (2.0 * p.column.height));
      v[0] = factor * x[1];
      v[1] = -factor * x[0];
    }
  }
  return v;
}

// A = I for every particle: the material starts undistorted.
template <int D>
void set_undistorted(const CaseFile& case_file, const DistortionScales& scales,
                     CarrierFields<D>& set, std::size_t count) {
  std::apply([&](auto&... fields) { (fields.resize(count), ...); }, set.fields());
  ExactDistortion<D> identity;
  if (!try_make_distortion<D>(Matrix<D>::Identity(), scales, identity)) {
    case_file.fail("fixed_point.unimodular_exponent", "the identity does not fit this scale");
  }
  for (std::size_t i = 0; i < count; ++i) {
    set.log_det.at(0, i) = identity.log_det;
    for (int c = 0; c < D * D; ++c) {
      set.unimodular.at(c, i) = identity.unimodular[c];
    }
  }
}

// The velocity a boundary block's particle has at full drive: `velocity = [...]` (a translating
// wall, the cavity's lid) or `angular_velocity = omega` (rad/s) about `rotation_centre` (default
// the origin; in 3D about the z axis through it), v = omega e_z x (x - c): a rigidly rotating wall
// (Taylor-Couette's outer ring). Neither: a wall at rest.
template <int D>
std::vector<Vec<D>> wall_velocities(const CaseFile& case_file, const ParticleBlock<D>& block) {
  const std::string velocity_key = block.key + ".velocity";
  const std::string omega_key = block.key + ".angular_velocity";
  const std::string centre_key = block.key + ".rotation_centre";
  const bool translates = case_file.has(velocity_key);
  const bool rotates = case_file.has(omega_key);
  if (block.kind != "boundary" && (translates || rotates || case_file.has(centre_key))) {
    case_file.fail(translates ? velocity_key
                   : rotates  ? omega_key
                              : centre_key,
                   "only a \"boundary\" block is a wall with a prescribed velocity");
  }
  if (translates && rotates) {
    case_file.fail(omega_key, "give a wall either a velocity or an angular_velocity, not both");
  }
  if (case_file.has(centre_key) && !rotates) {
    case_file.fail(centre_key, "rotation_centre needs angular_velocity");
  }
  std::vector<Vec<D>> velocities(block.positions.size(), Vec<D>{});
  if (translates) {
    const std::vector<double> given = case_file.numbers(velocity_key, D);
    Vec<D> v{};
    std::copy(given.begin(), given.end(), v.begin());
    std::fill(velocities.begin(), velocities.end(), v);
  } else if (rotates) {
    const double omega = case_file.number(omega_key);
    Vec<2> centre{};
    if (case_file.has(centre_key)) {
      const std::vector<double> c = case_file.numbers(centre_key, 2);
      centre = {c[0], c[1]};
    }
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      velocities[i][0] = -omega * (block.positions[i][1] - centre[1]);
      velocities[i][1] = omega * (block.positions[i][0] - centre[0]);
    }
  }
  return velocities;
}

std::string scientific(double value) {
  return format_scientific(value, 6);
}

template <int D>
std::unique_ptr<Simulation> create_in(const CaseFile& case_file, const SimulationOptions& options) {
  const Parameters<D> parameters = read_parameters<D>(case_file);
  const double reach = parameters.support_radius() / parameters.dr; // support radius over dr
  const auto blocks = read_particle_blocks<D>(
      case_file, parameters.dr, parameters.domain, particle_kinds,
      particle_budget(D, reach, 300.0 + 56.0 * D * D, options.memory_budget_bytes));
  std::vector<Vec<D>> material_positions, boundary_positions, boundary_velocities;
  for (const auto& block : blocks) {
    auto& positions = block.kind == "material" ? material_positions : boundary_positions;
    positions.insert(positions.end(), block.positions.begin(), block.positions.end());
    const std::vector<Vec<D>> velocities = wall_velocities<D>(case_file, block);
    if (block.kind == "boundary") {
      boundary_velocities.insert(boundary_velocities.end(), velocities.begin(), velocities.end());
    }
  }
  if (material_positions.empty()) {
    case_file.fail("particles", "the case has no material particles");
  }
  std::vector<Vec<D>> velocities;
  for (const Vec<D>& x : material_positions) {
    velocities.push_back(initial_velocity<D>(parameters, x));
  }

  State<D> state;
  // The masses' scale follows from the kernel sums (Model::initialise_constants).
  set_scales(state, {{"position", parameters.position_scale},
                     {"velocity", parameters.velocity_scale},
                     {"drive_time", parameters.drive_time_scale},
                     {"dissipated", parameters.dissipated_scale},
                     {"log_det", parameters.distortion_scales.log_det},
                     {"unimodular", parameters.distortion_scales.unimodular},
                     {"density", parameters.density_scale}});
  fill_set<FixedArithmetic, D>(
      case_file, state.material, material_positions.size(),
      {{"position", "particles", material_positions}, {"velocity", "particles", velocities}});
  fill_set<FixedArithmetic, D>(case_file, state.boundary, boundary_positions.size(),
                               {{"position", "particles", boundary_positions},
                                {"wall_velocity", "particles", boundary_velocities},
                                {"drive_time", "particles", 0.0},
                                {"wall_work", "particles", 0.0}});
  const bool moving_walls = any_wall_moves(state);
  set_undistorted<D>(case_file, parameters.distortion_scales, state.material.carried,
                     material_positions.size());
  set_undistorted<D>(case_file, parameters.distortion_scales, state.boundary.carried,
                     boundary_positions.size());

  SimulationInfo info = simulation_info(case_file, "shtc", D, Arithmetic::fixed, parameters.dt);
  info.splitting = parameters.splitting;
  info.sound_speed = parameters.material.sound_speed;
  info.setup_report.emplace_back("dt", scientific(parameters.dt));
  info.setup_report.emplace_back("sound_speed", scientific(parameters.material.sound_speed));
  info.setup_report.emplace_back("shear_speed", scientific(parameters.material.shear_speed));
  if (moving_walls) {
    info.setup_report.emplace_back("walls.ramp_time", scientific(parameters.ramp_time));
  }
  if (parameters.mirrored_walls) {
    info.setup_report.emplace_back("walls.no_slip", "mirrored");
  }
  if (parameters.cayley_distortion_update) {
    info.setup_report.emplace_back("distortion_update", "cayley");
  }
  if (parameters.relaxation_time) {
    info.setup_report.emplace_back("relaxation_time", scientific(*parameters.relaxation_time));
    info.setup_report.emplace_back("dt_over_relaxation_time",
                                   scientific(parameters.dt / *parameters.relaxation_time));
    info.setup_report.emplace_back("relaxation_splitting.relaxation_time",
                                   scientific(parameters.relaxation_splitting.relaxation_time));
    info.setup_report.emplace_back("relaxation_splitting.substeps",
                                   std::to_string(parameters.relaxation_splitting.substeps));
  }

  std::optional<std::size_t> probe;
  if (parameters.probe) {
    // The material particle nearest to the point at t = 0 (the lowest index among equals).
    double best = INFINITY;
    for (std::size_t a = 0; a < material_positions.size(); ++a) {
      double distance = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = material_positions[a][k] - (*parameters.probe)[k];
        distance += d * d;
      }
      if (distance < best) {
        best = distance;
        probe = a;
      }
    }
    std::string where;
    for (int k = 0; k < D; ++k) {
      where += (k == 0 ? "" : " ") + scientific(material_positions[*probe][k]);
    }
    info.setup_report.emplace_back("probe.particle", std::to_string(*probe));
    info.setup_report.emplace_back("probe.initial_position", where);
  }
  Model<D> model(parameters, std::move(info), std::move(state), probe);
  model.initialise_constants();
  return std::make_unique<ModelSimulation<Model<D>>>(std::move(model));
}

} // namespace

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options) {
  // The distortion algebra (distortion.hpp) is written for 2D and 3D.
  return with_dimension<2, 3>(case_file, [&]<int D>() { return create_in<D>(case_file, options); });
}

} // namespace revsph::shtc
