// The optional irreversible operator of the WCSPH model: Monaghan's artificial viscosity
// (viscosity_term.hpp) over tau, placed around the reversible palindrome by step.splitting
// (core/step_splitting.hpp), with the kinetic energy it takes counted as dissipated. With
// physics.artificial_viscosity = 0 it does not act, and the step is the palindrome, bit for bit.
#include "core/verlet.hpp"
#include "models/wcsph/model.hpp"

#include <sstream>

namespace revsph::wcsph {

template <int D, class Arith>
std::span<const IrreversibleOperator<Model<D, Arith>>> Model<D, Arith>::irreversible_operators() {
  static constexpr IrreversibleOperator<Model> operators[] = {{"artificial_viscosity",
                                                               &Model::apply_artificial_viscosity,
                                                               &Model::artificial_viscosity_acts}};
  return operators;
}

template <int D, class Arith>
std::string Model<D, Arith>::artificial_viscosity_acts(const Model& model) {
  if (!model.viscosity_on()) {
    return "";
  }
  std::ostringstream text;
  text << "Monaghan's artificial viscosity (alpha = " << model.parameters_.artificial_viscosity
       << ", h = support radius / 2, approaching pairs, dummy particles at rest take part), the "
          "energy counted as dissipated";
  return text.str();
}

template <int D, class Arith>
void Model<D, Arith>::apply_artificial_viscosity(double tau) {
  if (!viscosity_on()) {
    return;
  }
  // The densities and the layout belong to the positions, which this operator leaves alone: they
  // stay valid for the kick that follows.
  update_derived();
  gather_slot_velocity(slot_velocity_);
  const ArtificialViscosityTerm<D> term{kernel_,
                                        slot_mass_,
                                        density_sums_.values(0),
                                        slot_velocity_,
                                        layout_.in(state_.fluid),
                                        parameters_.artificial_viscosity,
                                        parameters_.sound_speed,
                                        0.5 * parameters_.support_radius,
                                        tau};
  sum_pairs<Arith>(layout_, term, viscosity_sums_);
  // In fixed point the exact integer totals are added: equal and opposite pair increments leave
  // the fluid's momentum unchanged bit for bit (equal masses).
  FaultRecorder faults;
  const std::span<const std::uint32_t> fluid = layout_.slots_of(state_.fluid);
  add_pair_totals<Arith>(state_.fluid.velocity, viscosity_sums_, 0, fluid, faults);
  // The kinetic energy the applied increments dv changed, m dv . (v_after - dv / 2) per particle
  // (= m (v_after^2 - v_before^2) / 2 exactly in real numbers), summed exactly over the run.
  const auto mass = mass_of(state_.fluid);
  const auto& scale = state_.fluid.velocity.info().scale;
  ExactDoubleSum kinetic_change;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    double particle = 0.0;
    for (int k = 0; k < D; ++k) {
      const double dv = viscosity_sums_.value(k, fluid[i]);
      particle += dv * (Arith::real(state_.fluid.velocity.at(k, i), scale) - 0.5 * dv);
    }
    kinetic_change.add(mass[i] * particle);
  }
  dissipated_ -= global_total(kinetic_change);
}

template class Model<1, FixedArithmetic>;
template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<1, FloatArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::wcsph
