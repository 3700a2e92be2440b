// The Wendland quintic kernel: normalisation and derivative, in 1D, 2D and 3D.

#include "core/kernel_wendland.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using revsph::WendlandQuintic;

// Composite Gauss-Legendre quadrature (5 points per panel) of f over [0, h]. The kernel is a
// polynomial of degree 5 in r, so the radial integrands (degree 6 and 7) are integrated exactly
// up to round-off.
template <class F>
double integrate(F&& f, double h, int panels) {
  static constexpr double nodes[] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                     0.5384693101056831, 0.9061798459386640};
  static constexpr double weights[] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                       0.4786286704993665, 0.2369268850561891};
  double total = 0.0;
  const double width = h / panels;
  for (int p = 0; p < panels; ++p) {
    const double centre = (p + 0.5) * width;
    for (int i = 0; i < 5; ++i) {
      total += 0.5 * width * weights[i] * f(centre + 0.5 * width * nodes[i]);
    }
  }
  return total;
}

TEST(WendlandQuintic, IntegratesToOneIn1D) {
  for (const double h : {0.015, 1.0, 3.7}) {
    const WendlandQuintic<1> kernel(h);
    const double integral = integrate([&](double r) { return 2.0 * kernel.value(r); }, h, 64);
    EXPECT_NEAR(integral, 1.0, 1e-10) << "h = " << h;
  }
}

TEST(WendlandQuintic, IntegratesToOneIn2D) {
  for (const double h : {0.015, 1.0, 3.7}) {
    const WendlandQuintic<2> kernel(h);
    const double integral =
        integrate([&](double r) { return 2.0 * std::numbers::pi * r * kernel.value(r); }, h, 64);
    EXPECT_NEAR(integral, 1.0, 1e-10) << "h = " << h;
  }
}

TEST(WendlandQuintic, IntegratesToOneIn3D) {
  for (const double h : {0.015, 1.0, 3.7}) {
    const WendlandQuintic<3> kernel(h);
    const double integral = integrate(
        [&](double r) { return 4.0 * std::numbers::pi * r * r * kernel.value(r); }, h, 64);
    EXPECT_NEAR(integral, 1.0, 1e-10) << "h = " << h;
  }
}

// Also checks the normalisation independently with a 2D Cartesian midpoint sum (not radial).
TEST(WendlandQuintic, CartesianSumOverALatticeIsOneIn2D) {
  const double h = 1.0;
  const WendlandQuintic<2> kernel(h);
  const int n = 2000;
  const double cell = 2.0 * h / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = -h + (i + 0.5) * cell;
      const double y = -h + (j + 0.5) * cell;
      sum += kernel.value(std::hypot(x, y)) * cell * cell;
    }
  }
  EXPECT_NEAR(sum, 1.0, 1e-6); // midpoint rule error O(cell^2)
}

template <int D>
void expect_derivative_matches_finite_differences(double h) {
  const WendlandQuintic<D> kernel(h);
  for (int i = 1; i < 100; ++i) {
    const double r = h * i / 100.0;
    const double step = 1e-5 * h;
    const double central = (kernel.value(r + step) - kernel.value(r - step)) / (2.0 * step);
    // Central differences: error ~ step^2 w''' / 6, plus round-off ~ eps w / step.
    const double tolerance = 1e-7 * std::abs(kernel.value(0.0)) / h;
    EXPECT_NEAR(kernel.derivative(r), central, tolerance) << "r / h = " << r / h;
    EXPECT_NEAR(kernel.derivative_over_r(r) * r, kernel.derivative(r), 1e-14 * kernel.value(0) / h);
  }
  EXPECT_EQ(kernel.value(h), 0.0);
  EXPECT_EQ(kernel.derivative(h), 0.0);
  EXPECT_EQ(kernel.value(1.5 * h), 0.0);
  EXPECT_EQ(kernel.derivative(0.0), 0.0);
  EXPECT_TRUE(std::isfinite(kernel.derivative_over_r(0.0)));
}

TEST(WendlandQuintic, DerivativeMatchesFiniteDifferences) {
  expect_derivative_matches_finite_differences<1>(0.015);
  expect_derivative_matches_finite_differences<1>(2.0);
  expect_derivative_matches_finite_differences<2>(0.015);
  expect_derivative_matches_finite_differences<2>(2.0);
  expect_derivative_matches_finite_differences<3>(0.015);
  expect_derivative_matches_finite_differences<3>(2.0);
}

} // namespace

namespace {

// h dw/dh and h d/dh (w'/r) at fixed r, against central differences in the support and against
// the closed forms printed in paper 2 (eqs. 43–46, support 2h; 2D and 3D only, 1D against the
// differences alone).
template <int D>
void expect_scale_derivatives(double h) {
  const double support = 2.0 * h;
  const WendlandQuintic<D> kernel(support);
  const double step = 1e-6 * support;
  const WendlandQuintic<D> wider(support + step);
  const WendlandQuintic<D> narrower(support - step);
  for (double r = 0.0; r < support; r += 0.037 * support) {
    const double numeric_value = support * (wider.value(r) - narrower.value(r)) / (2.0 * step);
    const double numeric_slope =
        support * (wider.derivative_over_r(r) - narrower.derivative_over_r(r)) / (2.0 * step);
    const double value_scale = std::fabs(kernel.value(0.0));
    const double slope_scale = std::fabs(kernel.derivative_over_r(0.0));
    EXPECT_NEAR(kernel.scale_derivative(r), numeric_value, 1e-7 * value_scale) << "r = " << r;
    EXPECT_NEAR(kernel.scale_derivative_of_derivative_over_r(r), numeric_slope, 1e-7 * slope_scale)
        << "r = " << r;

    const double s = r / h;
    const double u = 1.0 - r / (2.0 * h);
    const double pi = std::numbers::pi;
    if constexpr (D == 2) {
      const double eq43 = 7.0 / (4.0 * pi * h * h) * u * u * u * (7.0 * s * s - 3.0 * s - 2.0);
      EXPECT_NEAR(kernel.scale_derivative(r), eq43, 1e-12 * value_scale) << "eq. 43, r = " << r;
      // Eq. (44) as printed is twice the derivative of eq. (43)'s kernel: the factor is 35/(8 pi)
      // — found by this test; both the journal text and the preprint print 35/(4 pi).
      const double eq44_corrected = -35.0 / (8.0 * pi * std::pow(h, 4)) * u * u * (7.0 * s - 8.0);
      EXPECT_NEAR(kernel.scale_derivative_of_derivative_over_r(r), eq44_corrected,
                  1e-12 * slope_scale)
          << "eq. 44, r = " << r;
    } else if constexpr (D == 3) {
      const double eq45 =
          21.0 / (32.0 * pi * h * h * h) * u * u * u * (16.0 * s * s - 9.0 * s - 6.0);
      const double eq46 = -105.0 / (16.0 * pi * std::pow(h, 5)) * u * u * (4.0 * s - 5.0);
      EXPECT_NEAR(kernel.scale_derivative(r), eq45, 1e-12 * value_scale) << "eq. 45, r = " << r;
      EXPECT_NEAR(kernel.scale_derivative_of_derivative_over_r(r), eq46, 1e-12 * slope_scale)
          << "eq. 46, r = " << r;
    }
  }
}

TEST(WendlandQuintic, ScaleDerivativesIn1D) {
  expect_scale_derivatives<1>(1.0);
  expect_scale_derivatives<1>(0.013);
}

TEST(WendlandQuintic, ScaleDerivativesIn2D) {
  expect_scale_derivatives<2>(1.0);
  expect_scale_derivatives<2>(0.013);
}

TEST(WendlandQuintic, ScaleDerivativesIn3D) {
  expect_scale_derivatives<3>(1.0);
  expect_scale_derivatives<3>(0.013);
}

} // namespace
