// Initial state correction (paper 1 §3.2, Fig. 1): Newton iterations on the positions until the
// kernel density of eq. (4) is rho0 at every particle.

#include "core/kernel_wendland.hpp"
#include "models/wcsph/initial_state_correction.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

namespace revsph::wcsph {
namespace {

constexpr double rest_density = 1000.0;

// An n x m patch on the square lattice of spacing dr, cell centres at (i + 1/2) dr.
CoordinateArrays<2> square_patch(int columns, int rows, double dr) {
  CoordinateArrays<2> points;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      points[0].push_back((i + 0.5) * dr);
      points[1].push_back((j + 0.5) * dr);
    }
  }
  return points;
}

// Eq. (4) summed directly over all pairs: independent of the neighbour search of the solver.
template <int D>
std::vector<double> brute_force_density(const CoordinateArrays<D>& points, double mass,
                                        double support_radius) {
  const WendlandQuintic<D> kernel(support_radius);
  const std::size_t n = points[0].size();
  std::vector<double> density(n, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      double r_squared = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = points[k][a] - points[k][b];
        r_squared += d * d;
      }
      density[a] += mass * kernel.value(std::sqrt(r_squared));
    }
  }
  return density;
}

double max_relative_deviation(const std::vector<double>& density) {
  double largest = 0.0;
  for (const double rho : density) {
    largest = std::max(largest, std::abs(rho - rest_density) / rest_density);
  }
  return largest;
}

struct Patch {
  double dr = 0.01;
  double support_radius = 0.03; // h = 3 dr as in Table 1
  double mass = rest_density * 0.01 * 0.01;
  CoordinateArrays<2> positions = square_patch(30, 30, 0.01);
  Box<2> domain{{-0.2, -0.2}, {0.5, 0.5}};
};

IscReport correct(Patch& patch, const IscSettings& settings) {
  const std::vector<double> masses(patch.positions[0].size(), patch.mass);
  return correct_initial_state<2>(patch.positions, masses, CoordinateArrays<2>{}, {},
                                  patch.support_radius, rest_density, patch.domain, settings);
}

IscSettings fig1_settings(double dr) {
  IscSettings settings;
  settings.max_iterations = 10;
  settings.tolerance = 1e-10;
  settings.jitter = 0.1;
  settings.spacing = dr;
  settings.seed = 7;
  return settings;
}

TEST(InitialStateCorrection, SquarePatchReachesUniformDensityWithin1e10InAtMostTenIterations) {
  Patch patch;
  const double before = max_relative_deviation(
      brute_force_density<2>(patch.positions, patch.mass, patch.support_radius));
  // At the edges a particle misses a large part of its kernel: tens of percent (Fig. 1, left).
  EXPECT_GT(before, 0.2);

  const IscReport report = correct(patch, fig1_settings(patch.dr));
  ASSERT_TRUE(report.converged) << "residual " << report.residuals.back() << " after "
                                << report.iterations << " iterations";
  EXPECT_LE(report.iterations, 10);
  // Checked with an all-pairs sum, not with the solver's own residual.
  const std::vector<double> density =
      brute_force_density<2>(patch.positions, patch.mass, patch.support_radius);
  EXPECT_LT(max_relative_deviation(density), 1e-10);
  // Reported, not asserted: the uniform-density configuration the iteration reaches has collapsed
  // pairs near the free surface (measured 0.004 dr here; damping the steps does not avoid them),
  // a known limitation documented in models/wcsph/README.md.
  double closest = 1.0;
  for (std::size_t a = 0; a < patch.positions[0].size(); ++a) {
    for (std::size_t b = a + 1; b < patch.positions[0].size(); ++b) {
      closest = std::min(closest, std::hypot(patch.positions[0][a] - patch.positions[0][b],
                                             patch.positions[1][a] - patch.positions[1][b]));
    }
  }
  std::cout << "closest pair after the correction: " << closest / patch.dr << " dr\n";
  for (std::size_t i = 0; i + 1 < report.residuals.size(); ++i) {
    std::cout << "iteration " << i << ": residual " << report.residuals[i] << ", "
              << report.linear_iterations[i] << " CG iterations\n";
  }
}

TEST(InitialStateCorrection, ConvergesQuadraticallyNearTheSolution) {
  Patch patch;
  IscSettings settings = fig1_settings(patch.dr);
  settings.tolerance = 1e-14; // to see the last steps
  const IscReport report = correct(patch, settings);
  const std::vector<double>& r = report.residuals;
  ASSERT_GE(r.size(), 4u);
  // Once the residual is small (< 1e-3), each step at least squares it up to a modest constant:
  // r_{k+1} <= C r_k^2 with C = 100, until the floor of double rounding (~1e-13) is reached.
  int quadratic_steps = 0;
  for (std::size_t k = 0; k + 1 < r.size(); ++k) {
    if (r[k] < 1e-3 && r[k + 1] > 1e-13) {
      EXPECT_LT(r[k + 1], 100.0 * r[k] * r[k]) << "step " << k;
      ++quadratic_steps;
    }
  }
  EXPECT_GE(quadratic_steps, 1);
}

TEST(InitialStateCorrection, SameSeedSameBitsOtherSeedOtherPositions) {
  Patch first, second, third;
  const IscSettings settings = fig1_settings(first.dr);
  IscSettings other = settings;
  other.seed = settings.seed + 1;
  correct(first, settings);
  correct(second, settings);
  correct(third, other);
  EXPECT_EQ(first.positions, second.positions);
  EXPECT_NE(first.positions, third.positions);
}

// The densities and the Jacobian's diagonal are exact integer sums and the off-diagonal entries
// are made pair by pair: the corrected positions do not depend on the thread count.
TEST(InitialStateCorrection, SameBitsOnOneAndTwoThreads) {
  Patch one_thread, two_threads;
  const IscSettings settings = fig1_settings(one_thread.dr);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  correct(one_thread, settings);
  omp_set_num_threads(2);
  correct(two_threads, settings);
  omp_set_num_threads(threads);
  EXPECT_EQ(one_thread.positions, two_threads.positions);
}

TEST(InitialStateCorrection, FixedParticlesCountButDoNotMove) {
  // A patch resting on two layers of fixed (dummy) particles below it.
  Patch patch;
  CoordinateArrays<2> fixed;
  for (int j = 1; j <= 2; ++j) {
    for (int i = -4; i < 34; ++i) {
      fixed[0].push_back((i + 0.5) * patch.dr);
      fixed[1].push_back((0.5 - j) * patch.dr);
    }
  }
  const CoordinateArrays<2> fixed_before = fixed;
  const std::vector<double> masses(patch.positions[0].size(), patch.mass);
  const std::vector<double> fixed_masses(fixed[0].size(), patch.mass);
  const IscReport report =
      correct_initial_state<2>(patch.positions, masses, fixed, fixed_masses, patch.support_radius,
                               rest_density, patch.domain, fig1_settings(patch.dr));
  ASSERT_TRUE(report.converged) << report.residuals.back();
  EXPECT_EQ(fixed, fixed_before);
  // All pairs again, fixed particles included in the sums of the movable ones.
  CoordinateArrays<2> all = patch.positions;
  for (int k = 0; k < 2; ++k) {
    all[k].insert(all[k].end(), fixed[k].begin(), fixed[k].end());
  }
  std::vector<double> density = brute_force_density<2>(all, patch.mass, patch.support_radius);
  density.resize(patch.positions[0].size());
  EXPECT_LT(max_relative_deviation(density), 1e-10);
}

TEST(InitialStateCorrection, ThreeDimensionalCubeConverges) {
  CoordinateArrays<3> points;
  const double dr = 0.1;
  for (int k = 0; k < 8; ++k) {
    for (int j = 0; j < 8; ++j) {
      for (int i = 0; i < 8; ++i) {
        points[0].push_back((i + 0.5) * dr);
        points[1].push_back((j + 0.5) * dr);
        points[2].push_back((k + 0.5) * dr);
      }
    }
  }
  const double mass = rest_density * dr * dr * dr;
  const std::vector<double> masses(points[0].size(), mass);
  IscSettings settings = fig1_settings(dr);
  settings.max_iterations = 15;
  const IscReport report =
      correct_initial_state<3>(points, masses, CoordinateArrays<3>{}, {}, 3 * dr, rest_density,
                               Box<3>{{-1.0, -1.0, -1.0}, {2.0, 2.0, 2.0}}, settings);
  ASSERT_TRUE(report.converged) << report.residuals.back();
  EXPECT_LT(max_relative_deviation(brute_force_density<3>(points, mass, 3 * dr)), 1e-10);
}

TEST(InitialStateCorrection, NonConvergenceIsReportedWithTheResidual) {
  Patch patch;
  IscSettings settings = fig1_settings(patch.dr);
  settings.max_iterations = 1;
  const IscReport report = correct(patch, settings);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.iterations, 1);
  ASSERT_EQ(report.residuals.size(), 2u);
  EXPECT_GT(report.residuals.back(), settings.tolerance);
}

TEST(InitialStateCorrection, IsolatedParticleStopsEarlyWithAReason) {
  Patch patch;
  patch.positions[0].push_back(0.45); // far from the patch: its density is m w(0) whatever moves
  patch.positions[1].push_back(0.45);
  const IscReport report = correct(patch, fig1_settings(patch.dr));
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.stopped_early.find("movable particle 900"), std::string::npos)
      << report.stopped_early;
}

TEST(InitialStateCorrection, LeavingTheDomainThrowsAndLeavesPositionsUnchanged) {
  Patch patch;
  patch.domain = Box<2>{{0.0, 0.0}, {0.3, 0.3}}; // the outermost particles sit 0.005 inside
  const CoordinateArrays<2> before = patch.positions;
  IscSettings settings = fig1_settings(patch.dr);
  settings.jitter = 0.9; // moves some particle out at once
  EXPECT_THROW(correct(patch, settings), std::runtime_error);
  EXPECT_EQ(patch.positions, before);
}

} // namespace
} // namespace revsph::wcsph
