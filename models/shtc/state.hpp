#pragma once
// The state of an SHTC-SPH simulation, declared once (core/state_field.hpp). Fixed point only:
// the distortion's exact update (distortion.hpp) works on integers.
//
// Two particle sets. "material" particles move (eq. 47). "boundary" particles are held in place
// (the clamped base of the twisting column §4.2; no-slip and moving walls §4.3-4.4): they take part in every
// sum like material particles and their distortion evolves with the velocity gradient their
// moving neighbours give them, so the energy of eq. (24) summed over both sets is conserved and
// the step stays reversible (the paper resets velocities instead, which dissipates).

#include "core/state_field.hpp"

#include <algorithm>
#include <cstdint>

namespace revsph::shtc {

template <int D>
struct ParticleSetState {
  // The distortion A = exp(l / d) U (distortion.hpp): l = log det A and the unimodular U
  // (row-major, D * D components).
  StateField<std::int64_t> log_det;
  StateField<std::int64_t> unimodular;
  // Energy per mass removed by the relaxation so far (eqs. 51-53; zero for an elastic solid): with
  // it the energy budget closes in a dissipative case.
  StateField<std::int64_t> dissipated_energy;
  // Constants of the setup: masses and the integration constants C_rho (eq. 7), C_lambda (eq. 40).
  StateField<std::int64_t> mass;
  StateField<std::int64_t> density_constant;
  StateField<std::int64_t> lambda_constant;

  explicit ParticleSetState(const char* set)
      : log_det({set, "distortion_log_det", "1", Parity::even, 1, {}, true}),
        unimodular({set, "distortion_unimodular", "1", Parity::even, D * D, {}, true}),
        dissipated_energy({set, "dissipated_specific_energy", "J/kg", Parity::even, 1, {}, true}),
        mass({set, "mass", D == 2 ? "kg/m" : "kg", Parity::even, 1, {}, false}),
        density_constant({set, "density_constant", "kg/m^3", Parity::even, 1, {}, false}),
        lambda_constant({set, "lambda_constant", "kg/m^3", Parity::even, 1, {}, false}) {}

  template <class Visit>
  void for_each_field(Visit& visit) {
    visit(log_det);
    visit(unimodular);
    visit(dissipated_energy);
    visit(mass);
    visit(density_constant);
    visit(lambda_constant);
  }

  void resize(std::size_t count) {
    log_det.resize(count);
    unimodular.resize(count);
    dissipated_energy.resize(count);
    mass.resize(count);
    density_constant.resize(count);
    lambda_constant.resize(count);
  }
};

template <int D>
struct State {
  StateField<std::int64_t> position{{"material", "position", "m", Parity::even, D, {}, true}};
  StateField<std::int64_t> velocity{{"material", "velocity", "m/s", Parity::odd, D, {}, true}};
  ParticleSetState<D> material{"material"};
  StateField<std::int64_t> boundary_position{
      {"boundary", "position", "m", Parity::even, D, {}, false}};
  ParticleSetState<D> boundary{"boundary"};
  // Moving walls (the rotating ring of Taylor-Couette, the cavity's lid, §4.3-4.4) stay in place
  // and "pretend" a velocity in L (eq. 10), as the paper's lid does: the wall velocity at full
  // drive, and the signed time since the drive started. Time reversal negates drive_time, and the
  // velocity a wall pretends is wall_velocity * sign(drive_time) * ramp(|drive_time|): odd, so a
  // reversed run sees the walls move backwards and ramp down at the same instants (models/shtc/
  // README.md). Every boundary particle keeps its own copy of the clock (a set's fields share
  // one length); the drift advances them all alike.
  StateField<std::int64_t> wall_velocity{
      {"boundary", "wall_velocity", "m/s", Parity::even, D, {}, false}};
  StateField<std::int64_t> drive_time{{"boundary", "drive_time", "s", Parity::odd, 1, {}, true}};
  // Work per mass each moving wall particle has done on the rest (J/kg), accumulated in the
  // distortion sub-step (model.hpp): with it the energy budget of a driven case closes. Even: a
  // reversed step subtracts bit for bit what the forward step added.
  StateField<std::int64_t> wall_work{{"boundary", "wall_work", "J/kg", Parity::even, 1, {}, true}};

  template <class Visit>
  void for_each_field(Visit&& visit) {
    visit(position);
    visit(velocity);
    material.for_each_field(visit);
    visit(boundary_position);
    boundary.for_each_field(visit);
    visit(wall_velocity);
    visit(drive_time);
    visit(wall_work);
  }
};

// Whether any boundary particle is a moving wall.
template <int D>
bool any_wall_moves(const State<D>& state) {
  const auto velocities = state.wall_velocity.all();
  return std::any_of(velocities.begin(), velocities.end(), [](std::int64_t v) { return v != 0; });
}

} // namespace revsph::shtc
