// Entropic SPH's dissipation (paper 4 §5.1-5.2): the update that the core places by the case's
// splitting (core/step_splitting.hpp), and its declaration as an irreversible term (its pair
// terms: dissipation_terms.hpp).

#include "core/case_values.hpp"
#include "core/particle_update.hpp"
#include "fixedpoint/deterministic_math.hpp"
#include "models/entropic/dissipation_terms.hpp"
#include "models/entropic/model.hpp"

#include <cmath>

namespace revsph::entropic {

template <int D>
std::string Model<D>::dissipation_description(const Model& model) {
  // "viscosity and heat conduction (mu = ..., eq. 60; lambda_F = ..., eqs. 51-56)": the short
  // name first (the verifier's verdict cuts at the parenthesis); "" without dissipation.
  const Parameters<D>& p = model.parameters_;
  if (!p.dissipative()) {
    return "";
  }
  std::string names;
  std::string details;
  if (p.viscosity > 0.0) {
    names = "viscosity";
    details = "mu = " + format_scientific(p.viscosity, 3) + ", eq. 60";
  }
  if (p.heat_conductivity > 0.0) {
    names += (names.empty() ? "" : " and ") + std::string("heat conduction");
    details += (details.empty() ? "" : "; ") + std::string("lambda_F = ") +
               format_scientific(p.heat_conductivity, 3) +
               (p.conduction == HeatConduction::two_pass ? ", eqs. 51-56" : ", pairwise");
  }
  return names + " (" + details + ")";
}

template <int D>
void Model<D>::dissipate(double tau) {
  update_geometry();
  const std::size_t n = layout_.slot_count();
  const std::span<const std::uint32_t> slots = layout_.slots_of(state_.gas);
  Field& momentum = state_.gas.momentum;
  Field& entropy = state_.gas.entropy;
  const fixedpoint::Scale& m_scale = momentum.info().scale;
  const std::span<const double> gas_mass = of_gas(mass_);
  const bool two_pass =
      parameters_.heat_conductivity > 0.0 && parameters_.conduction == HeatConduction::two_pass;
  for (int k = 0; k < D; ++k) {
    slot_velocity_[k].assign(n, 0.0); // the walls: at rest, or mirrored below
    slot_heat_flux_[k].resize(two_pass ? n : 0);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < slots.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      slot_velocity_[k][slots[i]] = fixedpoint::to_real(momentum.at(k, i), m_scale) / gas_mass[i];
    }
  }
  // The temperature conduction sees: the gas's own; a thermal wall's held one, mirrored across
  // the wall by the gas near it; and with no-slip walls the walls' velocities, mirrored too
  // (dissipation_terms.hpp, WallMirrorTerm).
  conduction_temperature_.resize(n);
  const SlotInSet is_gas = layout_.in(state_.gas);
  const SlotInSet is_thermal = layout_.in(state_.thermal);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    conduction_temperature_[s] = is_gas(s) ? temperature_[s] : slot_held_temperature_[s];
  }
  const bool mirror_temperature = parameters_.heat_conductivity > 0.0 && has_thermal_walls_;
  const bool mirror_velocity = parameters_.no_slip_walls && parameters_.viscosity > 0.0;
  if (mirror_temperature || mirror_velocity) {
    // Each wall slot's own entries only: the pass reads the gas's temperatures and velocities.
    const auto mirror = [&](std::uint32_t s) {
      const double weight = wall_mirror_sums_.value(D + 1, s);
      if (is_gas(s) || !(weight > 0.0)) {
        return;
      }
      if (mirror_temperature && is_thermal(s)) {
        conduction_temperature_[s] =
            2.0 * slot_held_temperature_[s] - wall_mirror_sums_.value(0, s) / weight;
      }
      if (mirror_velocity) {
        for (int k = 0; k < D; ++k) {
          slot_velocity_[k][s] = -wall_mirror_sums_.value(1 + k, s) / weight;
        }
      }
    };
    sum_pairs<FixedArithmetic>(
        layout_, WallMirrorTerm<D>{kernel_, temperature_, slot_velocity_, layout_.in(state_.gas)},
        wall_mirror_sums_, {}, mirror);
  }
  if (two_pass) {
    const auto keep = [this](std::uint32_t s) {
      for (int k = 0; k < D; ++k) {
        slot_heat_flux_[k][s] = heat_flux_sums_.value(k, s);
      }
    };
    sum_pairs<FixedArithmetic>(layout_,
                               HeatFluxTerm<D>{kernel_, parameters_.heat_conductivity, volume_,
                                               conduction_temperature_,
                                               layout_.in(state_.gas, state_.thermal)},
                               heat_flux_sums_, {}, keep);
  }
  const double h = parameters_.support_radius;
  sum_pairs<FixedArithmetic>(
      layout_,
      DissipationTerm<D>{kernel_, tau, parameters_.viscosity, 0.01 * h * h,
                         parameters_.no_slip_walls, volume_, slot_velocity_, slot_heat_flux_,
                         layout_.in(state_.gas), layout_.in(state_.gas, state_.thermal),
                         two_pass ? 0.0 : parameters_.heat_conductivity, conduction_temperature_},
      dissipation_sums_);
  // Per particle: the exact impulse sum onto the momentum; then the heat, less the kinetic
  // energy the impulses themselves carry (sum_b tau P_ab / 2 - |J_a|^2 / (2 m_a): these add up
  // to the kinetic energy the viscosity removes), into the entropy at fixed density:
  // dS = m c_V ln(1 + heat / (m c_V T)) for both gas laws (derivations.md §4.5). The entropy
  // increment is rounded up, so that rounding never lowers the total entropy.
  const double heat_capacity = parameters_.heat_capacity();
  const fixedpoint::Scale& s_scale = entropy.info().scale;
  update_each_particle(
      entropy, "overflow or non-finite value in the dissipation", [&](std::size_t i) {
        const std::uint32_t s = slots[i];
        double impulse_squared = 0.0;
        bool fits = true;
        for (int k = 0; k < D; ++k) {
          const std::int64_t impulse = dissipation_sums_.raw_total(k, s);
          const double real_impulse = fixedpoint::to_real(impulse, m_scale);
          impulse_squared += real_impulse * real_impulse;
          fits = fits && fixedpoint::try_add(momentum.at(k, i), impulse, momentum.at(k, i));
        }
        const double heat = dissipation_sums_.value(D, s) - 0.5 * impulse_squared / gas_mass[i];
        const double thermal = gas_mass[i] * heat_capacity * temperature_[s];
        const double change = gas_mass[i] * heat_capacity * dmath::log1p(heat / thermal);
        std::int64_t increment = 0;
        return fits && fixedpoint::try_round_up_to_fixed(change, s_scale, increment) &&
               fixedpoint::try_add(entropy.at(0, i), increment, entropy.at(0, i));
      });
  // The heat the thermal walls took in (exact sums of exact per-particle totals: the same for
  // any thread or process count).
  const double reference = parameters_.initial_temperature();
  ExactDoubleSum heat_in, entropy_in, hot_out, cold_in;
  for (const std::uint32_t s : layout_.slots_of(state_.thermal)) {
    const double heat = dissipation_sums_.value(D, s);
    heat_in.add(heat);
    entropy_in.add(heat / slot_held_temperature_[s]);
    if (slot_held_temperature_[s] > reference) {
      hot_out.add(-heat);
    } else if (slot_held_temperature_[s] < reference) {
      cold_in.add(heat);
    }
  }
  wall_heat_ += global_total(heat_in);
  wall_entropy_ += global_total(entropy_in);
  hot_wall_heat_out_ += global_total(hot_out);
  cold_wall_heat_in_ += global_total(cold_in);
  geometry_valid_ = false;
}

#define REVSPH_ENTROPIC_DISSIPATION(D)                                                             \
  template std::string Model<D>::dissipation_description(const Model&);                            \
  template void Model<D>::dissipate(double);
REVSPH_ENTROPIC_DISSIPATION(1)
REVSPH_ENTROPIC_DISSIPATION(2)
REVSPH_ENTROPIC_DISSIPATION(3)
#undef REVSPH_ENTROPIC_DISSIPATION

} // namespace revsph::entropic
