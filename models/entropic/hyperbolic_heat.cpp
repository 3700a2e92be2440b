// Entropic SPH's Lagrangian hyperbolic heat conduction (paper 4 §5.5) as sub-steps of the model:
// the reversible exchange of eq. (68) between the entropies S and the entropy-flux variable w,
// and the relaxation of eq. (69). Pair terms: hyperbolic_heat_terms.hpp.

#include "core/case_values.hpp"
#include "core/particle_update.hpp"
#include "core/verlet.hpp"
#include "fixedpoint/deterministic_math.hpp"
#include "models/entropic/hyperbolic_heat_terms.hpp"
#include "models/entropic/model.hpp"

#include <cmath>

namespace revsph::entropic {

template <int D>
void Model<D>::flux_substep(double dt) {
  if (parameters_.hyperbolic()) {
    exchange_flux(dt);
  }
}

template <int D>
void Model<D>::entropy_exchange_substep(double dt) {
  if (parameters_.hyperbolic()) {
    exchange_entropy(dt);
  }
}

template <int D>
std::string Model<D>::relaxation_description(const Model& model) {
  const Parameters<D>& p = model.parameters_;
  return p.relaxing() ? "relaxation of the entropy flux w into heat (tau = " +
                            format_scientific(p.relaxation_time, 3) + " s, eq. 69)"
                      : "";
}

template <int D>
void Model<D>::exchange_flux(double dt) {
  // (68b): w_a += dt sum_b V_b (T_a - T_b) W'_ab e_ab, each pair's share rounded once. It reads
  // S and x only, so the same sub-step run on -w takes back bit for bit what it added.
  update_geometry();
  sum_pairs<FixedArithmetic>(
      layout_, FluxExchangeTerm<D>{kernel_, dt, volume_, temperature_, layout_.in(state_.gas)},
      flux_sums_);
  FaultRecorder faults;
  add_pair_totals<FixedArithmetic>(state_.gas.entropy_flux, flux_sums_, 0,
                                   layout_.slots_of(state_.gas), faults); // eq. (68b)
}

template <int D>
void Model<D>::exchange_entropy(double dt) {
  // (68a): S_a += dt J_a with J_ab = -2 c_w V_a V_b (w_a + w_b) . W'_ab e_ab, antisymmetric per
  // pair and odd in w: the total entropy is kept bit for bit, and the sub-step run on -w undoes
  // this one.
  update_geometry();
  const std::span<const std::uint32_t> slots = layout_.slots_of(state_.gas);
  const Field& flux = state_.gas.entropy_flux;
  const std::size_t n = layout_.slot_count();
  for (int k = 0; k < D; ++k) {
    slot_flux_[k].assign(n, 0.0);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < slots.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      slot_flux_[k][slots[i]] = fixedpoint::to_real(flux.at(k, i), flux.info().scale);
    }
  }
  sum_pairs<FixedArithmetic>(layout_,
                             EntropyExchangeTerm<D>{kernel_, dt,
                                                    parameters_.flux_energy_coefficient, volume_,
                                                    slot_flux_, layout_.in(state_.gas)},
                             entropy_exchange_sums_);
  FaultRecorder faults;
  add_pair_totals<FixedArithmetic>(state_.gas.entropy, entropy_exchange_sums_, 0, slots,
                                   faults); // eq. (68a)
  geometry_valid_ = false;                  // the temperatures follow the entropies
}

template <int D>
void Model<D>::relax_flux(double dt) {
  // (69) solved exactly over dt at fixed volume: w decays as e^(-2 c_w V dt / tau); the energy
  // it loses, c_w V (|w|^2 - |w'|^2) computed from the stored values, becomes heat at fixed
  // density, dS = m c_V ln(1 + heat / (m c_V T)) (derivations.md §4.5, §5.1), rounded up so that
  // rounding never lowers the entropy.
  update_geometry();
  const std::span<const std::uint32_t> slots = layout_.slots_of(state_.gas);
  const std::span<const double> gas_mass = of_gas(mass_);
  Field& flux = state_.gas.entropy_flux;
  Field& entropy = state_.gas.entropy;
  const fixedpoint::Scale& w_scale = flux.info().scale;
  const double heat_capacity = parameters_.heat_capacity();
  const double c_w = parameters_.flux_energy_coefficient;
  update_each_particle(
      entropy, "overflow or non-finite value in the relaxation", [&](std::size_t i) {
        const std::uint32_t s = slots[i];
        const double decay = dmath::exp(-2.0 * c_w * volume_[s] * dt / parameters_.relaxation_time);
        double before = 0.0;
        double after = 0.0;
        bool fits = true;
        for (int k = 0; k < D; ++k) {
          const double w = fixedpoint::to_real(flux.at(k, i), w_scale);
          std::int64_t decayed = 0;
          fits = fits && fixedpoint::try_to_fixed(w * decay, w_scale, decayed);
          const double w_after = fixedpoint::to_real(decayed, w_scale);
          before += w * w;
          after += w_after * w_after;
          flux.at(k, i) = decayed;
        }
        const double heat = c_w * volume_[s] * (before - after);
        const double thermal = gas_mass[i] * heat_capacity * temperature_[s];
        std::int64_t increment = 0;
        return fits &&
               fixedpoint::try_round_up_to_fixed(gas_mass[i] * heat_capacity *
                                                     dmath::log1p(heat / thermal),
                                                 entropy.info().scale, increment) &&
               fixedpoint::try_add(entropy.at(0, i), increment, entropy.at(0, i));
      });
  geometry_valid_ = false;
}

#define REVSPH_ENTROPIC_HYPERBOLIC_HEAT(D)                                                         \
  template void Model<D>::flux_substep(double);                                                    \
  template void Model<D>::entropy_exchange_substep(double);                                        \
  template std::string Model<D>::relaxation_description(const Model&);                             \
  template void Model<D>::exchange_flux(double);                                                   \
  template void Model<D>::exchange_entropy(double);                                                \
  template void Model<D>::relax_flux(double);
REVSPH_ENTROPIC_HYPERBOLIC_HEAT(1)
REVSPH_ENTROPIC_HYPERBOLIC_HEAT(2)
REVSPH_ENTROPIC_HYPERBOLIC_HEAT(3)
#undef REVSPH_ENTROPIC_HYPERBOLIC_HEAT

} // namespace revsph::entropic
