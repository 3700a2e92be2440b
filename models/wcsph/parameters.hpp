#pragma once
// Parameters of a WCSPH case, read from its case file. Every key read is declared in
// case_keys() (the reference: revsph cases --keys wcsph, docs/case-keys.md).

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/geometry.hpp"
#include "core/particle_discretisation.hpp"
#include "core/step_splitting.hpp"
#include "fixedpoint/scale.hpp"
#include "models/wcsph/equations.hpp"
#include "models/wcsph/initial_state_correction.hpp"

namespace revsph::wcsph {

enum class InitialField { rest, gresho_vortex };

template <int D>
struct Parameters : ParticleDiscretisation { // dr, support_radius, dt, cell_size_factor
  // [physics]
  double rest_density = 0.0;             // rho0 (kg/m^3)
  double sound_speed = 0.0;              // c (m/s)
  double gravity = 0.0;                  // g (m/s^2), along -axis D-1
  double gravity_reference_height = 0.0; // height of zero gravitational potential (m)
  // [discretisation]
  // [wall], eq. (7)
  WallSettings wall;
  // [physics] anti_clump_pressure: p0 of the anti-clump force of App. A (0: off)
  double anti_clump_pressure = 0.0;
  // [physics] artificial_viscosity: alpha of Monaghan's artificial viscosity (viscosity_term.hpp;
  // irreversible, 0: off) and [step] splitting: where it goes (core/step_splitting.hpp)
  double artificial_viscosity = 0.0;
  Splitting splitting = Splitting::strang;
  // [filter]: the Shepard filter of App. A, every shepard_every steps; active replaces the
  // velocities (dissipative, irreversible), passive only reports the filtered field
  std::int64_t shepard_every = 0;
  bool shepard_active = false;
  // [initial]: the initial velocity and pressure field
  InitialField initial_field = InitialField::rest;
  Vec<D> centre{};
  // [initial_state_correction]: paper 1 §3.2, applied to the fluid positions at setup
  bool isc_enabled = false;
  bool isc_with_dummies = true; // dummy particles count in the corrected densities
  IscSettings isc;
  Box<D> domain;
  // [fixed_point]: scales of the stored and the accumulated quantities
  fixedpoint::Scale position_scale;
  fixedpoint::Scale velocity_scale;
  fixedpoint::Scale density_scale;      // density sums and the constants C_a
  fixedpoint::Scale acceleration_scale; // acceleration sums

  // The wall interaction of eq. (7) with these parameters.
  WallPotential wall_potential() const { return wall.potential(); }
};

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file);

// The keys of a WCSPH case file beyond common_case_keys(), including those setup.cpp and
// core/particle_blocks.cpp read.
const KeyTable& case_keys();

} // namespace revsph::wcsph
