#pragma once
// The distortion A of SHTC-SPH (Kincl, Peshkov, Pavelka: paper 2 eq. 47, dA/dt = -A L) and its
// update in the reversible step (eq. 49), made exactly invertible in fixed point.
//
// The paper's update A <- A (I - h/2 L)(I + h/2 L)^-1 (Cayley) cannot be undone bit for bit once
// rounded: a linear map with det != 1 has no exact inverse on an integer lattice. Following the
// design note (exact-reversibility.md §4), A = exp(l / d) U is stored as
//   l = log det A   — one fixed-point number, updated additively: l += -tr(h L);
//   U = A / det(A)^(1/d) — the unimodular part, d x d fixed-point numbers, updated by
//       U <- U exp(-h dev L) written as a palindromic (Strang) product of plane rotations, plane
//       boosts and axis stretches, each a sequence of lifting (shear) steps
//       column_j += round(c * column_i), exactly undone by the same step with -c.
// Every parameter c is an odd function of h L computed so that -h L gives exactly -c; the update
// with -h L is then bit for bit the inverse of the update with h L. Accuracy: second order in h,
// like the Cayley update (the two differ by O(h^3) per step, O(h^2) over a fixed time).

#include "fixedpoint/scale.hpp"

#include <Eigen/Dense>

#include <array>
#include <cstdint>

namespace revsph::shtc {

template <int D>
using Matrix = Eigen::Matrix<double, D, D>;

struct DistortionScales {
  fixedpoint::Scale log_det;    // of l = log det A
  fixedpoint::Scale unimodular; // of the entries of U
};

template <int D>
struct ExactDistortion {
  std::int64_t log_det = 0;
  std::array<std::int64_t, D * D> unimodular{}; // U row-major: U(i, j) at [i * D + j]
};

// The exact form of A (det A > 0 required); false if det A <= 0, a value is not finite or does
// not fit its scale.
template <int D>
bool try_make_distortion(const Matrix<D>& a, const DistortionScales& scales,
                         ExactDistortion<D>& out);

// A = exp(l / d) U in doubles (for the stress and for output).
template <int D>
Matrix<D> to_matrix(const ExactDistortion<D>& a, const DistortionScales& scales);

// A <- A exp(-h L) to second order in h, exactly invertible: try_update_distortion(a, -h_l)
// returns a to its previous bits. `h_l` is h L (L at the half step). False on fixed-point
// overflow or a non-finite parameter; `a` is then unspecified (the step has failed).
template <int D>
bool try_update_distortion(ExactDistortion<D>& a, const Matrix<D>& h_l,
                           const DistortionScales& scales);

// The paper's update (eq. 49), in doubles: A (I - h L / 2)(I + h L / 2)^-1.
template <int D>
Matrix<D> cayley_update(const Matrix<D>& a, const Matrix<D>& h_l);

} // namespace revsph::shtc
