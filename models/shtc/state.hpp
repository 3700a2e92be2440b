#pragma once
// The state of an SHTC-SPH simulation, declared once (core/particle_sets.hpp). Fixed point only:
// the distortion's exact update (distortion.hpp) works on integers.
//
// Two particle sets. "material" particles move (eq. 47). "boundary" particles are held in place
// (the clamped base of the twisting column §4.2; no-slip and moving walls §4.3-4.4): they take
// part in every sum like material particles and their distortion evolves with the velocity
// gradient their moving neighbours give them, so the energy of eq. (24) summed over both sets is
// conserved and the step stays reversible (the paper resets velocities instead, which dissipates).

#include "core/common_fields.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"
#include "core/units.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>

namespace revsph::shtc {

using Field = StateField<std::int64_t>;

// What every carrier of the pair sums (material and boundary particle) carries.
template <int D>
struct CarrierFields {
  // The distortion A = exp(l / d) U (distortion.hpp): l = log det A and the unimodular U
  // (row-major, D * D components).
  Field log_det{{.name = "distortion_log_det", .unit = "1", .scaled_as = "log_det"}};
  Field unimodular{{.name = "distortion_unimodular",
                    .unit = "1",
                    .components = D * D,
                    .scaled_as = "unimodular"}};
  // Energy per mass removed by the relaxation so far (eqs. 51-53; zero for an elastic solid): with
  // it the energy budget closes in a dissipative case.
  Field dissipated_energy{
      {.name = "dissipated_specific_energy", .unit = "J/kg", .scaled_as = "dissipated"}};
  // Constants of the setup: masses and the integration constants C_rho (eq. 7), C_lambda (eq. 40).
  Field mass{mass_field<D>()};
  Field density_constant{density_constant_field()};
  Field lambda_constant{
      {.name = "lambda_constant", .unit = "kg/m^3", .evolved = false, .scaled_as = "density"}};

  auto fields() {
    return std::tie(log_det, unimodular, dissipated_energy, mass, density_constant,
                    lambda_constant);
  }
};

template <int D>
struct Material {
  static constexpr SetInfo set{.name = "material", .motion = Motion::moving};
  Field position{position_field<D>()};
  Field velocity{{.name = "velocity", .unit = "m/s", .parity = Parity::odd, .components = D}};
  CarrierFields<D> carried;

  auto fields() { return std::tuple_cat(std::tie(position, velocity), carried.fields()); }
};

template <int D>
struct Boundary {
  static constexpr SetInfo set{.name = "boundary", .motion = Motion::fixed};
  Field position{position_field<D>(false)};
  CarrierFields<D> carried;
  // Moving walls (the rotating ring of Taylor-Couette, the cavity's lid, §4.3-4.4) stay in place
  // and "pretend" a velocity in L (eq. 10), as the paper's lid does: the wall velocity at full
  // drive, and the signed time since the drive started. Time reversal negates drive_time, and
  // the velocity a wall pretends is wall_velocity * sign(drive_time) * ramp(|drive_time|): odd,
  // so a reversed run sees the walls move backwards and ramp down at the same instants
  // (models/shtc/README.md). Every boundary particle keeps its own copy of the clock (a set's
  // fields share one length); the drift advances them all alike.
  Field wall_velocity{{.name = "wall_velocity",
                       .unit = "m/s",
                       .components = D,
                       .evolved = false,
                       .scaled_as = "velocity"}};
  Field drive_time{{.name = "drive_time", .unit = "s", .parity = Parity::odd}};
  // Work per mass each moving wall particle has done on the rest (J/kg), accumulated in the
  // distortion sub-step (model.hpp): with it the energy budget of a driven case closes. Even: a
  // reversed step subtracts bit for bit what the forward step added.
  Field wall_work{{.name = "wall_work", .unit = "J/kg", .scaled_as = "dissipated"}};

  auto fields() {
    return std::tuple_cat(std::tie(position), carried.fields(),
                          std::tie(wall_velocity, drive_time, wall_work));
  }
};

template <int D>
struct State {
  Material<D> material;
  Boundary<D> boundary;

  State() { declare_state(*this); }
  auto sets() { return std::tie(material, boundary); }
};

// Whether any boundary particle is a moving wall.
template <int D>
bool any_wall_moves(const State<D>& state) {
  const auto velocities = state.boundary.wall_velocity.all();
  return std::any_of(velocities.begin(), velocities.end(), [](std::int64_t v) { return v != 0; });
}

} // namespace revsph::shtc
