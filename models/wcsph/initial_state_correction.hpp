#pragma once
// Initial state correction (ISC), paper 1 §3.2: Newton iterations on the particle positions until
// the kernel density of eq. (4), rho_a = sum_b m_b w(r_ab) with b = a included, equals rho0 for
// every particle. Afterwards the integration constants C_a of eq. (5) are zero up to the
// tolerance, so particles that start at a free surface are not marked for the rest of the run.
//
// Each iteration solves the linearisation (6a) of rho(x + dx) = rho0 with dx restricted to the
// discrete-gradient form (6b); see initial_state_correction.cpp for the signs, the choice of
// linear system and its cost.

#include "core/geometry.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace revsph::wcsph {

struct IscSettings {
  int max_iterations = 20;
  double tolerance = 1e-10; // on max_a |rho_a - rho0| / rho0 over the movable particles
  // Step 1 of the paper: before the iterations, every movable particle is displaced once by a
  // random vector of uniformly distributed direction and uniformly distributed length in
  // [0, jitter * spacing). It breaks the symmetry of regular lattices, on which the Newton
  // iteration "nearly always diverges" (paper 1, footnote 2). 0: no displacement.
  double jitter = 0.1;
  // Damping: a Newton step that would move some particle farther than max_step * spacing is
  // scaled down as a whole to that length (0: undamped). Far from the solution, full steps can
  // land on one of the many other configurations of uniform density, e.g. pairs of particles a
  // tenth of dr apart, which have the right density but explode under the pressure and
  // anti-clump forces; near it, steps are tiny and the convergence stays quadratic.
  double max_step = 0.0;
  double spacing = 0.0;   // the initial particle spacing dr; required when jitter or max_step > 0
  std::uint64_t seed = 1; // std::mt19937_64 seed of the jitter: equal seeds, equal results
};

struct IscReport {
  int iterations = 0; // Newton updates applied
  // max_a |rho_a - rho0| / rho0 before each iteration and after the last one
  // (iterations + 1 entries).
  std::vector<double> residuals;
  bool converged = false; // residuals.back() <= tolerance
  // Conjugate-gradient iterations of each Newton step's linear solve (the cost driver).
  std::vector<int> linear_iterations;
  // Empty unless the iteration stopped before max_iterations without converging: then why (a
  // particle without neighbours, whose density no displacement can change, or a non-finite
  // step).
  std::string stopped_early;
};

// Moves the `movable` particles so that the kernel density (eq. 4) of every movable particle
// equals rest_density; `fixed` particles (dummy walls) contribute to the density sums but do not
// move, and their own density is not corrected. Masses are per particle (per unit depth in 2D).
//
// On return `movable` holds the last iterate (also when not converged). Throws
// std::invalid_argument for inconsistent arguments and std::runtime_error, naming the particle
// and the iteration, if a particle is or would be moved outside `domain`; `movable` is then
// left unchanged. Deterministic: the result depends on the arguments only (not on the thread
// count).
template <int D>
IscReport correct_initial_state(CoordinateArrays<D>& movable, std::span<const double> movable_mass,
                                const CoordinateArrays<D>& fixed,
                                std::span<const double> fixed_mass, double support_radius,
                                double rest_density, const Box<D>& domain,
                                const IscSettings& settings);

extern template IscReport correct_initial_state<1>(CoordinateArrays<1>&, std::span<const double>,
                                                   const CoordinateArrays<1>&,
                                                   std::span<const double>, double, double,
                                                   const Box<1>&, const IscSettings&);
extern template IscReport correct_initial_state<2>(CoordinateArrays<2>&, std::span<const double>,
                                                   const CoordinateArrays<2>&,
                                                   std::span<const double>, double, double,
                                                   const Box<2>&, const IscSettings&);
extern template IscReport correct_initial_state<3>(CoordinateArrays<3>&, std::span<const double>,
                                                   const CoordinateArrays<3>&,
                                                   std::span<const double>, double, double,
                                                   const Box<3>&, const IscSettings&);

} // namespace revsph::wcsph
