// The two-fluid model's energy budget and its physical views for snapshots.
#include "models/two_fluid/model.hpp"

#include <stdexcept>

namespace revsph::two_fluid {

template <int D, class Arith>
EnergyBudget Model<D, Arith>::energy() {
  update_density();
  const ImpulseInputs& in = inputs_;
  // Exact sums (core/global_totals.hpp): the same value for any thread or process count.
  ExactDoubleSum kinetic, gravitational;
  for_each_moving([&](const auto& kind, std::size_t set) {
    const std::span<const double> mass = layout_.part_of_set(std::span<const double>(mass_), set);
    const auto& p_scale = kind.momentum.info().scale;
    const auto& x_scale = kind.position.info().scale;
    for (std::size_t i = 0; i < mass.size(); ++i) {
      double p_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double p = Arith::real(kind.momentum.at(k, i), p_scale);
        p_squared += p * p;
      }
      kinetic.add(0.5 * p_squared / mass[i]);
      const double y = Arith::real(kind.position.at(D - 1, i), x_scale);
      gravitational.add(mass[i] * parameters_.gravity * (y - parameters_.gravity_reference_height));
    }
  });
  // Every particle's m e(rho), walls included.
  const RunTotal internal = global_total_over_own_slots(layout_, [&](std::size_t s) {
    return in.mass[s] * internal_energy(in.density[s], slot_rest_density_[s]);
  });
  return EnergyBudget{{{"kinetic", global_total(kinetic)},
                       {"internal", internal},
                       {"gravitational", global_total(gravitational)},
                       {"dissipated", dissipated_},
                       {"wall_work", -wall_work_},
                       {"force_work", -force_work_}}};
}

template <int D, class Arith>
template <class Value>
void Model<D, Arith>::moving_vector_views(const ViewSink& sink, const char* name, const char* unit,
                                          const Value& value) {
  for_each_moving([&](const auto& kind, std::size_t set) {
    const std::span<const std::uint32_t> slots = layout_.slots_of_set(set);
    const std::span<const double> mass = layout_.part_of_set(std::span<const double>(mass_), set);
    const std::size_t n = slots.size();
    std::vector<double> values(D * n);
    for (int k = 0; k < D; ++k) {
      for (std::size_t i = 0; i < n; ++i) {
        values[k * n + i] = value(kind, k, i, slots[i], mass[i]);
      }
    }
    sink(ParticleView{std::string(layout_.sets()[set].name), name, unit, D, std::move(values)});
  });
}

template <int D, class Arith>
void Model<D, Arith>::derived_views(const ViewSink& sink) {
  update_density();
  const ImpulseInputs& in = inputs_;
  auto density_and_pressure = [&](std::size_t set) {
    const std::string name = layout_.sets()[set].name;
    const std::span<const std::uint32_t> slots = layout_.slots_of_set(set);
    std::vector<double> density(slots.size()), pressure(slots.size());
    for (std::size_t i = 0; i < slots.size(); ++i) {
      density[i] = in.density[slots[i]];
      pressure[i] = in.pressure[slots[i]];
    }
    sink(ParticleView{name, "density", "kg/m^3", 1, std::move(density)});
    sink(ParticleView{name, "pressure", "Pa", 1, std::move(pressure)});
  };
  for_each_moving([&](const auto&, std::size_t set) { density_and_pressure(set); });
  moving_vector_views(sink, "velocity", "m/s",
                      [](const auto& kind, int k, std::size_t i, std::uint32_t, double mass) {
                        return Arith::real(kind.momentum.at(k, i), kind.momentum.info().scale) /
                               mass;
                      });
  density_and_pressure(layout_.index_of(state_.wall));
  if (spin_on()) {
    spin_force_views(sink);
  }
  if (viscosity() > 0.0) {
    viscosity_views(sink);
  }
}

template <int D, class Arith>
void Model<D, Arith>::viscosity_views(const ViewSink& sink) {
  // Eq. (34)'s viscosity term (with eq. 39's eta_bar + eta_r, as the dissipate sub-step applies
  // it) on each fluid particle, as an acceleration (Fig. 5(b)): the dissipation's pair term over
  // one time step with the friction and the contact terms off, summed exactly at the momentum's
  // scale like the sub-step's own sums (the same bits for any decomposition), divided by dt.
  const double dt = this->info_.dt;
  PairSums<Arith, D + 1> sums(dissipation_sums_.quantities());
  sum_pairs<Arith>(layout_, dissipation_term(dt, 0.0, 0.0, /*contacts=*/false), sums);
  moving_vector_views(sink, "viscous_acceleration", "m/s^2",
                      [&](const auto&, int k, std::size_t, std::uint32_t slot, double mass) {
                        return sums.value(k, slot) / (mass * dt);
                      });
}

template <int D, class Arith>
void Model<D, Arith>::spin_force_views(const ViewSink& sink) {
  // Eq. (40)'s spin force on each fluid particle (Fig. 10): the accounted components of the
  // impulses over one time step with only the spin term among the non-gradient forces, summed
  // exactly at the momentum's scale like the kick's own sums (the same bits for any
  // decomposition), divided by dt. The state never sees these sums.
  const Parameters<D>& p = parameters_;
  const double dt = this->info_.dt;
  PairSums<Arith, 2 * D> sums(counted_impulse_sums_.quantities());
  sum_pairs<Arith>(layout_,
                   ImpulseTerm<D, true>{kernel_, inputs_, p.pressure_form, p.rotational_viscosity,
                                        p.gravity, dt, /*thermomechanical_on=*/false,
                                        /*spin_on=*/true},
                   sums);
  moving_vector_views(sink, "spin_force", D == 2 ? "N/m" : "N",
                      [&](const auto&, int k, std::size_t, std::uint32_t slot, double) {
                        return sums.value(D + k, slot) / dt;
                      });
}

template class Model<2, FixedArithmetic>;
template class Model<3, FixedArithmetic>;
template class Model<2, FloatArithmetic>;
template class Model<3, FloatArithmetic>;

} // namespace revsph::two_fluid
