#include "two_fluid_entropy_wave.hpp"

#include "core/kernel_wendland.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace revsph::analysis {

namespace {

using WaveMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

constexpr int dimension = 2; // D_s of (A4), (A8)

// Lattice offsets a neighbour can have: the support plus the displacement of both particles
// (2 dl < l) stays within ceil(support / l) + 1 nodes along each axis.
int lattice_reach(double support_over_l) {
  return static_cast<int>(std::ceil(support_over_l)) + 1;
}

// A lattice index k, possibly outside 0..n-1 (by less than n), as the node it images: the odd
// mirror image across x = 0 of node k' is node -1 - k' (at -(k' + 1/2) l), across x = 1 node
// 2 n - 1 - k'. The coordinate of the image of a source at x: -x, 2 - x or x.
struct Image {
  int node;
  int side; // -1: across the low side (x = 0), +1: across the high side (x = 1), 0: none
  double sign() const { return side == 0 ? 1.0 : -1.0; }
  double coordinate(double x) const { return side < 0 ? -x : (side > 0 ? 2.0 - x : x); }
};
Image image_of(int k, int n) {
  if (k < 0) {
    return {-1 - k, -1};
  }
  if (k >= n) {
    return {2 * n - 1 - k, 1};
  }
  return {k, 0};
}

// Calls f(source, sign, r) for every particle and ghost other than particle (i, j) itself within
// the candidate offsets: r = |r_i - r_j| for the image j of `source`, sign its factor on S (-1 per
// reflection).
template <class F>
void for_each_neighbour(const WaveParticles& particles, int i, int j, F&& f) {
  const int n = particles.per_side;
  const int reach = lattice_reach(particles.support_over_l);
  const std::array<double, 2>& xi = particles.position[static_cast<std::size_t>(j) * n + i];
  for (int dj = -reach; dj <= reach; ++dj) {
    const Image y_image = image_of(j + dj, n);
    for (int di = -reach; di <= reach; ++di) {
      if (di == 0 && dj == 0) {
        continue;
      }
      const Image x_image = image_of(i + di, n);
      const std::size_t source = static_cast<std::size_t>(y_image.node) * n + x_image.node;
      const std::array<double, 2>& xs = particles.position[source];
      const double dx = xi[0] - x_image.coordinate(xs[0]);
      const double dy = xi[1] - y_image.coordinate(xs[1]);
      f(source, x_image.sign() * y_image.sign(), std::sqrt(dx * dx + dy * dy));
    }
  }
}

// One row of L: the coefficients c_ij of L phi_i = sum_j c_ij (phi_j - phi_i) over the particles
// and ghosts j, folded onto the sources: column source += sign c_ij, the diagonal -= c_ij.
struct Row {
  std::vector<std::pair<std::size_t, double>> entries;
  void add(std::size_t self, std::size_t source, double sign, double coefficient) {
    entries.emplace_back(source, sign * coefficient);
    entries.emplace_back(self, -coefficient);
  }
};

// V_j = 1 / sum_k W_jk, the self term included: the particle volume of the Brookshaw form. A
// ghost's volume is its source's (the images are mirror-symmetric).
std::vector<double> kernel_volumes(const WaveParticles& particles,
                                   const WendlandQuintic<2>& kernel) {
  const int n = particles.per_side;
  std::vector<double> volume(particles.position.size());
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      double sum = kernel.value(0.0);
      for_each_neighbour(particles, i, j,
                         [&](std::size_t, double, double r) { sum += kernel.value(r); });
      volume[static_cast<std::size_t>(j) * n + i] = 1.0 / sum;
    }
  }
  return volume;
}

void fill_row(const WaveParticles& particles, WaveLaplacian method,
              const WendlandQuintic<2>& kernel, const std::vector<double>& volume, int i, int j,
              Row& row) {
  const int n = particles.per_side;
  const std::size_t self = static_cast<std::size_t>(j) * n + i;
  if (method == WaveLaplacian::fd) {
    // (phi_E + phi_W + phi_N + phi_S - 4 phi) / l^2; a node beyond a side is the odd image of the
    // node inside, which puts the zero on the side (the nodes sit l / 2 inside it).
    const double c = 1.0 / (particles.spacing * particles.spacing);
    for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const Image x_image = image_of(i + di, n);
      const Image y_image = image_of(j + dj, n);
      row.add(self, static_cast<std::size_t>(y_image.node) * n + x_image.node,
              x_image.sign() * y_image.sign(), c);
    }
    return;
  }
  if (method == WaveLaplacian::brookshaw) {
    // Eq. (14) = (A1): lap phi_i = 2 sum_j V_j (phi_i - phi_j) r_ij . grad_i W_ij / |r_ij|^2,
    // with grad_i W_ij = W'(r) r_ij / r, so c_ij = -2 V_j W'(r) / r >= 0. The paper prints (14)
    // without the 2: on a lattice sum_j V_j (x_j - x_i)^2 (-W'/r) -> int x^2 (-W'(r)/r) dA
    // = pi int r^2 (-W') dr = 2 pi int r W dr = 1, half of lap x^2 = 2. On the unperturbed
    // lattice the sums miss these integrals (kernel aliasing at support 3 l, the bias of paper 4's
    // volume sum): the form gives 2.977 for lap = 3, so its wave is 0.4 % slow.
    for_each_neighbour(particles, i, j, [&](std::size_t source, double sign, double r) {
      const double c = -2.0 * volume[source] * kernel.derivative_over_r(r);
      if (c != 0.0) {
        row.add(self, source, sign, c);
      }
    });
    return;
  }
  // App. A: w_ij = -(1 / (2 D_s)) r_ij . grad W_ij = -W'(r) r / (2 D_s) >= 0 (A4) (positive
  // inside the support for the Wendland quintic, as (A3) needs), P_ij = w_ij / sum_j w_ij (A3),
  // tau_i = sum_j |r_ij|^2 P_ij (A9), lap phi_i = (2 D_s / tau_i) sum_j (phi_j - phi_i) P_ij (A8).
  // The normalisation sum_j w_ij cancels: c_ij = 2 D_s w_ij / sum_j w_ij |r_ij|^2. On the
  // unperturbed lattice tau divides out the lattice's own second moment, so a quadratic comes out
  // exact, but the first moment sum_j P_ij r_ji ~ dl no longer vanishes once the particles are
  // displaced: an error ~ (dl / l^2) |grad phi| (at 400^2, dD = 0.5 %: 7 % of lap phi on average
  // for phi quadratic with lap phi = 3 and |grad phi| ~ 0.5; 30 % at dD = 2 %).
  const std::size_t first = row.entries.size();
  double second_moment = 0.0;
  for_each_neighbour(particles, i, j, [&](std::size_t source, double sign, double r) {
    const double w = -kernel.derivative(r) * r / (2.0 * dimension);
    if (w != 0.0) {
      second_moment += w * r * r;
      row.add(self, source, sign, w);
    }
  });
  const double scale = 2.0 * dimension / second_moment;
  for (std::size_t e = first; e < row.entries.size(); ++e) {
    row.entries[e].second *= scale;
  }
}

// L with the ghosts folded in, row i the operator at particle i.
WaveMatrix laplacian_matrix(const WaveParticles& particles, WaveLaplacian method) {
  const int n = particles.per_side;
  const auto count = static_cast<Eigen::Index>(particles.position.size());
  const WendlandQuintic<2> kernel(particles.support_over_l * particles.spacing);
  const std::vector<double> volume = method == WaveLaplacian::brookshaw
                                         ? kernel_volumes(particles, kernel)
                                         : std::vector<double>{};
  const int reach = lattice_reach(particles.support_over_l);
  WaveMatrix matrix(count, count);
  matrix.reserve(count * (method == WaveLaplacian::fd ? 5 : (2 * reach + 1) * (2 * reach + 1)));
  Row row;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      row.entries.clear();
      fill_row(particles, method, kernel, volume, i, j, row);
      std::sort(row.entries.begin(), row.entries.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      const auto r = static_cast<Eigen::Index>(j) * n + i;
      matrix.startVec(r);
      for (std::size_t e = 0; e < row.entries.size();) {
        double sum = 0.0;
        const std::size_t column = row.entries[e].first;
        for (; e < row.entries.size() && row.entries[e].first == column; ++e) {
          sum += row.entries[e].second;
        }
        matrix.insertBack(r, static_cast<Eigen::Index>(column)) = sum;
      }
    }
  }
  matrix.finalize();
  return matrix;
}

double mode(const std::array<double, 2>& x) {
  return std::sin(4.0 * std::numbers::pi * x[0]) * std::sin(3.0 * std::numbers::pi * x[1]);
}

// A uniform double in [0, 1) from the engine's top 53 bits: the same on every standard library
// (std::uniform_real_distribution's algorithm is unspecified).
double uniform(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// A uniformly distributed direction by rejection from the square [-1, 1)^2: only +, *, / and
// sqrt, all correctly rounded in IEEE arithmetic, where cos and sin of a uniform angle would
// depend on the C library's last bits.
std::array<double, 2> random_direction(std::mt19937_64& engine) {
  for (;;) {
    const double u = 2.0 * uniform(engine) - 1.0;
    const double v = 2.0 * uniform(engine) - 1.0;
    const double r2 = u * u + v * v;
    if (r2 > 1e-12 && r2 <= 1.0) {
      const double r = std::sqrt(r2);
      return {u / r, v / r};
    }
  }
}

} // namespace

std::string_view name_of(WaveLaplacian method) {
  switch (method) {
  case WaveLaplacian::sph:
    return "sph";
  case WaveLaplacian::brookshaw:
    return "brookshaw";
  case WaveLaplacian::fd:
    return "fd";
  }
  return "?";
}

WaveLaplacian wave_laplacian_named(std::string_view name) {
  for (const WaveLaplacian m : {WaveLaplacian::sph, WaveLaplacian::brookshaw, WaveLaplacian::fd}) {
    if (name == name_of(m)) {
      return m;
    }
  }
  throw std::invalid_argument("unknown Laplacian '" + std::string(name) +
                              "' (known: sph, brookshaw, fd)");
}

double displacement_for(double fluctuation_percent, double spacing) {
  return spacing * (std::sqrt(1.0 + fluctuation_percent / 100.0) - 1.0);
}

WaveParticles wave_particles(int per_side, double fluctuation_percent, std::uint64_t seed,
                             double support_over_l) {
  if (!(support_over_l >= 1.5 && support_over_l <= 6.0)) {
    throw std::invalid_argument("the kernel's support must be in [1.5, 6] spacings");
  }
  if (per_side <= 2 * lattice_reach(support_over_l)) {
    throw std::invalid_argument("the entropy wave needs more than " +
                                std::to_string(2 * lattice_reach(support_over_l)) +
                                " particles per side");
  }
  WaveParticles particles;
  particles.support_over_l = support_over_l;
  particles.per_side = per_side;
  particles.spacing = 1.0 / per_side;
  particles.displacement = displacement_for(fluctuation_percent, particles.spacing);
  if (!(fluctuation_percent >= 0.0) || !(particles.displacement < 0.5 * particles.spacing)) {
    throw std::invalid_argument("the volume fluctuation rate must be in [0, 125) %");
  }
  std::mt19937_64 engine(seed);
  particles.position.reserve(static_cast<std::size_t>(per_side) * per_side);
  for (int j = 0; j < per_side; ++j) {
    for (int i = 0; i < per_side; ++i) {
      const std::array<double, 2> e = random_direction(engine);
      particles.position.push_back({(i + 0.5) * particles.spacing + particles.displacement * e[0],
                                    (j + 0.5) * particles.spacing + particles.displacement * e[1]});
    }
  }
  return particles;
}

std::vector<double> apply_wave_laplacian(const WaveParticles& particles, WaveLaplacian method,
                                         std::span<const double> phi) {
  const WaveMatrix matrix = laplacian_matrix(particles, method);
  const Eigen::Map<const Eigen::VectorXd> in(phi.data(), static_cast<Eigen::Index>(phi.size()));
  const Eigen::VectorXd out = matrix * in;
  return {out.data(), out.data() + out.size()};
}

EntropyWaveResult entropy_wave(const EntropyWaveOptions& options) {
  if (!(options.speed > 0.0) || !(options.t_end > 0.0) || !(options.dt_factor > 0.0) ||
      options.probe_every < 1) {
    throw std::invalid_argument("speed, t_end, dt_factor and probe_every must be positive");
  }
  if (options.method == WaveLaplacian::fd && options.fluctuation_percent != 0.0) {
    throw std::invalid_argument("fd lives on the unperturbed lattice: its fluctuation must be 0");
  }
  const WaveParticles particles = wave_particles(options.per_side, options.fluctuation_percent,
                                                 options.seed, options.support_over_l);
  EntropyWaveResult result;
  result.spacing = particles.spacing;
  result.displacement = particles.displacement;

  // dt = dt_factor l / c, shortened so that a whole number of steps ends at t_end. The leapfrog's
  // own phase error: cos(w' dt) = 1 - (w dt)^2 / 2 gives w' = w (1 + (w dt)^2 / 24), and
  // lambda dt = 5 pi c dt = 5 pi dt_factor / per_side is 3.9e-3 at the defaults for either c:
  // lambda t_end (lambda dt)^2 / 24 = 63.6 x 6.4e-7 = 4.1e-5 rad for c = 135 (6.1e-6 for c = 20),
  // against 2.2e-3 rad of the 5-point Laplacian's dispersion (its frequency is low by
  // (k_x^4 + k_y^4) l^2 / (24 k^2) = 3.5e-5). Measured with fd at 400^2, c = 135: its mode
  // amplitude at t_end for dt_factor 0.05, 0.1, 0.2 extrapolates to 4.1e-5 rad at 0.1.
  const double nominal = options.dt_factor * particles.spacing / options.speed;
  result.steps =
      std::max(1L, static_cast<long>(std::ceil(options.t_end / nominal * (1.0 - 1e-12))));
  result.dt = options.t_end / static_cast<double>(result.steps);

  WaveMatrix step_matrix = laplacian_matrix(particles, options.method);
  result.nonzeros = static_cast<std::size_t>(step_matrix.nonZeros());
  const double cdt = options.speed * result.dt;
  step_matrix *= cdt * cdt;

  const auto count = static_cast<Eigen::Index>(particles.position.size());
  Eigen::VectorXd previous(count);
  for (Eigen::Index p = 0; p < count; ++p) {
    previous[p] = mode(particles.position[static_cast<std::size_t>(p)]);
  }
  // The start: dS/dt = 0 makes the exact solution even in t, so S^{-1} = S^1 and the central
  // difference at n = 0 gives S^1 = S^0 + dt^2 c^2 L S^0 / 2. (Taking S^{-1} from the exact
  // solution instead would start from the true Laplacian, not L's, an O(dt^2) mismatch.)
  Eigen::VectorXd product = step_matrix * previous;
  Eigen::VectorXd current = previous + 0.5 * product;

  // The probe: the particle of the lattice node whose cell holds options.probe, the same particle
  // for every dD (the default (0.3, 0.4) lies on cell edges for per_side = 100 or 400, where the
  // particle nearest to it would depend on the displacements).
  const auto cell = [&](double x) {
    return std::clamp(static_cast<int>(std::floor(x * particles.per_side)), 0,
                      particles.per_side - 1);
  };
  const auto probe = static_cast<Eigen::Index>(cell(options.probe[1])) * particles.per_side +
                     cell(options.probe[0]);
  result.probe_position = particles.position[static_cast<std::size_t>(probe)];
  const double lambda = 5.0 * std::numbers::pi * options.speed; // (47), (m, n) = (4, 3)
  const double probe_mode = mode(result.probe_position);
  const auto sample = [&](long n, double value) {
    const double t = static_cast<double>(n) * result.dt;
    result.probe_time.push_back(t);
    result.probe_value.push_back(value);
    result.probe_exact.push_back(std::cos(lambda * t) * probe_mode);
  };
  sample(0, previous[probe]);
  if (result.steps == 1 || options.probe_every == 1) {
    sample(1, current[probe]);
  }
  for (long n = 1; n < result.steps; ++n) {
    product.noalias() = step_matrix * current;
    previous = 2.0 * current - previous + product; // S^{n+1}, into S^{n-1}'s storage
    previous.swap(current);
    if ((n + 1) % options.probe_every == 0 || n + 1 == result.steps) {
      sample(n + 1, current[probe]);
    }
  }

  const double amplitude = 1.0; // A
  const double phase = std::cos(lambda * options.t_end);
  double sum_sf = 0.0;
  double sum_ff = 0.0;
  for (Eigen::Index p = 0; p < count; ++p) {
    const double f = mode(particles.position[static_cast<std::size_t>(p)]);
    sum_sf += current[p] * f;
    sum_ff += f * f;
  }
  result.mode_amplitude = sum_sf / sum_ff;
  double sum = 0.0;
  double literal_sum = 0.0;
  double off_mode_sum = 0.0;
  for (Eigen::Index p = 0; p < count; ++p) {
    const double f = mode(particles.position[static_cast<std::size_t>(p)]);
    const double exact = phase * f;
    const double difference = std::abs(current[p] - exact);
    const double denominator = (std::abs(exact) + amplitude) / 100.0;
    const double error = difference / denominator;
    sum += error;
    literal_sum += difference / (std::abs(exact + amplitude) / 100.0);
    result.max_error_percent = std::max(result.max_error_percent, error);
    off_mode_sum += std::abs(current[p] - result.mode_amplitude * f) / denominator;
  }
  result.mean_error_percent = sum / static_cast<double>(count);
  result.literal_error_percent = literal_sum / static_cast<double>(count);
  result.off_mode_error_percent = off_mode_sum / static_cast<double>(count);
  return result;
}

} // namespace revsph::analysis
