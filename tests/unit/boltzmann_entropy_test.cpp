// The Boltzmann-entropy analysis (paper 1, Appendix B): Maxwell–Boltzmann samples recover their
// θ and equilibrium entropy from a 100-bin histogram, distributions away from equilibrium have a
// lower entropy at the same energy, degenerate inputs give finite or explicitly flagged values, and
// `revsph entropy` reads a verify experiment.

#include "core/snapshot_file.hpp"
#include "temp_directory.hpp"
#include "tools/analysis/boltzmann_entropy.hpp"
#include "tools/revsph/commands.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using namespace revsph::analysis;

// Speeds of `count` velocity vectors whose D components are independent Gaussians of variance θ:
// an exact Maxwell–Boltzmann sample.
std::vector<double> maxwell_speeds(int dimension, double theta, std::size_t count,
                                   std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> component(0.0, std::sqrt(theta));
  std::vector<double> speeds(count);
  for (double& speed : speeds) {
    double square = 0.0;
    for (int c = 0; c < dimension; ++c) {
      const double v = component(generator);
      square += v * v;
    }
    speed = std::sqrt(square);
  }
  return speeds;
}

double kinetic_energy(const std::vector<double>& speeds, double mass) {
  double energy = 0.0;
  for (const double speed : speeds) {
    energy += 0.5 * mass * speed * speed;
  }
  return energy;
}

double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

struct Case {
  int dimension;
  double theta;
  std::uint64_t seed;
};

class MaxwellSample : public ::testing::TestWithParam<Case> {};

// The accuracy targets: 10^5 particles, 100 bins up to the largest speed. The sampling noise of
// θ itself is about 1/√N ≈ 0.3 % (2D), i.e. about 0.003 in S; the errors are printed so that the
// margin is visible.
TEST_P(MaxwellSample, RecoversThetaAndEquilibriumEntropyWithinOnePercent) {
  const Case c = GetParam();
  constexpr std::size_t particles = 100'000;
  constexpr double mass = 1.7;
  const std::vector<double> speeds = maxwell_speeds(c.dimension, c.theta, particles, c.seed);
  const SpeedHistogram histogram = speed_histogram(speeds);
  ASSERT_EQ(histogram.bins(), default_speed_bins);
  ASSERT_EQ(histogram.binned(), particles);

  const double theta_fit = fit_theta(histogram, c.dimension);
  const double theta_moment = moment_theta(speeds, c.dimension);
  const double entropy = reduced_entropy(histogram, c.dimension);
  const double entropy_equilibrium = equilibrium_entropy(c.theta, c.dimension);
  const double entropy_from_energy = equilibrium_entropy_from_energy(
      kinetic_energy(speeds, mass), static_cast<double>(particles), mass, c.dimension);
  std::cout << c.dimension << "D theta = " << c.theta << ": theta_fit error "
            << 100 * (theta_fit / c.theta - 1) << " %, theta_moment error "
            << 100 * (theta_moment / c.theta - 1) << " %, S = " << entropy
            << " vs S_eq(theta) = " << entropy_equilibrium << " (error "
            << 100 * (entropy / entropy_equilibrium - 1) << " %), S_eq(E) = " << entropy_from_energy
            << " (error " << 100 * (entropy_from_energy / entropy_equilibrium - 1) << " %)\n";

  EXPECT_LT(relative_error(theta_fit, c.theta), 0.01);
  EXPECT_LT(relative_error(theta_moment, c.theta), 0.01);
  EXPECT_LT(relative_error(entropy, entropy_equilibrium), 0.01);
  EXPECT_LT(relative_error(entropy_from_energy, entropy_equilibrium), 0.01);
  // The quadrature itself, without the sample's own deviation from θ: the histogram entropy
  // against the equilibrium entropy at the sample's energy. Bias of 100 bins plus the plug-in
  // estimator's (bins − 1)/(2N) is below 1e-3.
  EXPECT_NEAR(entropy, entropy_from_energy, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(TwoAndThreeDimensions, MaxwellSample,
                         ::testing::Values(Case{2, 0.7, 20230001}, Case{2, 2.3, 20230002},
                                           Case{3, 0.7, 20230003}, Case{3, 2.3, 20230004}),
                         [](const ::testing::TestParamInfo<Case>& test) {
                           return std::to_string(test.param.dimension) + "D_theta" +
                                  (test.param.theta < 1 ? "0p7" : "2p3");
                         });

// The 3D formulas were derived for this code (header of boltzmann_entropy.hpp); check them, and
// the 2D ones, against direct quadrature of the densities on a fine grid.
TEST(MaxwellBoltzmann, DensityCdfAndEquilibriumEntropyAgreeWithQuadrature) {
  for (const int dimension : {2, 3}) {
    for (const double theta : {0.05, 0.7, 2.3}) {
      constexpr int steps = 200'000;
      const double top = 12.0 * std::sqrt(theta);
      const double h = top / steps;
      double mass = 0.0;
      double second_moment = 0.0;
      double entropy = 0.0;
      for (int i = 0; i < steps; ++i) {
        const double v = (i + 0.5) * h;
        const double f = maxwell_boltzmann_density(v, theta, dimension);
        mass += f * h;
        second_moment += f * v * v * h;
        if (f > 0.0) {
          entropy -= f * std::log(f / std::pow(v, dimension - 1)) * h;
        }
        if (i % 20'000 == 0) {
          const double cdf_slope =
              (maxwell_boltzmann_cdf(v + 1e-6, theta, dimension) -
               maxwell_boltzmann_cdf(v - 1e-6 < 0 ? 0 : v - 1e-6, theta, dimension)) /
              (v + 1e-6 - (v - 1e-6 < 0 ? 0 : v - 1e-6));
          EXPECT_NEAR(cdf_slope, f, 1e-6 / std::sqrt(theta));
        }
      }
      EXPECT_NEAR(mass, 1.0, 1e-9);
      EXPECT_NEAR(second_moment, dimension * theta, 1e-8 * theta); // <v²> = Dθ
      EXPECT_NEAR(entropy, equilibrium_entropy(theta, dimension), 1e-8);
      EXPECT_NEAR(maxwell_boltzmann_cdf(top, theta, dimension), 1.0, 1e-12);
    }
  }
  // Eq. (20) and (21) as printed, in 2D; E = (D/2) N m θ.
  EXPECT_DOUBLE_EQ(equilibrium_entropy(2.3, 2), 1.0 + std::log(2.3));
  EXPECT_DOUBLE_EQ(equilibrium_entropy_from_energy(10.0, 4.0, 0.5, 2), 1.0 + std::log(5.0));
  EXPECT_DOUBLE_EQ(equilibrium_entropy(2.3, 3),
                   1.5 + 1.5 * std::log(2.3) + 0.5 * std::log(std::numbers::pi / 2));
  EXPECT_DOUBLE_EQ(theta_from_energy(15.0, 4.0, 0.5, 3), 5.0);
}

// Second law direction: at a given kinetic energy the Maxwell–Boltzmann distribution has the
// largest reduced entropy, so anything else lies below S_eq(E).
TEST(BoltzmannEntropy, NonEquilibriumDistributionsLieBelowTheEquilibriumAtTheirEnergy) {
  for (const int dimension : {2, 3}) {
    constexpr std::size_t particles = 100'000;
    // Every particle at the same speed (a thin shell in velocity space).
    const std::vector<double> same_speed(particles, 1.3);
    const double same_speed_entropy = reduced_entropy(speed_histogram(same_speed), dimension);
    const double same_speed_equilibrium =
        equilibrium_entropy_from_energy(kinetic_energy(same_speed, 1.0), particles, 1.0, dimension);
    EXPECT_TRUE(std::isfinite(same_speed_entropy));
    EXPECT_LT(same_speed_entropy, same_speed_equilibrium - 1.0);

    // A narrow Gaussian shell |v| ~ N(2, 0.1²).
    std::mt19937_64 generator(77 + dimension);
    std::normal_distribution<double> shell_speed(2.0, 0.1);
    std::vector<double> shell(particles);
    for (double& speed : shell) {
      speed = std::abs(shell_speed(generator));
    }
    const double shell_entropy = reduced_entropy(speed_histogram(shell), dimension);
    const double shell_equilibrium =
        equilibrium_entropy_from_energy(kinetic_energy(shell, 1.0), particles, 1.0, dimension);
    EXPECT_LT(shell_entropy, shell_equilibrium - 0.5);

    // Relaxation at constant energy: a fraction λ of the shell replaced by a Maxwell–Boltzmann
    // sample of the same energy. The entropy is concave and maximal at λ = 1, so it grows with λ
    // (bins shared, as `revsph entropy` shares them over a run).
    const double theta = moment_theta(shell, dimension);
    const std::vector<double> thermal = maxwell_speeds(dimension, theta, particles, 99);
    double previous = -std::numeric_limits<double>::infinity();
    for (const double lambda : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const auto thermal_count = static_cast<std::size_t>(lambda * particles);
      std::vector<double> mixed(thermal.begin(),
                                thermal.begin() + static_cast<std::ptrdiff_t>(thermal_count));
      mixed.insert(mixed.end(), shell.begin() + static_cast<std::ptrdiff_t>(thermal_count),
                   shell.end());
      const double entropy = reduced_entropy(speed_histogram(mixed, 100, 6.0), dimension);
      EXPECT_GT(entropy, previous + 0.05) << "lambda = " << lambda;
      previous = entropy;
    }
    EXPECT_NEAR(previous, equilibrium_entropy(theta, dimension), 0.02);
  }
}

TEST(BoltzmannEntropy, EdgeCasesAreFiniteOrExplicitlyFlagged) {
  for (const int dimension : {2, 3}) {
    // Every particle at rest (the dam break at t = 0) with no range given: no bins to resolve;
    // S → −∞ is the limit of a distribution concentrated at v = 0.
    const std::vector<double> at_rest(1000, 0.0);
    const SpeedHistogram degenerate = speed_histogram(at_rest);
    EXPECT_TRUE(degenerate.degenerate());
    EXPECT_EQ(degenerate.counts[0], at_rest.size());
    EXPECT_EQ(reduced_entropy(degenerate, dimension), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(fit_theta(degenerate, dimension), 0.0);
    EXPECT_EQ(moment_theta(at_rest, dimension), 0.0);
    EXPECT_EQ(equilibrium_entropy(0.0, dimension), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(equilibrium_entropy_from_energy(0.0, 1000, 1.0, dimension),
              -std::numeric_limits<double>::infinity());

    // At rest but with the run's range: everything in the first bin, the lowest entropy the bins
    // resolve, −ln(f_1 / c_1^(D−1)) with f_1 = 1/Δv, c_1 = Δv/2.
    const SpeedHistogram resting_in_range = speed_histogram(at_rest, 100, 5.0);
    const double width = 0.05;
    EXPECT_NEAR(reduced_entropy(resting_in_range, dimension),
                std::log(width) + (dimension - 1) * std::log(width / 2), 1e-12);
    EXPECT_TRUE(std::isfinite(fit_theta(resting_in_range, dimension)));

    // A single particle.
    const std::vector<double> single{0.8};
    const SpeedHistogram one = speed_histogram(single);
    EXPECT_TRUE(std::isfinite(reduced_entropy(one, dimension)));
    const double theta_single = fit_theta(one, dimension);
    EXPECT_TRUE(std::isfinite(theta_single));
    EXPECT_GT(theta_single, 0.0);
    EXPECT_DOUBLE_EQ(moment_theta(single, dimension), 0.64 / dimension);

    // Empty bins: two clusters far apart and a range well beyond both.
    std::vector<double> clusters(500, 0.3);
    clusters.insert(clusters.end(), 500, 2.0);
    const SpeedHistogram gappy = speed_histogram(clusters, 100, 10.0);
    EXPECT_EQ(std::count(gappy.counts.begin(), gappy.counts.end(), 0u), 98);
    EXPECT_TRUE(std::isfinite(reduced_entropy(gappy, dimension)));
    EXPECT_TRUE(std::isfinite(fit_theta(gappy, dimension)));

    // Speeds above an explicit range are counted, not binned; with none left, NaN and
    // binned() == 0 say so.
    const SpeedHistogram partial = speed_histogram(clusters, 100, 1.0);
    EXPECT_EQ(partial.above_max, 500u);
    EXPECT_TRUE(std::isfinite(reduced_entropy(partial, dimension)));
    const SpeedHistogram none_left = speed_histogram(std::vector<double>{3.0, 4.0}, 10, 1.0);
    EXPECT_EQ(none_left.binned(), 0u);
    EXPECT_TRUE(std::isnan(reduced_entropy(none_left, dimension)));
    EXPECT_TRUE(std::isnan(fit_theta(none_left, dimension)));
  }

  // The largest speed lands in the last (closed) bin.
  const SpeedHistogram closed = speed_histogram(std::vector<double>{0.0, 1.0, 3.0}, 3);
  EXPECT_EQ(closed.counts, (std::vector<std::size_t>{1, 1, 1}));
  EXPECT_DOUBLE_EQ(closed.edges.back(), 3.0);

  // Bad input is refused, not turned into NaN.
  const std::vector<double> ok{1.0};
  EXPECT_THROW(speed_histogram(std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(speed_histogram(std::vector<double>{-1.0}), std::invalid_argument);
  EXPECT_THROW(speed_histogram(std::vector<double>{std::nan("")}), std::invalid_argument);
  EXPECT_THROW(speed_histogram(ok, 0), std::invalid_argument);
  EXPECT_THROW(speed_histogram(ok, 10, 0.0), std::invalid_argument);
  EXPECT_THROW(reduced_entropy(speed_histogram(ok), 4), std::invalid_argument);
  EXPECT_THROW(equilibrium_entropy(-1.0, 2), std::invalid_argument);
  EXPECT_THROW(equilibrium_entropy_from_energy(1.0, 0.0, 1.0, 2), std::invalid_argument);
  EXPECT_THROW(maxwell_boltzmann_density(1.0, 0.0, 3), std::invalid_argument);
}

// --- revsph entropy on a hand-made verify experiment -------------------------------------------

void write_velocity_snapshot(const fs::path& path, std::int64_t step, double dt,
                             const std::vector<std::array<double, 2>>& velocities) {
  revsph::StateSnapshot state;
  revsph::FieldSnapshot velocity{
      {"fluid", "velocity", "m/s", revsph::Parity::odd, 2, revsph::fixedpoint::Scale(0), true},
      revsph::RawKind::ieee_double,
      velocities.size(),
      {}};
  for (int c = 0; c < 2; ++c) {
    for (const auto& v : velocities) {
      velocity.bits.push_back(std::bit_cast<std::int64_t>(v[static_cast<std::size_t>(c)]));
    }
  }
  revsph::FieldSnapshot mass{
      {"fluid", "mass", "kg/m", revsph::Parity::even, 1, revsph::fixedpoint::Scale(0), false},
      revsph::RawKind::ieee_double,
      velocities.size(),
      std::vector<std::int64_t>(velocities.size(), std::bit_cast<std::int64_t>(0.4))};
  state.fields = {velocity, mass};
  revsph::SnapshotMetadata metadata;
  metadata.model = "toy";
  metadata.dimension = 2;
  metadata.arithmetic = revsph::Arithmetic::floating;
  metadata.case_name = "toy";
  metadata.step = step;
  metadata.time = static_cast<double>(step) * dt;
  metadata.dt = dt;
  metadata.state_hash = revsph::state_hash(state);
  fs::create_directories(path.parent_path());
  revsph::write_snapshot(path, metadata, state, std::vector<revsph::ParticleView>{});
}

std::vector<std::map<std::string, std::string>> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream header_stream(line);
  for (std::string name; std::getline(header_stream, name, ',');) {
    header.push_back(name);
  }
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::stringstream row_stream(line);
    std::map<std::string, std::string> row;
    for (const std::string& name : header) {
      std::getline(row_stream, row[name], ',');
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(EntropyCommand, ReadsAVerifyExperimentAndRetracesTimeBackwards) {
  revsph::testing::TempDirectory directory("revsph-entropy-test");
  const fs::path run = directory.path();
  const double dt = 0.1;
  const std::vector<std::array<double, 2>> at_rest(50, {0.0, 0.0});
  std::vector<std::array<double, 2>> moving;
  for (int i = 0; i < 50; ++i) {
    moving.push_back({0.1 * i, -0.05 * i});
  }
  // Forward 0 → 10 steps, reversal (velocities negated), backward 10 → 20 steps.
  std::vector<std::array<double, 2>> reversed = moving;
  for (auto& v : reversed) {
    v = {-v[0], -v[1]};
  }
  write_velocity_snapshot(run / "forward/snapshots/step_000000000.h5", 0, dt, at_rest);
  write_velocity_snapshot(run / "forward/snapshots/step_000000010.h5", 10, dt, moving);
  write_velocity_snapshot(run / "backward/snapshots/step_000000010.h5", 10, dt, reversed);
  write_velocity_snapshot(run / "backward/snapshots/step_000000020.h5", 20, dt, at_rest);
  std::ofstream(run / "summary.json") << R"({"reversal_step": 10, "dt": 0.1})";

  revsph::cli::EntropyOptions options;
  options.run_dir = run.string();
  options.bins = 10;
  options.plots = false;
  ASSERT_EQ(revsph::cli::entropy_command(options), revsph::cli::success);

  const auto rows = read_csv(run / "analysis" / "entropy.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].at("phase"), "forward");
  EXPECT_EQ(rows[3].at("phase"), "backward");
  EXPECT_DOUBLE_EQ(std::stod(rows[2].at("forward_equivalent_time")), 1.0);
  EXPECT_DOUBLE_EQ(std::stod(rows[3].at("forward_equivalent_time")), 0.0);
  EXPECT_EQ(rows[0].at("S_reduced"), rows[3].at("S_reduced")) << "same speeds, same bins";
  EXPECT_EQ(rows[1].at("S_reduced"), rows[2].at("S_reduced"));
  EXPECT_LT(std::stod(rows[0].at("S_reduced")), std::stod(rows[1].at("S_reduced")));
  EXPECT_EQ(rows[0].at("S_eq_energy"), "-inf"); // at rest: E = 0
  const double energy = std::stod(rows[1].at("kinetic_energy"));
  double expected_energy = 0.0;
  for (const auto& v : moving) {
    expected_energy += 0.5 * 0.4 * (v[0] * v[0] + v[1] * v[1]);
  }
  EXPECT_NEAR(energy, expected_energy, 1e-9 * expected_energy);

  const auto histogram = read_csv(run / "analysis" / "histograms.csv");
  ASSERT_EQ(histogram.size(), 20u);
  EXPECT_EQ(histogram.front().at("snapshot"), "turning_point");
  EXPECT_EQ(histogram.back().at("snapshot"), "final");

  options.run_dir = (run / "nowhere").string();
  EXPECT_EQ(revsph::cli::entropy_command(options), revsph::cli::bad_input);
}

} // namespace
