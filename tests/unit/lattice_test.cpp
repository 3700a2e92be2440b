// Particle lattices of case-file blocks: counts, spacing and cell volumes.

#include "core/particle_blocks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

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
  // 1D: a row of points at the cell centres, each standing for one spacing.
  const auto row = revsph::lattice_points<1>(Lattice::square, Box<1>{{0}, {2}}, 0.01);
  ASSERT_EQ(row.size(), 200u);
  EXPECT_NEAR(row.front()[0], 0.005, 1e-15);
  EXPECT_NEAR(row.back()[0], 1.995, 1e-12);
  for (std::size_t i = 1; i < row.size(); ++i) {
    EXPECT_NEAR(row[i][0] - row[i - 1][0], 0.01, 1e-12);
  }
  EXPECT_DOUBLE_EQ(revsph::lattice_cell_volume<1>(Lattice::square, 0.01), 0.01);
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

TEST(Lattice, AnnulusBlockIsConcentricRingsOfOneParticlePerSpacingSquared) {
  const revsph::CaseFile case_file = revsph::CaseFile::parse(R"([[particles]]
kind = "fluid"
shape = "annulus"
centre = [0.5, -0.25]
inner_radius = 1.0
outer_radius = 2.0
)",
                                                             "annulus test");
  const double spacing = 0.05;
  const std::string_view kinds[] = {"fluid"};
  const auto blocks = revsph::read_particle_blocks<2>(case_file, spacing, Box<2>{{-2, -3}, {3, 2}},
                                                      kinds, {100, 0});
  ASSERT_EQ(blocks.size(), 1u);
  const auto& points = blocks[0].positions;
  // 20 rings at r = 1 + (i + 1/2) spacing, each with round(2 pi r / spacing) points.
  std::size_t expected = 0;
  for (int ring = 0; ring < 20; ++ring) {
    expected += static_cast<std::size_t>(
        std::lround(2.0 * std::numbers::pi * (1.0 + (ring + 0.5) * spacing) / spacing));
  }
  EXPECT_EQ(points.size(), expected);
  double inner = 1e9;
  double outer = 0.0;
  for (const auto& p : points) {
    const double r = std::hypot(p[0] - 0.5, p[1] + 0.25);
    inner = std::min(inner, r);
    outer = std::max(outer, r);
  }
  EXPECT_NEAR(inner, 1.0 + 0.5 * spacing, 1e-12);
  EXPECT_NEAR(outer, 2.0 - 0.5 * spacing, 1e-12);
  // One particle per spacing^2 of the annulus' area (3 pi), to the rounding of the ring counts.
  EXPECT_NEAR(blocks[0].volume_per_particle, spacing * spacing, 1e-3 * spacing * spacing);
}

TEST(Lattice, AnnulusBlockRefusesALatticeAndAThinOrInvertedRing) {
  const std::string_view kinds[] = {"fluid"};
  auto blocks_of = [&](const std::string& extra, double spacing) {
    const revsph::CaseFile case_file = revsph::CaseFile::parse(
        "[[particles]]\nkind = \"fluid\"\nshape = \"annulus\"\ncentre = [0, 0]\n" + extra,
        "annulus test");
    return revsph::read_particle_blocks<2>(case_file, spacing, Box<2>{{-3, -3}, {3, 3}}, kinds,
                                           {100, 0});
  };
  EXPECT_THROW(blocks_of("inner_radius = 1.0\nouter_radius = 2.0\nlattice = \"square\"\n", 0.1),
               revsph::CaseError);
  EXPECT_THROW(blocks_of("inner_radius = 1.0\nouter_radius = 1.05\n", 0.1), revsph::CaseError);
  EXPECT_THROW(blocks_of("inner_radius = 2.0\nouter_radius = 1.0\n", 0.1), revsph::CaseError);
  EXPECT_NO_THROW(blocks_of("inner_radius = 0.0\nouter_radius = 1.0\n", 0.1));
}

} // namespace
