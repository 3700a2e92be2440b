#pragma once
// The renormalised SPH velocity gradient of SHTC-SPH (paper 2, eq. 10):
//   L_a = (sum_b m_b v_ab (x) grad w_ab) H_a^-1,      grad w_ab = w'(r_ab) / r_ab x_ab (eq. 6),
// as a pair term of core's pair loop (arrays indexed by slot), with H_a^-1 from kernel_sums.hpp.
// L_a is exact for a linear velocity field whenever a has d linearly independent neighbours
// (Statement 2), and zero where H_a is singular.
//
// The tensor product for (b, a) equals that for (a, b) (both factors change sign); only the mass
// factor differs. The sums are exact in integers (SumScales::velocity_sum) and every term is odd
// in v, so negating all velocities negates L bit for bit — what the reversible step (eq. 49)
// needs of it — for any thread count and any cell size.

#include "models/shtc/kernel_sums.hpp"

#include <span>
#include <tuple>
#include <vector>

namespace revsph::shtc {

// The velocities each slot sees its partners move with: `seen_by_material` for every slot, or,
// with mirrored walls (mirrored_walls.hpp), `seen_by_walls` for the boundary slots (is_wall; an
// empty set_of_slot: one view for all).
template <int D>
struct SeenVelocities {
  CoordinateView<D> seen_by_material;
  CoordinateView<D> seen_by_walls;
  SlotInSet is_wall;
};

template <int D>
struct VelocityGradientTerm {
  static constexpr int width = D * D; // sum_b m_b v_ab (x) grad w_ab, row by row
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass;
  SeenVelocities<D> v;

  // Filled from own particles' state (a distributed run copies the ghosts' in, core/pair_sum.hpp).
  auto slot_inputs() const { return std::tie(v.seen_by_material, v.seen_by_walls); }
  const CoordinateView<D>& view_of_slot(std::uint32_t s) const {
    return !v.is_wall.set_of_slot.empty() && v.is_wall(s) ? v.seen_by_walls : v.seen_by_material;
  }
  void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
            std::array<double, width>& to_b) const {
    const double slope = kernel.derivative_over_r(p.r);
    std::array<double, D> gradient{};
    for (int k = 0; k < D; ++k) {
      gradient[k] = slope * p.x_ab[k];
    }
    add_terms(view_of_slot(p.a), p, gradient, mass[p.b], to_a);
    // a and b see the same velocities unless one is a mirrored wall and the other is not.
    add_terms(view_of_slot(p.b), p, gradient, mass[p.a], to_b);
  }

private:
  static void add_terms(const CoordinateView<D>& velocity, const PairGeometry<D>& p,
                        const std::array<double, D>& gradient, double mass,
                        std::array<double, width>& out) {
    for (int i = 0; i < D; ++i) {
      const double v_ab = velocity[i][p.a] - velocity[i][p.b];
      for (int j = 0; j < D; ++j) {
        out[i * D + j] = mass * (v_ab * gradient[j]);
      }
    }
  }
};

template <int D>
struct VelocityGradients {
  explicit VelocityGradients(const fixedpoint::Scale& scale) : totals(quantities(scale)) {}

  std::vector<GradientMatrix<D>> gradient; // L by slot
  PairSums<FixedArithmetic, D * D> totals;

private:
  static std::array<SummedQuantity, D * D> quantities(const fixedpoint::Scale& scale) {
    std::array<SummedQuantity, D * D> q{};
    q.fill({"velocity_gradient", scale});
    return q;
  }
};

template <int D>
void velocity_gradients(const WendlandQuintic<D>& kernel, const SlotLayout<D>& layout,
                        const SeenVelocities<D>& v, std::span<const double> mass,
                        std::span<const GradientMatrix<D>> h_inverse,
                        VelocityGradients<D>& result) {
  sum_pairs<FixedArithmetic>(layout, VelocityGradientTerm<D>{kernel, mass, v}, result.totals);
  const std::size_t n = layout.slot_count();
  result.gradient.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    GradientMatrix<D> velocity_sum;
    for (int i = 0; i < D; ++i) {
      for (int j = 0; j < D; ++j) {
        velocity_sum(i, j) = result.totals.value(i * D + j, s);
      }
    }
    result.gradient[s] = velocity_sum * h_inverse[s];
  }
}

// Every slot sees the same velocities `v`.
template <int D>
void velocity_gradients(const WendlandQuintic<D>& kernel, const SlotLayout<D>& layout,
                        const CoordinateView<D>& v, std::span<const double> mass,
                        std::span<const GradientMatrix<D>> h_inverse,
                        VelocityGradients<D>& result) {
  velocity_gradients<D>(kernel, layout, SeenVelocities<D>{v, v, {}}, mass, h_inverse, result);
}

} // namespace revsph::shtc
