// Particle lattices of case-file blocks: counts, spacing and cell volumes.

#include "core/particle_blocks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using revsph::Box;
using revsph::Lattice;

TEST(Lattice, SquareBlockHoldsOneParticlePerCellAtCellCentres) {
  const auto points = revsph::lattice_points<2>(Lattice::square, Box<2>{{0, 0}, {1, 2}}, 0.02);
  EXPECT_EQ(points.size(), 50u * 100u);
  EXPECT_NEAR(points.front()[0], 0.01, 1e-15);
  EXPECT_NEAR(points.front()[1], 0.01, 1e-15);
  EXPECT_NEAR(points.back()[0], 0.99, 1e-12);
  EXPECT_NEAR(points.back()[1], 1.99, 1e-12);
  EXPECT_DOUBLE_EQ(revsph::lattice_cell_volume<2>(Lattice::square, 0.02), 0.0004);
  const auto cube =
      revsph::lattice_points<3>(Lattice::square, Box<3>{{0, 0, 0}, {1, 0.5, 0.25}}, 0.05);
  EXPECT_EQ(cube.size(), 20u * 10u * 5u);
}

TEST(Lattice, HexagonalBlockHasNearestNeighboursAtTheSpacing) {
  const double spacing = 0.1;
  for (const auto& points :
       {revsph::lattice_points<2>(Lattice::hexagonal, Box<2>{{0, 0}, {2, 2}}, spacing)}) {
    ASSERT_GT(points.size(), 300u);
    double nearest = 1e9;
    for (std::size_t i = 1; i < points.size(); ++i) {
      nearest =
          std::min(nearest, std::hypot(points[i][0] - points[0][0], points[i][1] - points[0][1]));
    }
    EXPECT_NEAR(nearest, spacing, 1e-12);
    // Density of the lattice: one particle per cell volume.
    EXPECT_NEAR(static_cast<double>(points.size()) *
                    revsph::lattice_cell_volume<2>(Lattice::hexagonal, spacing),
                4.0, 0.15);
  }
  const auto hcp =
      revsph::lattice_points<3>(Lattice::hexagonal, Box<3>{{0, 0, 0}, {1, 1, 1}}, spacing);
  double nearest = 1e9;
  const auto& centre = hcp[hcp.size() / 2];
  for (const auto& p : hcp) {
    const double d = std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
    if (d > 0) {
      nearest = std::min(nearest, d);
    }
  }
  EXPECT_NEAR(nearest, spacing, 1e-12);
  EXPECT_NEAR(revsph::lattice_cell_volume<3>(Lattice::hexagonal, spacing),
              std::pow(spacing, 3) / std::sqrt(2.0), 1e-15);
}

TEST(Lattice, BodyCentredCubicHasEightNearestNeighboursAndTwoParticlesPerCube) {
  const double spacing = 0.1;
  const auto bcc = revsph::lattice_points<3>(Lattice::body_centred_cubic,
                                             Box<3>{{-0.5, -0.5, 0.0}, {0.5, 0.5, 1.0}}, spacing);
  // 10 x 10 corner points and 9 x 9 centre points per cube layer, 10 cube layers (20 layers).
  EXPECT_EQ(bcc.size(), 10u * (100u + 81u));
  // An interior point: the one nearest to the block's centre.
  auto distance = [](const revsph::Vec<3>& p, const revsph::Vec<3>& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  };
  revsph::Vec<3> centre = bcc.front();
  for (const auto& p : bcc) {
    if (distance(p, {0.0, 0.0, 0.5}) < distance(centre, {0.0, 0.0, 0.5})) {
      centre = p;
    }
  }
  int nearest_count = 0;
  double nearest = 1e9;
  for (const auto& p : bcc) {
    const double d = std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
    if (d > 0) {
      nearest = std::min(nearest, d);
    }
  }
  for (const auto& p : bcc) {
    const double d = std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
    nearest_count += std::fabs(d - nearest) < 1e-12 ? 1 : 0;
  }
  EXPECT_NEAR(nearest, spacing * std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_EQ(nearest_count, 8);
  EXPECT_NEAR(revsph::lattice_cell_volume<3>(Lattice::body_centred_cubic, spacing),
              std::pow(spacing, 3) / 2.0, 1e-15);
  // Symmetric about the block's axis: both kinds of layer are centred.
  double mean_x = 0.0;
  for (const auto& p : bcc) {
    mean_x += p[0];
  }
  EXPECT_NEAR(mean_x / static_cast<double>(bcc.size()), 0.0, 1e-12);
}

} // namespace
