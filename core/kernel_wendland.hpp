#pragma once
// The Wendland quintic (C2) kernel, written with its support radius h (w = 0 for r >= h):
//   w(r) = alpha_D (1 - q)^4 (1 + 4 q),   q = r / h,
//   alpha_1 = 3 / (2 h),   alpha_2 = 7 / (pi h^2),   alpha_3 = 21 / (2 pi h^3),
// so that its integral over the support is 1 (in 1D: 2 h int_0^1 (1 - q)^4 (1 + 4q) dq = 2h / 3).
// Paper 1 uses it with h = 3 dr (Table 1). It is positive definite in up to three dimensions
// (Wendland's psi_{3,1}), so the same function serves 1D.

#include <numbers>

namespace revsph {

template <int D>
class WendlandQuintic {
  static_assert(D >= 1 && D <= 3, "the Wendland quintic is defined here for 1D, 2D and 3D");

public:
  explicit WendlandQuintic(double support_radius)
      : support_(support_radius), inverse_support_(1.0 / support_radius),
        normalisation_(normalisation(support_radius)) {}

  double support_radius() const { return support_; }

  // w(r)
  double value(double r) const {
    const double q = r * inverse_support_;
    if (q >= 1.0) {
      return 0.0;
    }
    const double one_minus_q = 1.0 - q;
    const double squared = one_minus_q * one_minus_q;
    return normalisation_ * squared * squared * (1.0 + 4.0 * q);
  }

  // dw/dr = -20 alpha q (1 - q)^3 / h
  double derivative(double r) const { return derivative_over_r(r) * r; }

  // (dw/dr) / r = -20 alpha (1 - q)^3 / h^2: finite at r = 0, so a pair force
  // (dw/dr / r) * (x_a - x_b) needs no division by the distance.
  double derivative_over_r(double r) const {
    const double q = r * inverse_support_;
    if (q >= 1.0) {
      return 0.0;
    }
    const double one_minus_q = 1.0 - q;
    return -20.0 * normalisation_ * one_minus_q * one_minus_q * one_minus_q * inverse_support_ *
           inverse_support_;
  }

  // Derivatives with respect to the kernel's length scale at fixed r (h d/dh, the same as
  // S d/dS for the support S = 2h of paper 2), for the tensile penalty of SHTC-SPH (paper 2,
  // eqs. 40–46). With w = alpha S^-D (1 - q)^4 (1 + 4q), q = r / S:
  //   S dw/dS = alpha S^-D (1 - q)^3 (20 q^2 - D (1 - q)(1 + 4q))          (eqs. 43, 45)
  double scale_derivative(double r) const {
    const double q = r * inverse_support_;
    if (q >= 1.0) {
      return 0.0;
    }
    const double one_minus_q = 1.0 - q;
    return normalisation_ * one_minus_q * one_minus_q * one_minus_q *
           (20.0 * q * q - D * one_minus_q * (1.0 + 4.0 * q));
  }
  //   S d/dS (w'(r) / r) = -20 alpha S^-D-2 (1 - q)^2 ((D + 5) q - (D + 2))  (eqs. 44, 46)
  double scale_derivative_of_derivative_over_r(double r) const {
    const double q = r * inverse_support_;
    if (q >= 1.0) {
      return 0.0;
    }
    const double one_minus_q = 1.0 - q;
    return -20.0 * normalisation_ * inverse_support_ * inverse_support_ * one_minus_q *
           one_minus_q * ((D + 5) * q - (D + 2));
  }

private:
  static double normalisation(double h) {
    if constexpr (D == 1) {
      return 3.0 / (2.0 * h);
    } else if constexpr (D == 2) {
      return 7.0 / (std::numbers::pi * h * h);
    } else {
      return 21.0 / (2.0 * std::numbers::pi * h * h * h);
    }
  }

  double support_;
  double inverse_support_;
  double normalisation_;
};

} // namespace revsph
