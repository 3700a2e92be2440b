#pragma once
// Parameters of an SHTC-SPH case, read from its case file. Every key read is declared in
// case_keys() (the reference: revsph cases --keys shtc, docs/case-keys.md).

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/geometry.hpp"
#include "core/step_splitting.hpp"
#include "fixedpoint/scale.hpp"
#include "models/shtc/distortion.hpp"
#include "models/shtc/elastic_energy.hpp"
#include "models/shtc/relaxation.hpp"

#include <optional>

namespace revsph::shtc {

// The values of material.relaxation_rate: the paper's rate, or the one matched to the splitting
// (relaxation.hpp).
enum class RelaxationRate { paper, matched };

// The initial velocity field.
enum class InitialField {
  rest,
  // Paper 2 eq. (55): v_y = A omega (a1 (sinh s + sin s) - a2 (cosh s + cos s)), s = alpha (x - x0)
  bending_plate,
  // Paper 2 eq. (60): v = omega sin(pi z / (2 H)) (y, -x, 0)
  twisting_column,
};

struct BendingPlateField {
  double amplitude = 0.0; // A (m)
  double omega = 0.0;     // omega (1/s)
  double alpha = 0.0;     // alpha (1/m)
  double a1 = 0.0;
  double a2 = 0.0;
  double x0 = 0.0; // left end of the plate (m): s = alpha (x - x0)
};

struct TwistingColumnField {
  double omega = 0.0;  // omega (1/s)
  double height = 0.0; // H (m)
};

template <int D>
struct Parameters {
  // [material]
  ElasticMaterial material;
  // tau of eqs. (51)-(53), from relaxation_time or kinematic_viscosity (tau = 6 nu / cs^2,
  // eqs. 65, 69); none: an elastic solid (tau = infinity)
  std::optional<double> relaxation_time;
  // Where the relaxation goes in the step (step.splitting, core/step_splitting.hpp; by default
  // after the distortion update, the paper's eq. 52) and its RK4 rate there ([material]
  // relaxation_rate = "paper", eq. 53's tau, or "matched": relaxation.hpp, nu kept at any
  // dt / tau)
  Splitting splitting = Splitting::after_centre;
  RelaxationSplitting relaxation_splitting;
  // [penalty]: the tensile penalty of eqs. (39)–(42); cp = 0 switches it off
  double penalty_speed = 0.0;
  // [discretisation]
  double dr = 0.0;
  double smoothing_length = 0.0; // h of paper 2; the kernel's support radius is 2 h
  double dt = 0.0;
  double cell_size_factor = 1.0;
  // discretisation.distortion_update = "cayley": the paper's update (eq. 49) in doubles, rounded
  // to the stored form — for comparing with the paper; not exactly invertible, so the step is
  // not bitwise reversible. "exact" (default): distortion.hpp's exactly invertible update.
  bool cayley_distortion_update = false;
  // [initial]
  InitialField initial_field = InitialField::rest;
  BendingPlateField plate;
  TwistingColumnField column;
  // [walls]: moving walls reach their velocity over ramp_time, as
  // sin^2(pi t / (2 ramp_time)) (0: at once)
  double ramp_time = 0.0;
  // walls.no_slip = "mirrored" (an option beyond paper 2): boundary particles pretend
  // 2 v_wall - (Shepard average of the fluid's velocity around them) instead of v_wall, so that
  // the velocity continues across the wall and vanishes relative to it at the wall itself
  // (mirrored_walls.hpp). "pretended" (default): v_wall, the paper's way.
  bool mirrored_walls = false;
  // [probe]: the material particle nearest to this point at t = 0 is reported in diagnostics.csv
  std::optional<Vec<D>> probe;
  Box<D> domain;
  // [fixed_point]
  fixedpoint::Scale position_scale;
  fixedpoint::Scale velocity_scale;
  fixedpoint::Scale density_scale;    // of the constants C_rho and C_lambda
  fixedpoint::Scale dissipated_scale; // of the energy per mass removed by the relaxation
  fixedpoint::Scale mass_scale;       // set at setup from the largest mass
  fixedpoint::Scale drive_time_scale; // of the walls' clock
  DistortionScales distortion_scales;

  double support_radius() const { return 2.0 * smoothing_length; }
  // The fraction of its full velocity a moving wall has at drive time t >= 0.
  double drive_ramp(double t) const;
};

template <int D>
Parameters<D> read_parameters(const CaseFile& case_file);

// The keys of an SHTC case file beyond common_case_keys(), including those setup.cpp (dimension,
// the walls' velocities) and core/particle_blocks.cpp read.
const KeyTable& case_keys();

} // namespace revsph::shtc
