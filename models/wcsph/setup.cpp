#include "models/wcsph/setup.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/case_values.hpp"
#include "core/dimension.hpp"
#include "core/memory.hpp"
#include "core/particle_blocks.hpp"
#include "core/run_settings.hpp"
#include "core/state_fill.hpp"
#include "models/wcsph/gresho.hpp"
#include "models/wcsph/model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <sstream>

namespace revsph::wcsph {

namespace {

constexpr std::string_view particle_kinds[] = {"fluid", "wall", "dummy"};
// Memory per particle, generously: state, positions, derived arrays and cell lists ~250 B, plus
// 4 B per neighbour in the lists and as much again while they are built. Measured about 220 B per
// particle in 2D at h = 3 dr (~28 neighbours; tools/bench/results).

// The initial velocity and the density each carrier (fluid, then dummy) should have at t = 0:
// rest, or the Gresho vortex of App. A (its velocity, and the density whose Tait pressure is the
// vortex's pressure, so that the vortex starts in equilibrium).
template <int D>
struct InitialFields {
  std::vector<Vec<D>> velocity;       // fluid
  std::vector<double> target_density; // carriers
};

template <int D>
InitialFields<D> initial_fields(const Parameters<D>& parameters,
                                const std::vector<Vec<D>>& fluid_positions,
                                const std::vector<Vec<D>>& dummy_positions) {
  InitialFields<D> fields{std::vector<Vec<D>>(fluid_positions.size()), {}};
  fields.target_density.reserve(fluid_positions.size() + dummy_positions.size());
  // The Gresho vortex is two-dimensional (parameters.cpp refuses it in 1D and 3D).
  const bool gresho = D == 2 && parameters.initial_field == InitialField::gresho_vortex;
  auto target = [&](const Vec<D>& p) {
    if constexpr (D == 2) {
      if (gresho) {
        const double r = dmath::hypot(p[0] - parameters.centre[0], p[1] - parameters.centre[1]);
        return tait_density(gresho::pressure(r, parameters.rest_density), parameters.rest_density,
                            parameters.sound_speed);
      }
    }
    return parameters.rest_density;
  };
  for (std::size_t a = 0; a < fluid_positions.size(); ++a) {
    const Vec<D>& p = fluid_positions[a];
    if constexpr (D == 2) {
      if (gresho) {
        const auto u = gresho::velocity(p[0] - parameters.centre[0], p[1] - parameters.centre[1]);
        fields.velocity[a][0] = u[0];
        fields.velocity[a][1] = u[1];
      }
    }
    fields.target_density.push_back(target(p));
  }
  for (const Vec<D>& p : dummy_positions) {
    fields.target_density.push_back(target(p));
  }
  return fields;
}

// A point file's initial density (kg/m^3) of the carriers it places: their density at t = 0,
// eq. (5) with C_a chosen so.
SetUpValue initial_density_from_file(std::span<double> target_density) {
  return {.name = "density",
          .unit = "kg/m^3",
          .values = target_density,
          .from_file = [](double density) { return density > 0.0 ? density : std::nan(""); },
          .admits = "above 0 kg/m^3",
          .what = "the initial density"};
}

// A point file's initial pressure (Pa): the density at which the Tait equation (2) gives it,
// defined above -rho0 c^2 / 7 (the pressure at zero density).
template <int D>
SetUpValue initial_pressure_from_file(const Parameters<D>& parameters,
                                      std::span<double> target_density) {
  const double rho0 = parameters.rest_density;
  const double c = parameters.sound_speed;
  const double lowest = -rho0 * c * c / 7.0;
  return {.name = "pressure",
          .unit = "Pa",
          .values = target_density,
          .from_file =
              [=](double pressure) {
                return pressure > lowest ? tait_density(pressure, rho0, c) : std::nan("");
              },
          .admits = "above " + format_number(lowest) + " Pa (-rho0 c^2 / 7, zero density)",
          .what = "the initial density"};
}

template <int D>
CoordinateArrays<D> coordinate_arrays(const std::vector<Vec<D>>& points) {
  CoordinateArrays<D> arrays;
  for (int k = 0; k < D; ++k) {
    arrays[k].reserve(points.size());
    for (const Vec<D>& point : points) {
      arrays[k].push_back(point[k]);
    }
  }
  return arrays;
}

std::string scientific(double value) {
  return format_scientific(value, 3);
}

// Paper 1 §3.2: the fluid particles move until their kernel density (eq. 4), dummy particles
// included, is rho0; wall particles of eq. (7) take no part in densities. Done in double
// precision before anything is converted to fixed point, so the state that starts the reversible
// run is simply the corrected one. Failing to converge is a case error: running on would mark
// the free-surface particles through C_a, which is what the correction exists to avoid.
template <int D>
void correct_fluid_positions(const CaseFile& case_file, const Parameters<D>& parameters,
                             std::vector<Vec<D>>& fluid_positions,
                             const std::vector<double>& fluid_masses,
                             const std::vector<Vec<D>>& dummy_positions,
                             const std::vector<double>& dummy_masses,
                             std::vector<std::pair<std::string, std::string>>& report_out) {
  CoordinateArrays<D> movable = coordinate_arrays<D>(fluid_positions);
  IscReport report;
  try {
    report = correct_initial_state<D>(movable, fluid_masses, coordinate_arrays<D>(dummy_positions),
                                      dummy_masses, parameters.support_radius,
                                      parameters.rest_density, parameters.domain, parameters.isc);
  } catch (const std::exception& error) {
    case_file.fail("initial_state_correction", error.what());
  }
  if (!report.converged) {
    std::ostringstream reason;
    reason << "did not converge: max |rho - rho0| / rho0 = " << scientific(report.residuals.back())
           << " after " << report.iterations << " Newton iterations (tolerance "
           << scientific(parameters.isc.tolerance) << ", max_iterations "
           << parameters.isc.max_iterations << ", seed " << parameters.isc.seed << ")";
    if (!report.stopped_early.empty()) {
      reason << ": " << report.stopped_early;
    }
    case_file.fail("initial_state_correction", reason.str());
  }
  for (std::size_t a = 0; a < fluid_positions.size(); ++a) {
    for (int k = 0; k < D; ++k) {
      fluid_positions[a][k] = movable[k][a];
    }
  }
  std::string linear_iterations;
  for (const int n : report.linear_iterations) {
    if (!linear_iterations.empty()) {
      linear_iterations += ' ';
    }
    linear_iterations += std::to_string(n);
  }
  report_out.emplace_back("initial_state_correction.seed", std::to_string(parameters.isc.seed));
  report_out.emplace_back("initial_state_correction.jitter", scientific(parameters.isc.jitter));
  report_out.emplace_back("initial_state_correction.iterations", std::to_string(report.iterations));
  report_out.emplace_back("initial_state_correction.initial_residual",
                          scientific(report.residuals.front()));
  report_out.emplace_back("initial_state_correction.final_residual",
                          scientific(report.residuals.back()));
  report_out.emplace_back("initial_state_correction.linear_iterations", linear_iterations);
}

template <int D, class Arith>
std::unique_ptr<Simulation> create_in(const CaseFile& case_file, const SimulationOptions& options) {
  using Raw = typename Arith::Raw;
  const Parameters<D> parameters = read_parameters<D>(case_file);
  const double reach = parameters.support_radius / parameters.dr; // support radius over dr
  auto blocks =
      read_particle_blocks<D>(case_file, parameters.dr, parameters.domain, particle_kinds,
                              particle_budget(D, reach, 250.0, options.memory_budget_bytes));
  // Particles of each set in block order; masses are rho0 times the lattice cell volume.
  std::vector<Vec<D>> fluid_positions, wall_positions, dummy_positions;
  std::vector<double> fluid_masses, dummy_masses;
  for (const auto& block : blocks) {
    const double mass = parameters.rest_density * block.volume_per_particle;
    auto& positions = block.kind == "fluid"   ? fluid_positions
                      : block.kind == "dummy" ? dummy_positions
                                              : wall_positions;
    positions.insert(positions.end(), block.positions.begin(), block.positions.end());
    if (block.kind == "fluid") {
      fluid_masses.insert(fluid_masses.end(), block.positions.size(), mass);
    } else if (block.kind == "dummy") {
      dummy_masses.insert(dummy_masses.end(), block.positions.size(), mass);
    }
  }
  // Every copy made during the set-up is freed before the model's first pair sums (the peak of
  // the set-up's memory would otherwise hold the particles three times over).
  free_storage(blocks);
  if (fluid_positions.empty()) {
    case_file.fail("particles", "the case has no fluid particles");
  }
  const fixedpoint::Scale masses =
      mass_scale(case_file, "physics.rest_density", {fluid_masses, dummy_masses});
  std::vector<std::pair<std::string, std::string>> setup_report;
  const PeriodicBox period = read_periodic_box<D>(case_file);
  if (period.any() && parameters.isc_enabled) {
    case_file.fail("domain.periodic", "the initial state correction does not wrap its particles "
                                      "across periodic faces: disable one of them");
  }
  if (period.periodic[D - 1] && parameters.gravity != 0.0) {
    case_file.fail("domain.periodic", "gravity acts along the last axis, whose potential energy "
                                      "a periodic wrap would not conserve");
  }
  if (parameters.isc_enabled) {
    const std::vector<Vec<D>> no_positions;
    const std::vector<double> no_masses;
    correct_fluid_positions<D>(case_file, parameters, fluid_positions, fluid_masses,
                               parameters.isc_with_dummies ? dummy_positions : no_positions,
                               parameters.isc_with_dummies ? dummy_masses : no_masses,
                               setup_report);
  }
  InitialFields<D> initial = initial_fields<D>(parameters, fluid_positions, dummy_positions);

  State<D, Raw> state;
  set_scales(state, {{"position", parameters.position_scale},
                     {"velocity", parameters.velocity_scale},
                     {"mass", masses},
                     {"density", parameters.density_scale}});
  // The density constants start at zero: initialise_density_constants sets them. A point file
  // may give a carrier's initial density or its pressure (Taylor-Green's), either one the target
  // density of the carriers it places.
  const std::span<double> fluid_target =
      std::span(initial.target_density).first(fluid_positions.size());
  const std::span<double> dummy_target =
      std::span(initial.target_density).subspan(fluid_positions.size());
  fill_set<Arith, D>(case_file, state.fluid, fluid_positions.size(),
                     {{"position", "particles", fluid_positions},
                      {"velocity", "initial.field", initial.velocity},
                      {"mass", "physics.rest_density", fluid_masses},
                      {"density_constant", "particles", 0.0}},
                     {initial_density_from_file(fluid_target),
                      initial_pressure_from_file(parameters, fluid_target)});
  fill_set<Arith, D>(case_file, state.wall, wall_positions.size(),
                     {{"position", "particles", wall_positions}});
  fill_set<Arith, D>(case_file, state.dummy, dummy_positions.size(),
                     {{"position", "particles", dummy_positions},
                      {"mass", "physics.rest_density", dummy_masses},
                      {"density_constant", "particles", 0.0}},
                     {initial_density_from_file(dummy_target),
                      initial_pressure_from_file(parameters, dummy_target)});
  free_storage(fluid_positions);
  free_storage(wall_positions);
  free_storage(dummy_positions);
  free_storage(fluid_masses);
  free_storage(dummy_masses);
  free_storage(initial.velocity);

  // A periodic domain: the density constants (eq. 5) sum over the neighbours across the faces.
  attach_periodic_images(state, parameters.support_radius);
  SimulationInfo info = simulation_info(case_file, "wcsph", D, options.arithmetic, parameters.dt);
  info.sound_speed = parameters.sound_speed;
  info.splitting = parameters.splitting;
  info.setup_report = std::move(setup_report);
  Model<D, Arith> model(parameters, std::move(info), std::move(state));
  model.initialise_density_constants(initial.target_density);
  return std::make_unique<ModelSimulation<Model<D, Arith>>>(std::move(model));
}

} // namespace

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options) {
  return with_dimension_and_arithmetic<1, 2, 3>(
      case_file, options.arithmetic,
      [&]<int D, class Arith>() { return create_in<D, Arith>(case_file, options); });
}

} // namespace revsph::wcsph
