#pragma once
// Symplectic WCSPH in fixed point (FixPA) or floating point (FloPA), paper 1 §2–4:
// velocity Verlet kick(dt/2) drift(dt) kick(dt/2), the acceleration a deterministic function of
// the positions (closed-form density eq. 5, Tait pressure eq. 2, pressure force eq. 1b, gravity,
// conservative wall eq. 7).

#include "core/cell_list.hpp"
#include "core/energy.hpp"
#include "core/kernel_wendland.hpp"
#include "core/neighbour_list.hpp"
#include "core/simulation.hpp"
#include "core/step_composition.hpp"
#include "models/wcsph/parameters.hpp"
#include "models/wcsph/state.hpp"

#include <array>
#include <span>
#include <vector>

namespace revsph::wcsph {

template <int D, class Arith>
class Model {
public:
  using Raw = typename Arith::Raw;

  // `state` holds positions, velocities, masses and wall positions with their scales set;
  // `density_constant` is computed here from the initial positions (eq. 5: C_a = rho0 -
  // rho_a(t = 0)). A state restored later (Simulation::restore_state) brings its own C_a.
  Model(Parameters<D> parameters, SimulationInfo info, State<D, Raw> state);

  static std::span<const Substep<Model>> palindrome();

  State<D, Raw>& state() { return state_; }
  const SimulationInfo& info() const { return info_; }
  const Parameters<D>& parameters() const { return parameters_; }
  EnergyBudget energy();
  // Density, pressure, acceleration and each energy term per fluid particle.
  std::vector<ParticleView> derived_views();
  void invalidate_derived() {
    derived_valid_ = false;
    walls_valid_ = false;
  }
  void reverse_time();

  // Sub-steps (paper 1 §4, steps 1–3).
  void kick(double dt);
  void drift(double dt);

  // Derived quantities at the current positions (for diagnostics and tests).
  const std::vector<double>& density();
  const std::array<std::vector<double>, D>& acceleration();
  const NeighbourList& fluid_neighbours();

private:
  static void kick_substep(Model& model, double dt) { model.kick(dt); }
  static void drift_substep(Model& model, double dt) { model.drift(dt); }
  struct ParticleEnergies {
    std::vector<double> kinetic, gravitational, compressional, wall;
  };
  void update_derived();
  void update_walls();
  ParticleEnergies particle_energies();

  Parameters<D> parameters_;
  SimulationInfo info_;
  State<D, Raw> state_;
  WendlandQuintic<D> kernel_;

  // Derived from the state, recomputed after every drift.
  bool derived_valid_ = false;
  bool walls_valid_ = false; // wall positions and masses are constant: converted once
  CoordinateArrays<D> position_;
  CoordinateArrays<D> wall_position_;
  std::vector<double> mass_;
  CellList<D> fluid_cells_;
  CellList<D> wall_cells_;
  NeighbourList fluid_neighbours_;
  NeighbourList wall_neighbours_;
  std::vector<double> density_;
  std::vector<double> pressure_over_density_squared_;
  std::array<std::vector<double>, D> acceleration_;
};

extern template class Model<2, FixedArithmetic>;
extern template class Model<3, FixedArithmetic>;
extern template class Model<2, FloatArithmetic>;
extern template class Model<3, FloatArithmetic>;

} // namespace revsph::wcsph
