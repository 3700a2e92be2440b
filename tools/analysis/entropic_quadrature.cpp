#include "entropic_quadrature.hpp"

#include "core/arithmetic.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/pair_system.hpp"
#include "core/particle_blocks.hpp"
#include "core/slot_layout.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace revsph::analysis {

namespace {

// Eq. (30).
double f1(double x, double y) {
  return std::exp(-x - y);
}
double f2(double x, double /*y*/) {
  return 1.0 + std::cos(8.0 * x) + std::sin(8.0 * x);
}
double f3(double x, double y) {
  return 1.0 - x * y + 4.0 * x * x * y * y;
}

// sum_b W_ab, the sum including b = a: the inverse mass volume with m = 1 (eqs. 23, 32a) and the
// inverse entropic volume with S = 1 (eqs. 24, 36a).
struct KernelSumTerm {
  static constexpr int width = 1;
  const WendlandQuintic<2>& kernel;

  void pair(const PairGeometry<2>& p, std::array<double, 1>& to_a,
            std::array<double, 1>& to_b) const {
    to_a[0] = kernel.value(p.r);
    to_b[0] = to_a[0];
  }
  template <class Add>
  void self(std::uint32_t, Add& add) const {
    add(0, kernel.value(0.0));
  }
};

int nearest_even(double x) {
  return std::max(2, 2 * static_cast<int>(std::lround(0.5 * x)));
}

struct Particles {
  std::vector<Vec<2>> inside;  // in [0,1]^2: the quadrature's points
  std::vector<Vec<2>> dummies; // the band around it
};

// Core's hexagonal lattice with unit spacing (even rows at x = 1/2 + i, odd rows at x = 1 + i,
// row j at y = (j + 1/2) sqrt(3)/2), mapped column i of even rows to (i + 1/4 - band) / columns
// and row j to (j + 1/2 - band) / rows.
Particles lattice(int columns, int rows, int band) {
  const double row_period = 0.5 * std::numbers::sqrt3;
  const Box<2> region{{0.0, 0.0}, {columns + 2.0 * band + 1.0, (rows + 2.0 * band) * row_period}};
  Particles particles;
  for (const Vec<2>& p : lattice_points<2>(Lattice::hexagonal, region, 1.0)) {
    const long row = std::lround(p[1] / row_period - 0.5);
    const Vec<2> x{(p[0] - 0.25 - band) / columns, (static_cast<double>(row) + 0.5 - band) / rows};
    const bool inside = x[0] > 0.0 && x[0] < 1.0 && x[1] > 0.0 && x[1] < 1.0;
    (inside ? particles.inside : particles.dummies).push_back(x);
  }
  return particles;
}

} // namespace

const std::array<QuadratureFunction, 3>& quadrature_functions() {
  static const std::array<QuadratureFunction, 3> functions{{
      {"f1", f1, std::pow(1.0 - std::exp(-1.0), 2)},
      {"f2", f2, 1.0 + std::sin(8.0) / 8.0 + (1.0 - std::cos(8.0)) / 8.0},
      {"f3", f3, 43.0 / 36.0},
  }};
  return functions;
}

std::string_view name_of(QuadratureVolume volume) {
  return volume == QuadratureVolume::mass ? "mass" : "implicit";
}

double QuadratureResult::relative_error(QuadratureVolume volume, int function) const {
  const double exact = quadrature_functions()[function].exact;
  return std::abs(quadrature[static_cast<int>(volume)][function] - exact) / std::abs(exact);
}

int columns_for(double particles) {
  // N = columns rows with rows ~ 2 columns / sqrt(3).
  const int guess = static_cast<int>(std::lround(std::sqrt(particles * 0.5 * std::numbers::sqrt3)));
  int best = std::max(2, guess);
  for (int c = std::max(2, guess - 2); c <= guess + 2; ++c) {
    const double n = static_cast<double>(c) * nearest_even(2.0 * c / std::numbers::sqrt3);
    const double best_n =
        static_cast<double>(best) * nearest_even(2.0 * best / std::numbers::sqrt3);
    if (std::abs(std::log(n / particles)) < std::abs(std::log(best_n / particles))) {
      best = c;
    }
  }
  return best;
}

QuadratureResult entropic_quadrature(int columns, double band_width) {
  if (columns < 2) {
    throw std::invalid_argument("the quadrature lattice needs at least 2 columns");
  }
  QuadratureResult result;
  result.columns = columns;
  result.rows = nearest_even(2.0 * columns / std::numbers::sqrt3);
  const double n = static_cast<double>(columns) * result.rows;
  result.dr = 1.0 / std::sqrt(n);   // (31)
  const double h = 3.0 * result.dr; // the support radius (§3.4)
  const WendlandQuintic<2> kernel(h);
  // Dummy layers: at least band_width h + one lattice period beyond the square on every side, an
  // even number of them, so that the lowest row in the square is an even row of the lattice.
  const int layers = static_cast<int>(std::ceil(band_width * h * std::max(columns, result.rows)));
  const int band = 2 * (layers / 2 + 1);
  const Particles particles = lattice(columns, result.rows, band);
  result.particles = particles.inside.size();
  result.dummies = particles.dummies.size();
  if (result.particles != static_cast<std::size_t>(n)) {
    throw std::logic_error("the quadrature lattice has " + std::to_string(result.particles) +
                           " particles in [0,1]^2, not columns rows");
  }

  // Carriers: the particles in [0,1]^2, then the dummies.
  const double reach = (band + 1.0) / std::min(columns, result.rows);
  SlotLayout<2> layout(Box<2>{{-reach, -reach}, {1.0 + reach, 1.0 + reach}}, h,
                       {{"inside", particles.inside.size()}, {"dummy", particles.dummies.size()}});
  const auto position = [&](int axis, std::size_t carrier) {
    return carrier < particles.inside.size()
               ? particles.inside[carrier][axis]
               : particles.dummies[carrier - particles.inside.size()][axis];
  };
  layout.build(position, h);

  // Mass/entropic volume (23)-(24) with m = S = 1: V_a = 1 / sum_b W_ab. The sum's scale: the
  // number density N with 48 bits, as the entropic model's "number_density".
  PairSums<FixedArithmetic, 1> sums(
      SummedQuantity{"number_density", fixedpoint::Scale::covering(n, 48)});
  sum_pairs<FixedArithmetic>(layout, KernelSumTerm{kernel}, sums);
  std::vector<double> mass_volume(layout.carrier_count());
  const std::span<const std::uint32_t> carrier = layout.carrier_of_slot();
  for (std::size_t s = 0; s < layout.slot_count(); ++s) {
    mass_volume[carrier[s]] = 1.0 / sums.value(0, s);
  }

  // Implicit volume (26): sum_b W_ab V_b = 1 over all particles, dummies included. W is symmetric
  // positive definite (the Wendland quintic is positive definite in 2D), so conjugate gradients
  // from a zero start, as models/entropic/model.cpp solves it.
  PairSystem w;
  w.assemble<2>(layout, [&](double r) { return kernel.value(r); }, layout.carrier_count(),
                {1e-12, 20000});
  std::vector<double> implicit_volume(layout.carrier_count());
  const bool converged =
      w.solve_unknowns(std::vector<double>(layout.carrier_count(), 1.0), implicit_volume);
  result.solver_iterations = w.iterations();
  result.solver_residual = w.error();
  if (!converged) {
    throw std::runtime_error("the implicit volume's solve W V = 1 did not converge (" +
                             std::to_string(columns) + " columns)");
  }

  // (29): sum_a V_a f(x_a) over the particles in [0,1]^2 (carriers 0 .. N-1, in lattice order).
  for (std::size_t c = 0; c < particles.inside.size(); ++c) {
    result.volume_sum[0] += mass_volume[c];
    result.volume_sum[1] += implicit_volume[c];
  }
  const auto& functions = quadrature_functions();
  for (int f = 0; f < 3; ++f) {
    double mass_sum = 0.0;
    double implicit_sum = 0.0;
    for (std::size_t c = 0; c < particles.inside.size(); ++c) {
      const double value = functions[f].f(particles.inside[c][0], particles.inside[c][1]);
      mass_sum += mass_volume[c] * value;
      implicit_sum += implicit_volume[c] * value;
    }
    result.quadrature[0][f] = mass_sum;
    result.quadrature[1][f] = implicit_sum;
  }
  return result;
}

} // namespace revsph::analysis
