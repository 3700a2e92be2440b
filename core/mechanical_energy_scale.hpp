#pragma once
// The energy that moves around in a run: the denominator of energy.csv's
// mechanical_relative_error (docs/verify.md, "Two energy errors").
//
// |E(t) - E(0)| / |E(0)| is the paper's measure (paper 1, Fig. 8), but E(0) can be dominated by
// energy that never moves: the compressional energy of WCSPH water at rest is about c^2 / 6 per
// unit mass (c^2 / 42 (1 + 6) at rho = rho0), 2400 J/kg for c = 120 m/s, while a dam break
// releases gravitational energy of order g H / 2, a few J/kg. The mechanical scale is instead
//     S(t) = max over s <= t and over the terms i of  e_i(s),
//     e_i = |E_i| for the kinetic energy (its zero is rest, so all of it is in motion), and
//     e_i = |E_i - E_i(0)| for every other term (potential energies, the dissipated energy, the
//           work of driven walls: only their change is energy that moved),
// the largest amount of energy any one term has held in motion or taken up or given away so far.
// Dam break: the drop of the gravitational energy (paper 1, Fig. 5 divides by the same drop);
// Gresho vortex: its kinetic energy; an elastic plate: its initial kinetic energy, which turns
// into shear energy and back; a driven cavity: the work the lid has done.

#include "core/energy.hpp"

#include <vector>

namespace revsph {

class MechanicalEnergyScale {
public:
  // The first budget observed is E_i(0).
  void observe(const EnergyBudget& budget);
  bool started() const { return started_; }
  double value() const { return scale_; }

private:
  bool started_ = false;
  std::vector<double> initial_terms_;
  double scale_ = 0.0;
};

// |E - E(0)| / S, with 0 / 0 = 0 (nothing has moved and nothing has changed) and d / 0 = inf.
double mechanical_relative_error(double deviation, double scale);

} // namespace revsph
