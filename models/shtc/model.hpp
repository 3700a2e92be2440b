#pragma once
// SHTC-SPH (paper 2) in fixed point: the reversible step of eq. (49) made bitwise reversible.
//   kick(dt/2)       v += dt/2 a(x, A)                       (eq. 48 / m, forces.hpp)
//   drift(dt/2)      x += dt/2 v
//   distortion(dt)   A <- A exp(-dt L(x, v))                  (eq. 47; distortion.hpp, exactly
//                                                             invertible, L of eq. 10 odd in v)
//   drift(dt/2), kick(dt/2)
// Each sub-step is undone bit for bit by itself after a time reversal (v -> -v), and the
// sequence is a palindrome: the step is bitwise reversible (design note §2, §4). The distortion
// update replaces the paper's Cayley form (same second order; tests compare them).
// A fluid's relaxation (eqs. 51-53, irreversible) is an operator the core places by the case's
// step.splitting (core/step_splitting.hpp): by default right after the distortion update (the
// paper's eq. 52); a solid has none (relaxation.hpp).
//
// Particles: "material" (moving) then "boundary" (in place, at rest or pretending a wall
// velocity; state.hpp), together the carriers. The neighbour loops run over the carriers in cell order (slots); the state and every
// output stay in canonical order.

#include "core/model_api.hpp"
#include "models/shtc/kernel_sums.hpp"
#include "models/shtc/parameters.hpp"
#include "models/shtc/state.hpp"
#include "models/shtc/sum_scales.hpp"
#include "models/shtc/velocity_gradient.hpp"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace revsph::shtc {

template <int D>
class Model : public ModelParts<Parameters<D>, State<D>> {
  using Parts = ModelParts<Parameters<D>, State<D>>;
  using Parts::info_;
  using Parts::parameters_;
  using Parts::state_;

public:
  // `state` holds positions, velocities and distortions with their scales; masses and the
  // integration constants are set by initialise_constants, or come with a restored snapshot.
  Model(Parameters<D> parameters, SimulationInfo info, State<D> state,
        std::optional<std::size_t> probe_particle);

  // Paper 2 §3.1: m_a = rho0 V_a with V_a = 1 / sum_b w_ab; then C_rho,a = rho0 - sum_b m_b w_ab
  // (eq. 7) and C_lambda,a = -sum_b m_b h dw_ab/dh (eq. 40), so that rho = rho0 and lambda = 0
  // at t = 0.
  void initialise_constants();

  static std::span<const Substep<Model>> palindrome();
  // The relaxation (eqs. 51-53), placed by step.splitting.
  static std::span<const IrreversibleOperator<Model>> irreversible_operators();

  // Kinetic, volumetric (eq. 29), shear (eq. 31 or 35) and penalty (eq. 39) energy, eq. (24);
  // with relaxation also the energy it has removed ("dissipated"), so that the total is conserved.
  EnergyBudget energy();
  void derived_views(const ViewSink& sink);
  // The angular momentum and, with moving walls, the power they feed in.
  std::vector<EnergyTerm> diagnostics();
  // The material particle nearest the case's probe point at t = 0, if it names one: the core
  // reports its position (probe_x, ...) in diagnostics.csv (core/simulation.hpp).
  std::vector<ProbeParticle> probe_particles() const {
    if (!probe_particle_) {
      return {};
    }
    return {ProbeParticle{"probe", "material", *probe_particle_}};
  }
  void invalidate_derived() {
    constants_valid_ = false;
    geometry_valid_ = false;
    force_valid_ = false;
  }

  void kick(double dt);
  void drift(double dt);
  void update_distortion(double dt);
  // Relaxes every carrier's distortion over dt (eqs. 52d, 53), counting the energy it removes.
  void relax_all(double dt);

  // Per material particle, canonical order (for tests).
  const CoordinateArrays<D>& acceleration();
  std::size_t material_count() const { return state_.material.position.count(); }
  // The carriers of the pair passes: every slot of the layout (in a distributed run their ghosts
  // too, which the loops over slots read through particle_in_slot like own particles).
  std::size_t carrier_count() const { return carrier_position().count(); }

private:
  // What each sub-step does irreversibly in this case ("" for nothing; step_composition.hpp).
  static std::string distortion_irreversibility(const Model& model);
  static std::string relaxation_irreversibility(const Model& model);
  std::string relaxation_description() const;

  // Per particle of one set, in the set's order.
  struct ParticleEnergies {
    std::vector<double> kinetic, bulk, shear, penalty, dissipated; // kinetic: material only
  };
  struct CarrierValues {
    std::vector<double> density, lambda;
    std::vector<Matrix<D>> distortion;
  };

  // The carriers' positions (material, then boundary).
  CarrierField<FixedArithmetic> carrier_position() const {
    return {&state_.material.position, &state_.boundary.position};
  }
  // What each set's carriers carry, indexed by the set's index in the layout.
  std::array<CarrierFields<D>*, 2> carried_by_set() {
    return {&state_.material.carried, &state_.boundary.carried};
  }
  ExactDistortion<D> distortion_of(const CarrierFields<D>& set, std::size_t i) const;
  static void store_distortion(CarrierFields<D>& set, std::size_t i,
                               const ExactDistortion<D>& distortion);
  // The velocity boundary particle i pretends now (state.hpp).
  Vec<D> wall_velocity_now(std::size_t i) const;
  // Whether the walls can do work: some wall moves, or walls mirror the fluid (wall_velocity is
  // a constant of the state: set with the constants).
  bool walls_work() const { return walls_work_; }
  // The velocities of eq. (10) by slot: slot_velocity_ (the material's, and v_w for the walls)
  // and, with mirrored walls, slot_mirrored_velocity_ (the walls' mirrored).
  void update_carrier_velocities();
  // The velocities the material sees the carriers move with, by slot.
  const CoordinateArrays<D>& slot_velocity_seen() const {
    return parameters_.mirrored_walls ? slot_mirrored_velocity_ : slot_velocity_;
  }
  // P = -sum_b v_b . F_b over the boundary particles, F_b the force of the distortion's stress
  // on b: with L linear in every velocity, the elastic energy changes by -sum_c v_c . F_c over
  // all carriers, so this is the rate at which the velocities the walls pretend add energy. With
  // mirrored walls the material's L sees a wall move with its mirrored velocity and the wall's
  // own L with v_w: the part of F_b from the material's stress pairs with the first, the part
  // from the walls' stress with the second.
  RunTotal wall_power();
  // The shear stress's accelerations per slot, of the current geometry and distortions, from
  // the stress of all carriers, of the material only or of the walls only.
  enum class StressOf { all, material, walls };
  void shear_accelerations(CoordinateArrays<D>& acceleration, StressOf carriers);
  struct WallForces {
    CoordinateArrays<D> from_walls;    // without mirroring: from all carriers
    CoordinateArrays<D> from_material; // mirrored walls only
  };
  void wall_forces(WallForces& forces);
  // -dt/2 v_b . (a_b before + a_b after) per mass, into wall_work: the trapezoid pairing of the
  // update, which the kicks balance to O(dt^2) in the reversible part. Uses the wall velocities
  // and forces of the sub-step (slot_velocity_, slot_mirrored_velocity_, wall_force_before_/
  // after_).
  bool add_wall_work(double dt);
  // The relaxation of eqs. (51)-(53) over dt, adding the energy per mass it removes.
  bool relax(ExactDistortion<D>& distortion, std::int64_t& dissipated, double dt) const;
  void update_constants();
  void update_geometry();
  void update_force();
  // Per set of the layout.
  std::array<CarrierValues, 2> carrier_values();
  std::array<ParticleEnergies, 2> particle_energies(const std::array<CarrierValues, 2>& values);

  std::optional<std::size_t> probe_particle_;
  WendlandQuintic<D> kernel_;

  SumScales sum_scales_;

  bool constants_valid_ = false;
  std::vector<double> mass_;                                     // carriers
  std::vector<std::int64_t> density_constant_, lambda_constant_; // carriers, raw
  bool walls_work_ = false;
  bool walls_work_known_ = false;
  // Derived from the positions.
  bool geometry_valid_ = false;
  SlotLayout<D> layout_; // carriers: material, then boundary particles
  std::vector<double> slot_mass_;
  std::vector<std::int64_t> slot_density_constant_, slot_lambda_constant_;
  KernelSums<D> sums_; // slots
  // Derived from the positions and the distortions.
  bool force_valid_ = false;
  std::vector<GradientMatrix<D>> slot_distortion_;
  std::vector<GradientMatrix<D>> slot_stress_;
  PairSums<FixedArithmetic, D> acceleration_sums_;
  CoordinateArrays<D> slot_acceleration_;
  CoordinateArrays<D> acceleration_; // material, canonical order
  // Scratch of the distortion sub-step.
  CoordinateArrays<D> slot_velocity_;
  VelocityGradients<D> gradients_;
  CoordinateArrays<D> slot_mirrored_velocity_; // walls: 2 v_w - the fluid's (mirrored walls)
  PairSums<FixedArithmetic, D + 1> mirror_sums_;
  std::vector<GradientMatrix<D>> slot_shear_stress_;
  WallForces wall_force_before_, wall_force_after_;
};

extern template class Model<2>;
extern template class Model<3>;

} // namespace revsph::shtc
