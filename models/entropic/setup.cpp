#include "models/entropic/setup.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/case_values.hpp"
#include "core/dimension.hpp"
#include "core/particle_blocks.hpp"
#include "core/run_settings.hpp"
#include "core/state_fill.hpp"
#include "fixedpoint/conversion.hpp"
#include "models/entropic/model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>

namespace revsph::entropic {

namespace {

constexpr std::string_view particle_kinds[] = {"gas", "wall", "dummy", "thermal"};
// Memory per particle, generously: state (~(2 D + 2) * 8 B), slot copies, a dozen per-slot
// arrays (density, volume, thermodynamic state, force coefficients), the kernel and impulse sums
// and the cell list ~400 B, plus 4 B per neighbour in the lists and as much again while they are
// built (as models/wcsph/setup.cpp).

// initial.temperature_gradient and initial.temperature_perturbation: at the initial density
// T ∝ e^(sigma / c_V) for both gas laws (equation_of_state.hpp), so a temperature T is
// sigma = sigma0 + c_V ln(T / T0).
template <int D>
void apply_initial_temperature(const CaseFile& case_file, const Parameters<D>& parameters,
                               const std::vector<Vec<D>>& positions,
                               const std::vector<double>& masses, std::vector<double>& entropies) {
  const auto& gradient = parameters.initial_temperature_gradient;
  const double perturbation = parameters.initial_temperature_perturbation;
  if (perturbation == 0.0 &&
      std::all_of(gradient.begin(), gradient.end(), [](double g) { return g == 0.0; })) {
    return;
  }
  Vec<D> lowest = positions.front();
  Vec<D> highest = positions.front();
  for (const Vec<D>& x : positions) {
    for (int k = 0; k < D; ++k) {
      lowest[k] = std::min(lowest[k], x[k]);
      highest[k] = std::max(highest[k], x[k]);
    }
  }
  const double t0 = parameters.initial_temperature();
  const double sigma0 = parameters.initial_specific_entropy();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    double t = t0;
    for (int k = 0; k < D; ++k) {
      t += gradient[static_cast<std::size_t>(k)] *
           (positions[i][k] - 0.5 * (lowest[k] + highest[k]));
    }
    if (perturbation != 0.0) {
      const auto scaled = [&](int k) {
        const double width = highest[k] - lowest[k];
        return width > 0.0 ? (positions[i][k] - lowest[k]) / width : 0.5;
      };
      t += perturbation * dmath::cos(std::numbers::pi * scaled(0)) *
           dmath::sin(std::numbers::pi * scaled(D - 1));
    }
    if (!(t > 0.0)) {
      case_file.fail(
          perturbation != 0.0 ? "initial.temperature_perturbation" : "initial.temperature_gradient",
          "gives a temperature <= 0 K at a gas particle (T0 = " + format_scientific(t0, 3) + " K)");
    }
    entropies[i] = masses[i] * (sigma0 + parameters.heat_capacity() * dmath::log(t / t0));
  }
}

// initial.hydrostatic: every particle (gas, dummy, thermal) takes the density and specific
// entropy of the hydrostatic start at its own height (Parameters::hydrostatic_state), its mass
// scaled from rho_c to rho(y); the gas's seed roll (initial.temperature_perturbation) on top, at
// the particle's density.
template <int D>
void apply_hydrostatic_start(const CaseFile& case_file, const Parameters<D>& parameters,
                             const std::vector<Vec<D>>& gas_positions,
                             std::span<const std::vector<Vec<D>>* const> positions,
                             std::span<std::vector<double>* const> masses,
                             std::span<std::vector<double>* const> entropies) {
  double lowest = gas_positions.front()[D - 1];
  double highest = lowest;
  Vec<D> low = gas_positions.front();
  Vec<D> high = low;
  for (const Vec<D>& x : gas_positions) {
    for (int k = 0; k < D; ++k) {
      low[k] = std::min(low[k], x[k]);
      high[k] = std::max(high[k], x[k]);
    }
  }
  lowest = low[D - 1];
  highest = high[D - 1];
  const double centre = 0.5 * (lowest + highest);
  const double t0 = parameters.initial_temperature();
  const double gradient = parameters.initial_temperature_gradient[static_cast<std::size_t>(D - 1)];
  const double perturbation = parameters.initial_temperature_perturbation;
  for (std::size_t set = 0; set < positions.size(); ++set) {
    const bool gas = set == 0;
    for (std::size_t i = 0; i < positions[set]->size(); ++i) {
      const Vec<D>& x = (*positions[set])[i];
      const double z = x[D - 1] - centre;
      const auto state = parameters.hydrostatic_state(z);
      if (!state) {
        case_file.fail("initial.hydrostatic",
                       "no hydrostatic state of positive temperature and pressure + B at height " +
                           format_scientific(x[D - 1], 3) +
                           " m (raise initial.pressure or lower physics.gravity)");
      }
      double sigma = state->second;
      if (gas && perturbation != 0.0) {
        const auto scaled = [&](int k) {
          const double width = high[k] - low[k];
          return width > 0.0 ? (x[k] - low[k]) / width : 0.5;
        };
        const double t = t0 + gradient * z;
        const double seeded = t + perturbation * dmath::cos(std::numbers::pi * scaled(0)) *
                                      dmath::sin(std::numbers::pi * scaled(D - 1));
        if (!(seeded > 0.0)) {
          case_file.fail("initial.temperature_perturbation",
                         "gives a temperature <= 0 K at a gas particle");
        }
        sigma += parameters.heat_capacity() * dmath::log(seeded / t);
      }
      double& m = (*masses[set])[i];
      m *= state->first / parameters.initial_density;
      (*entropies[set])[i] = m * sigma;
    }
  }
}

std::string scientific(double value) {
  return format_scientific(value, 6);
}

template <int D>
std::unique_ptr<Simulation> create_in(const CaseFile& case_file, const SimulationOptions& options) {
  const Parameters<D> parameters = read_parameters<D>(case_file);
  const double reach = parameters.support_radius / parameters.dr; // support radius over dr
  const auto blocks =
      read_particle_blocks<D>(case_file, parameters.dr, parameters.domain, particle_kinds,
                              particle_budget(D, reach, 400.0, options.memory_budget_bytes));
  // Gas particles in block order, at rest, each with the mass rho times its lattice cell volume
  // and the entropy S = m sigma of the initial state (eq. 21 with uniform sigma).
  const double specific_entropy = parameters.initial_specific_entropy();
  // Dummy particles get the same mass and entropy per lattice cell.
  // Thermal particles get the gas's entropy, like dummies: their pressure, which holds the gas
  // off the wall, is then the gas's. (The entropy of their held temperature would give the
  // stiffened gas of the cavity cases a pressure of -47 at a cooler: it sucked the gas in.) Only
  // the conduction sees their held temperature.
  std::vector<Vec<D>> gas_positions, wall_positions, dummy_positions, thermal_positions;
  std::vector<double> gas_masses, gas_entropies, dummy_masses, dummy_entropies;
  std::vector<double> thermal_masses, thermal_entropies, thermal_temperatures;
  for (const auto& block : blocks) {
    const std::string temperature_key = block.key + ".temperature";
    if (block.kind != "thermal" && case_file.has(temperature_key)) {
      case_file.fail(temperature_key, "only for kind = \"thermal\" (a wall held at a temperature)");
    }
    if (block.kind == "wall") {
      wall_positions.insert(wall_positions.end(), block.positions.begin(), block.positions.end());
      continue;
    }
    if (block.kind == "thermal") {
      const double held = case_file.positive_number(temperature_key);
      require_positive_finite(
          case_file, temperature_key.c_str(),
          "4 max(T_w, T0) / dr^D, the scale of the wall temperature sums",
          wall_temperature_sum_magnitude<D>(held, parameters.initial_temperature(), parameters.dr));
      const double mass = parameters.initial_density * block.volume_per_particle;
      thermal_positions.insert(thermal_positions.end(), block.positions.begin(),
                               block.positions.end());
      thermal_masses.insert(thermal_masses.end(), block.positions.size(), mass);
      thermal_entropies.insert(thermal_entropies.end(), block.positions.size(),
                               mass * specific_entropy);
      thermal_temperatures.insert(thermal_temperatures.end(), block.positions.size(), held);
      continue;
    }
    const bool dummy = block.kind == "dummy";
    std::vector<Vec<D>>& positions = dummy ? dummy_positions : gas_positions;
    std::vector<double>& masses = dummy ? dummy_masses : gas_masses;
    std::vector<double>& entropies = dummy ? dummy_entropies : gas_entropies;
    const double mass = parameters.initial_density * block.volume_per_particle;
    positions.insert(positions.end(), block.positions.begin(), block.positions.end());
    masses.insert(masses.end(), block.positions.size(), mass);
    entropies.insert(entropies.end(), block.positions.size(), mass * specific_entropy);
  }
  if (gas_positions.empty()) {
    case_file.fail("particles", "the case has no gas particles");
  }
  if (parameters.initial_hydrostatic) {
    const std::vector<Vec<D>>* positions[] = {&gas_positions, &dummy_positions, &thermal_positions};
    std::vector<double>* masses[] = {&gas_masses, &dummy_masses, &thermal_masses};
    std::vector<double>* entropies[] = {&gas_entropies, &dummy_entropies, &thermal_entropies};
    apply_hydrostatic_start<D>(case_file, parameters, gas_positions, positions, masses, entropies);
  } else {
    apply_initial_temperature<D>(case_file, parameters, gas_positions, gas_masses, gas_entropies);
  }
  const fixedpoint::Scale masses =
      mass_scale(case_file, "initial.density", {gas_masses, dummy_masses, thermal_masses});

  State<D> state;
  const double hottest_wall =
      thermal_temperatures.empty()
          ? 1.0
          : *std::max_element(thermal_temperatures.begin(), thermal_temperatures.end());
  set_scales(state, {{"position", parameters.position_scale},
                     {"momentum", parameters.momentum_scale},
                     {"entropy", parameters.entropy_scale},
                     {"mass", masses},
                     {"entropy_flux", parameters.entropy_flux_scale},
                     {"temperature", fixedpoint::Scale::covering(hottest_wall, 52)}});
  // The gas at rest, its entropy flux w = 0.
  fill_set<FixedArithmetic, D>(case_file, state.gas, gas_positions.size(),
                               {{"position", "particles", gas_positions},
                                {"momentum", "particles", 0.0},
                                {"entropy_flux", "particles", 0.0},
                                {"entropy", "fixed_point.entropy_exponent", gas_entropies},
                                {"mass", "initial.density", gas_masses}});
  fill_set<FixedArithmetic, D>(case_file, state.wall, wall_positions.size(),
                               {{"position", "particles", wall_positions}});
  fill_set<FixedArithmetic, D>(case_file, state.dummy, dummy_positions.size(),
                               {{"position", "particles", dummy_positions},
                                {"entropy", "fixed_point.entropy_exponent", dummy_entropies},
                                {"mass", "initial.density", dummy_masses}});
  fill_set<FixedArithmetic, D>(case_file, state.thermal, thermal_positions.size(),
                               {{"position", "particles", thermal_positions},
                                {"entropy", "fixed_point.entropy_exponent", thermal_entropies},
                                {"mass", "initial.density", thermal_masses},
                                {"temperature", "particles", thermal_temperatures}});

  SimulationInfo info = simulation_info(case_file, "entropic", D, Arithmetic::fixed, parameters.dt);
  info.splitting = parameters.splitting;
  info.sound_speed = parameters.initial_sound_speed();
  info.setup_report.emplace_back("dt", scientific(parameters.dt));
  info.setup_report.emplace_back("initial_sound_speed",
                                 scientific(parameters.initial_sound_speed()));
  info.setup_report.emplace_back("initial_specific_entropy", scientific(specific_entropy));
  Model<D> model(parameters, std::move(info), std::move(state));
  return std::make_unique<ModelSimulation<Model<D>>>(std::move(model));
}

} // namespace

std::unique_ptr<Simulation> create(const CaseFile& case_file, const SimulationOptions& options) {
  return with_dimension<1, 2, 3>(case_file,
                                 [&]<int D>() { return create_in<D>(case_file, options); });
}

} // namespace revsph::entropic
