#pragma once
// The worked example of docs/adding-a-model.md: a complete reversible SPH model in a state table,
// one pair term and a kick-drift-kick palindrome. A barotropic gas, p = K rho^gamma, held in a
// harmonic trap, with the summation density rho_a = sum_b m_b W_ab and the symmetric pressure
// force
//   dv_a/dt = -sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) grad W_ab - omega^2 x_a
// (Monaghan 1992, eq. 3.3), which is -grad of sum_a m_a (e(rho_a) + omega^2 |x_a|^2 / 2),
// e = K rho^(gamma - 1) / (gamma - 1). Everything else (snapshots, hashes, the time reversal, the
// verifier) comes from the core. tests/system/minimal_model_test.cpp builds and reverses it.

#include "core/model_api.hpp"
#include "core/summation_density.hpp"
#include "core/units.hpp"
#include "core/verlet.hpp"

#include <cmath>
#include <tuple>

namespace revsph::minimal {

// The state table: one particle set, each field with its unit and parity under time reversal.
template <int D>
struct Gas {
  static constexpr SetInfo set{.name = "gas", .motion = Motion::moving};
  StateField<std::int64_t> position{position_field<D>()};
  StateField<std::int64_t> velocity{
      {.name = "velocity", .unit = "m/s", .parity = Parity::odd, .components = D}};
  StateField<std::int64_t> mass{mass_field<D>()};
  StateField<std::int64_t> density_constant{density_constant_field()};
  auto fields() { return std::tie(position, velocity, mass, density_constant); }
};

template <int D>
struct State {
  Gas<D> gas;
  State() { declare_state(*this); }
  auto sets() { return std::tie(gas); }
};

// The one pair term: the symmetric pressure force, for both particles of a pair.
template <int D>
struct PressureForce {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;                 // by slot
  std::span<const double> pressure_over_rho_sq; // by slot
  CoordinateView<D> x;                          // by slot
  double omega_squared;

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    const double f =
        -(pressure_over_rho_sq[p.a] + pressure_over_rho_sq[p.b]) * kernel.derivative_over_r(p.r);
    for (int k = 0; k < D; ++k) {
      to_a[k] = mass[p.b] * f * p.x_ab[k];
      to_b[k] = -mass[p.a] * f * p.x_ab[k];
    }
  }
  // The trap acts on each particle alone.
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    for (int k = 0; k < D; ++k) {
      add(k, -omega_squared * x[k][s]);
    }
  }
};

struct Settings {
  double support_radius = 0.0;
  double stiffness = 1.0; // K
  double gamma = 1.4;
  double trap_frequency = 10.0; // omega, 1/s
  fixedpoint::Scale density_scale{-40}, acceleration_scale{-30};
};

template <int D>
class Model : public ModelParts<Settings, State<D>> {
  using Parts = ModelParts<Settings, State<D>>;
  using Parts::parameters_;
  using Parts::state_;

public:
  Model(const Box<D>& domain, Settings settings, SimulationInfo info, State<D> state)
      : Parts(settings, std::move(info), std::move(state)), kernel_(settings.support_radius),
        layout_(domain, settings.support_radius, carrier_sets(state_.gas)),
        density_sums_(SummedQuantity{"density", settings.density_scale}),
        force_sums_(components_of<D>("acceleration", settings.acceleration_scale)) {}

  static std::span<const Substep<Model>> palindrome() { return kick_drift_kick<Model>(); }
  void invalidate_derived() { forces_valid_ = false; }

  EnergyBudget energy() {
    update_forces();
    // Exact sums, completed over the run by global_total (core/global_totals.hpp).
    ExactDoubleSum kinetic, internal, trap;
    const double omega_squared = parameters_.trap_frequency * parameters_.trap_frequency;
    const auto slots = layout_.slots_of(state_.gas);
    for (std::size_t i = 0; i < slots.size(); ++i) {
      const double m = mass_[slots[i]];
      for (int k = 0; k < D; ++k) {
        const double v = real(state_.gas.velocity, k, i);
        kinetic.add(0.5 * m * v * v);
        const double x = real(state_.gas.position, k, i);
        trap.add(0.5 * m * omega_squared * x * x);
      }
      const double rho = density_sums_.value(0, slots[i]);
      internal.add(m * parameters_.stiffness * std::pow(rho, parameters_.gamma - 1.0) /
                   (parameters_.gamma - 1.0));
    }
    return EnergyBudget{{{"kinetic", global_total(kinetic)},
                         {"internal", global_total(internal)},
                         {"trap", global_total(trap)}}};
  }
  void derived_views(const ViewSink& sink) {
    update_forces();
    const auto rho = layout_.in_set_order(density_sums_.values(0), state_.gas);
    std::vector<double> values(rho.size());
    for (std::size_t i = 0; i < rho.size(); ++i) {
      values[i] = rho[i];
    }
    sink(ParticleView{"gas", "density", "kg/m^3", 1, std::move(values)});
  }

private:
  static double real(const StateField<std::int64_t>& field, int k, std::size_t i) {
    return fixedpoint::to_real(field.at(k, i), field.info().scale);
  }
  // Both pair sums at the current positions: the density, then the force.
  void update_forces() {
    if (forces_valid_) {
      return;
    }
    const CarrierField<FixedArithmetic> mass{&state_.gas.mass};
    const CarrierField<FixedArithmetic> constant{&state_.gas.density_constant};
    layout_.build(CarrierField<FixedArithmetic>{&state_.gas.position}, parameters_.support_radius,
                  Gathered{[&](std::size_t c) { return mass.real(0, c); }, &mass_},
                  Gathered{[&](std::size_t c) { return constant.raw(0, c); }, &constant_});
    pressure_over_rho_sq_.resize(layout_.slot_count());
    sum_pairs<FixedArithmetic>(
        layout_, SummationDensityTerm<D, FixedArithmetic>{kernel_, mass_, constant_}, density_sums_,
        {}, [&](std::uint32_t s) {
          const double rho = density_sums_.value(0, s);
          pressure_over_rho_sq_[s] = parameters_.stiffness * std::pow(rho, parameters_.gamma - 2.0);
        });
    const double omega_squared = parameters_.trap_frequency * parameters_.trap_frequency;
    sum_pairs<FixedArithmetic>(
        layout_,
        PressureForce<D>{kernel_, mass_, pressure_over_rho_sq_, layout_.position(), omega_squared},
        force_sums_);
    forces_valid_ = true;
  }

public:
  // The sub-steps (public: core's kick_drift_kick names them).
  // v += dt a(x): exact in integers, and undone bit for bit after the time reversal.
  void kick(double dt) {
    update_forces();
    const auto slots = layout_.slots_of(state_.gas);
    FaultRecorder faults;
    add_rate<FixedArithmetic>(
        state_.gas.velocity, [&](int k, std::size_t i) { return force_sums_.value(k, slots[i]); },
        dt, faults);
  }
  // x += dt v.
  void drift(double dt) {
    FaultRecorder faults;
    revsph::drift<FixedArithmetic>(state_.gas.position, state_.gas.velocity, dt, faults);
    forces_valid_ = false;
  }

private:
  WendlandQuintic<D> kernel_;
  SlotLayout<D> layout_;
  bool forces_valid_ = false;
  std::vector<double> mass_, pressure_over_rho_sq_;
  std::vector<std::int64_t> constant_;
  PairSums<FixedArithmetic, 1> density_sums_;
  PairSums<FixedArithmetic, D> force_sums_;
};

} // namespace revsph::minimal
