// The irreversible sub-step of the two-fluid model (paper 5): the normal fluid's viscosity
// (eqs. 34, 39) and the mutual friction (eqs. 29, 35) as pair exchanges (dissipation_terms.hpp),
// with the energy they dissipate and the work of moving walls counted.
#include "core/verlet.hpp"
#include "models/two_fluid/model.hpp"

#include <sstream>

namespace revsph::two_fluid {

template <int D, class Arith>
std::string Model<D, Arith>::dissipation_acts(const Model& model) {
  const Parameters<D>& p = model.parameters_;
  std::ostringstream text;
  if (model.viscosity() > 0.0) {
    text << "normal-fluid viscosity (eta_bar + eta_r = " << model.viscosity() << " Pa s, "
         << (p.central_viscosity ? "central form" : "eqs. 34, 39");
    if (model.normal_pair_factor() != 1.0) {
      text << ", undiluted: normal pairs times N / N_n = " << model.normal_pair_factor();
    }
    text << ")";
  }
  if (p.mutual_friction.active()) {
    text << (text.tellp() > 0 ? " and " : "")
         << "mutual friction (eqs. 29, 35; C_L(0) = " << p.mutual_friction.coefficient(0.0)
         << " kg/(m^3 s)"
         << (p.mutual_friction.wall_at_initial_line_density ? ", held at the walls" : "") << ")";
  }
  if (p.contact.collision) {
    text << (text.tellp() > 0 ? " and " : "")
         << "pair collisions for r < dr (ref. [40], e = " << p.contact.restitution << ")";
  }
  if (p.contact.riemann) {
    text << (text.tellp() > 0 ? " and " : "")
         << "pairwise Riemann dissipation for r < dr (ref. [41])";
  }
  if (text.tellp() > 0) {
    text << ", the energy counted as dissipated";
  }
  return text.str();
}

template <int D, class Arith>
DissipationTerm<D> Model<D, Arith>::dissipation_term(double tau, double friction,
                                                     double wall_friction, bool contacts) {
  update_density();
  DissipationInputs& in = dissipation_inputs_;
  const std::size_t slots = layout_.slot_count();
  for (int k = 0; k < D; ++k) {
    in.velocity[k].resize(slots);
  }
  for_each_moving([&](const auto& kind, std::size_t set) {
    const std::span<const std::uint32_t> slot = layout_.slots_of_set(set);
    const std::span<const double> mass = layout_.part_of_set(std::span<const double>(mass_), set);
    const auto& p_scale = kind.momentum.info().scale;
    for (std::size_t i = 0; i < slot.size(); ++i) {
      for (int k = 0; k < D; ++k) {
        in.velocity[k][slot[i]] = Arith::real(kind.momentum.at(k, i), p_scale) / mass[i];
      }
    }
  });
  const std::span<const std::uint32_t> wall = layout_.slots_of(state_.wall);
  const auto& v_scale = state_.wall.velocity.info().scale;
  for (std::size_t i = 0; i < wall.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      in.velocity[k][wall[i]] = Arith::real(state_.wall.velocity.at(k, i), v_scale);
    }
  }
  const bool any_friction = friction > 0.0 || wall_friction > 0.0;
  if (any_friction) {
    // The weights move with the particles only: the density's layout is this sub-step's.
    sum_pairs<Arith>(layout_, NormalWeightTerm<D>{kernel_, in.superfluid}, normal_weight_sums_);
  }
  const Contact& contact = parameters_.contact;
  return DissipationTerm<D>{
      kernel_,
      in,
      inputs_.volume,
      inputs_.phase_volume,
      any_friction ? normal_weight_sums_.values(0) : std::span<const double>{},
      viscosity(),
      normal_pair_factor(),
      parameters_.central_viscosity,
      friction,
      wall_friction,
      {contacts ? parameters_.dr : 0.0, contact.collision, contact.restitution, contact.riemann,
       contact.limiter, parameters_.sound_speed, inputs_.mass, inputs_.density},
      tau};
}

template <int D, class Arith>
void Model<D, Arith>::dissipate(double tau) {
  const MutualFriction& mutual_friction = parameters_.mutual_friction;
  const double friction = mutual_friction.active() ? mutual_friction.coefficient(time_) : 0.0;
  const double wall_friction =
      mutual_friction.active() ? mutual_friction.wall_coefficient(time_) : 0.0;
  const Contact& contact = parameters_.contact;
  if (viscosity() == 0.0 && friction == 0.0 && wall_friction == 0.0 && !contact.any()) {
    return;
  }
  sum_pairs<Arith>(layout_, dissipation_term(tau, friction, wall_friction, contact.any()),
                   dissipation_sums_);
  FaultRecorder faults;
  for_each_moving([&](auto& kind, std::size_t set) {
    add_pair_totals<Arith>(kind.momentum, dissipation_sums_, 0, layout_.slots_of_set(set), faults);
  });
  faults.throw_if_any();
  // The accounts: the walls' work, and as dissipated what the sub-step took beyond it, the
  // kinetic energy its applied (rounded) impulses changed.
  const RunTotal wall_work = global_total_over_own_slots(
      layout_, [&](std::size_t s) { return dissipation_sums_.value(D, s); });
  const RunTotal kinetic_change = work_of_impulses(dissipation_sums_, 0);
  wall_work_ += wall_work;
  dissipated_ += wall_work - kinetic_change;
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::two_fluid
