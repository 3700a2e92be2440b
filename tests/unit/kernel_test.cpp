// The Wendland quintic kernel: normalisation and derivative, in 2D and 3D.

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
  expect_derivative_matches_finite_differences<2>(0.015);
  expect_derivative_matches_finite_differences<2>(2.0);
  expect_derivative_matches_finite_differences<3>(0.015);
  expect_derivative_matches_finite_differences<3>(2.0);
}

} // namespace
