#pragma once
// The closed-form summation density with an integration constant per particle,
//   rho_a = sum_b m_b w(r_ab) + C_a      (paper 1 eq. 5; paper 3 eq. 24),
// the sum over the carriers b including b = a. C_a is set at setup so that rho_a(0) is the wanted
// initial density; it avoids integrating the continuity equation, and the density is then a
// function of the positions only (what makes the pressure force a kick).

#include "core/fault.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/state_field.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

namespace revsph {

template <int D, class Arith>
struct SummationDensityTerm {
  static constexpr int width = 1;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass; // by slot
  // By slot, at the density's scale: paper 1's integration constant C_a of eq. (5); empty for
  // the plain sum (paper 4's eq. 32a).
  std::span<const typename Arith::Raw> density_constant;

  void pair(const PairGeometry<D>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    const double w = kernel.value(p.r);
    to_a[0] = mass[p.b] * w;
    to_b[0] = mass[p.a] * w;
  }
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    add(0, mass[s] * kernel.value(0.0));
    if (!density_constant.empty()) {
      add.raw(0, density_constant[s]);
    }
  }
};

// sum_b w(|x_a - x_b|) over a full square (cubic) lattice of spacing dr, b = a included: the
// kernel sum of a unit-mass particle inside a liquid laid on the lattice. A boundary particle
// whose constant is set from it weighs as if it were inside the liquid, wet or dry.
template <int D>
double lattice_kernel_sum(const WendlandQuintic<D>& kernel, double dr) {
  const int reach = static_cast<int>(kernel.support_radius() / dr) + 1;
  std::array<int, D> index{};
  index.fill(-reach);
  double sum = 0.0;
  while (true) {
    double r_squared = 0.0;
    for (int k = 0; k < D; ++k) {
      r_squared += (index[k] * dr) * (index[k] * dr);
    }
    sum += kernel.value(std::sqrt(r_squared));
    int k = 0;
    while (k < D && index[k] == reach) {
      index[k++] = -reach;
    }
    if (k == D) {
      return sum;
    }
    ++index[k];
  }
}

// C_a = wanted - sum into particle i's density constant; a constant that does not fit its scale
// is the setup's fault on that particle.
template <class Arith>
void set_density_constant(StateField<typename Arith::Raw>& field, std::size_t i, double wanted,
                          double sum) {
  if (!Arith::try_from_real(wanted - sum, field.info().scale, field.at(0, i))) {
    throw SimulationFault(
        {field.info().particle_set, i, "density_constant", "does not fit its scale"}, 0);
  }
}

} // namespace revsph
