#pragma once
// The closed-form summation density with an integration constant per particle,
//   rho_a = sum_b m_b w(r_ab) + C_a      (paper 1 eq. 5; paper 3 eq. 24),
// the sum over the carriers b including b = a. C_a is set at setup so that rho_a(0) is the wanted
// initial density; it avoids integrating the continuity equation, and the density is then a
// function of the positions only (what makes the pressure force a kick).

#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace revsph {

template <int D, class Arith>
struct SummationDensityTerm {
  static constexpr int width = 1;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;                          // by slot
  std::span<const typename Arith::Raw> density_constant; // by slot, the density's scale

  void pair(const PairGeometry<D>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    const double w = kernel.value(p.r);
    to_a[0] = mass[p.b] * w;
    to_b[0] = mass[p.a] * w;
  }
  template <class Add>
  void self(std::uint32_t s, Add& add) const {
    add(0, mass[s] * kernel.value(0.0));
    add.raw(0, density_constant[s]);
  }
};

} // namespace revsph
