#include "models/wcsph/initial_state_correction.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/arithmetic.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/slot_layout.hpp"
#include "core/summation_density.hpp"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>

// Signs. Moving every particle by dx changes the density of eq. (4) to first order by
//   rho_a(x + dx) - rho_a(x) = sum_b m_b w'(r_ab) e_ab . (dx_a - dx_b),   e_ab = x_ab / r_ab,
// (d r_ab = e_ab . (dx_a - dx_b); the b = a term vanishes), which is eq. (6a) once the left side
// is set to rho0 - rho_a. Written as a matrix, J dx = rho0 - rho with the Jacobian
//   J[a, a] = sum_b m_b w'(r_ab) e_ab   (all b, fixed particles included),
//   J[a, c] = -m_c w'(r_ac) e_ac        (movable c != a; fixed particles have no column).
// The discrete gradient of eq. (6b), dx_c = sum_b m_b (phi_c / rho_c^2 + phi_b / rho_b^2)
// w'(r_cb) e_cb, is exactly dx = M^-1 J^T chi with chi_b = m_b phi_b / rho_b^2 and M the
// diagonal of the masses (expand (J^T chi)_c: the diagonal block J[c, c] gives the phi_c terms,
// the entries J[a, c] of the other rows the phi_b terms), provided phi = 0 on fixed particles:
// they keep only the phi_c / rho_c^2 term, like a Dirichlet condition on the potential at the
// wall. (The sign of phi relative to the paper's G is immaterial: phi is solved for.) So the
// Newton step is
//   (J M^-1 J^T) chi = rho0 - rho,   dx = M^-1 J^T chi,                               (6)
// the minimum-norm solution of J dx = rho0 - rho in the kinetic-energy metric dx^T M dx. A
// direct check that the signs are right: the residual falls quadratically (unit test).
//
// Choice of linear system. Eliminating dx from the N(d+1) block system [[I, G/rho],
// [-rho D, 0]] of the paper gives exactly the N x N Schur complement A = J M^-1 J^T above, so
// the two are the same problem; what differs is what a solver sees. The block matrix is
// indefinite, nonsymmetric and has a zero diagonal block: a direct solver needs a general LU
// with pivoting (Eigen's SparseLU), storing L and U without using symmetry, and its fill
// contains that of A anyway (eliminating the identity block creates A); Krylov methods on the
// saddle-point form (GMRES, BiCGSTAB) have no convergence guarantee and need a preconditioner,
// i.e. again an approximation of A. A is symmetric positive semi-definite always, and definite
// when J has full row rank, which holds for generic configurations (a particle without
// neighbours, the one sure way to lose it, is detected and reported): conjugate gradients then
// converge monotonically in the A-norm, need no pivoting or restarts, and are deterministic. A is never formed: it couples particles up to 2h apart (about
// 110 entries per row in 2D with h = 3 dr, 900 in 3D), while J has about 2 x 30 (3 x 115);
// each product is J (M^-1 (J^T p)), O(N) memory and time.
//
// Measured on the 200 x 400 patch (80 000 particles, dr = 0.005 m, h = 3 dr, 2-core VM shared
// with other jobs): a sparse LDL^T of the assembled A (Eigen SimplicialLDLT, AMD ordering; a
// geometric nested dissection was no better) took 40-90 s per Newton step with 5e7 entries in
// the factor (0.9 GB peak) and 8 min in all; diagonally preconditioned conjugate gradients to
// 1e-12 took 1100-3000 iterations (about as many as for 100 x 200) and 7-28 s per step. The
// iteration count grows slowly with N, so for N ~ 1e5 in 2D the iterative solver is both faster
// and much smaller; a direct factorisation in 3D would be worse still (fill ~ N^(4/3)).

namespace revsph::wcsph {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

template <int D>
std::size_t count_of(const CoordinateArrays<D>& points, std::span<const double> mass,
                     const char* set) {
  for (int k = 1; k < D; ++k) {
    if (points[k].size() != points[0].size()) {
      throw std::invalid_argument(std::string("initial state correction: the ") + set +
                                  " coordinate arrays differ in length");
    }
  }
  if (mass.size() != points[0].size()) {
    std::ostringstream message;
    message << "initial state correction: " << points[0].size() << " " << set << " particles but "
            << mass.size() << " masses";
    throw std::invalid_argument(message.str());
  }
  for (std::size_t i = 0; i < mass.size(); ++i) {
    if (!(mass[i] > 0.0) || !std::isfinite(mass[i])) {
      std::ostringstream message;
      message << "initial state correction: " << set << " particle " << i
              << " has a mass that is not positive and finite (" << mass[i] << ")";
      throw std::invalid_argument(message.str());
    }
  }
  return mass.size();
}

void validate(const IscSettings& settings, double support_radius, double rest_density) {
  const auto require = [](bool condition, const char* what) {
    if (!condition) {
      throw std::invalid_argument(std::string("initial state correction: ") + what);
    }
  };
  require(support_radius > 0.0 && std::isfinite(support_radius),
          "the support radius must be positive and finite");
  require(rest_density > 0.0 && std::isfinite(rest_density),
          "the rest density must be positive and finite");
  require(settings.max_iterations >= 0, "max_iterations must not be negative");
  require(settings.tolerance > 0.0 && std::isfinite(settings.tolerance),
          "the tolerance must be positive and finite");
  require(settings.jitter >= 0.0 && std::isfinite(settings.jitter),
          "the jitter must be non-negative and finite");
  require(settings.max_step >= 0.0 && std::isfinite(settings.max_step),
          "max_step must be non-negative and finite");
  require((settings.jitter == 0.0 && settings.max_step == 0.0) ||
              (settings.spacing > 0.0 && std::isfinite(settings.spacing)),
          "a jitter or a step limit needs a positive, finite particle spacing");
}

// `when` completes "... particle 17 <when> outside the domain", e.g. "is" or "would be moved
// by iteration 3 to".
template <int D>
void require_inside(const CoordinateArrays<D>& points, const Box<D>& domain, const char* set,
                    const std::string& when) {
  for (std::size_t i = 0; i < points[0].size(); ++i) {
    const Vec<D> point = point_of<D>(points, i);
    if (!domain.contains(point)) {
      std::ostringstream message;
      message.precision(17);
      message << "initial state correction: " << set << " particle " << i << " " << when << " (";
      for (int k = 0; k < D; ++k) {
        message << (k > 0 ? ", " : "") << point[k];
      }
      message << "), outside the domain [";
      for (int k = 0; k < D; ++k) {
        message << (k > 0 ? ", " : "") << domain.min[k];
      }
      message << "] - [";
      for (int k = 0; k < D; ++k) {
        message << (k > 0 ? ", " : "") << domain.max[k];
      }
      message << "]";
      throw std::runtime_error(message.str());
    }
  }
}

// A double uniform in [0, 1) from the top 53 bits, so that the jitter is the same with every
// standard library (std::uniform_real_distribution is implementation-defined).
double unit_uniform(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// Step 1 of the paper: |dx_a| < jitter * spacing. Direction uniform on the circle or sphere;
// length uniform in [0, jitter * spacing) (not uniform in area or volume: what is wanted is
// only a break of symmetry of about the given size).
template <int D>
void apply_jitter(CoordinateArrays<D>& points, const IscSettings& settings) {
  if (settings.jitter == 0.0) {
    return;
  }
  std::mt19937_64 engine(settings.seed);
  const double largest = settings.jitter * settings.spacing;
  for (std::size_t i = 0; i < points[0].size(); ++i) {
    Vec<D> direction{};
    if constexpr (D == 1) {
      direction = {unit_uniform(engine) < 0.5 ? -1.0 : 1.0};
    } else if constexpr (D == 2) {
      const double angle = 2.0 * std::numbers::pi * unit_uniform(engine);
      direction = {dmath::cos(angle), dmath::sin(angle)};
    } else {
      const double cos_polar = 2.0 * unit_uniform(engine) - 1.0; // uniform on the sphere
      const double sin_polar = std::sqrt(std::max(0.0, 1.0 - cos_polar * cos_polar));
      const double azimuth = 2.0 * std::numbers::pi * unit_uniform(engine);
      direction = {sin_polar * dmath::cos(azimuth), sin_polar * dmath::sin(azimuth), cos_polar};
    }
    const double length = largest * unit_uniform(engine);
    for (int k = 0; k < D; ++k) {
      points[k][i] += length * direction[k];
    }
  }
}

// The movable particles (set 0, carriers 0 .. n-1) and the fixed ones (set 1) in one slot layout
// of the core's pair loop, rebuilt at every Newton iteration, with their masses by slot.
template <int D>
struct IscLayout {
  SlotLayout<D> layout;
  std::vector<double> slot_mass;

  IscLayout(const Box<D>& domain, double support_radius, std::size_t movable, std::size_t fixed)
      : layout(domain, support_radius, {{"movable", movable}, {"fixed", fixed}}) {}

  void build(const CoordinateArrays<D>& movable, std::span<const double> movable_mass,
             const CoordinateArrays<D>& fixed, std::span<const double> fixed_mass,
             double support_radius) {
    const std::size_t n = movable_mass.size();
    layout.build(
        [&](int axis, std::size_t c) { return c < n ? movable[axis][c] : fixed[axis][c - n]; },
        support_radius,
        Gathered{[&](std::size_t c) { return c < n ? movable_mass[c] : fixed_mass[c - n]; },
                 &slot_mass});
  }
  std::span<const std::uint32_t> movable_slots() const { return layout.slots_of_set(0); }
};

// Eq. (4), the sum including b = a (core/summation_density.hpp), in exact integer sums at the
// rest density's scale with 48 bits below it: the same bits for any thread count and cell size.
template <int D>
void compute_density(const WendlandQuintic<D>& kernel, const IscLayout<D>& isc, double rest_density,
                     std::vector<double>& density) {
  PairSums<FixedArithmetic, 1> sums(
      SummedQuantity{"density", fixedpoint::Scale::covering(rest_density, 48)});
  sum_pairs<FixedArithmetic>(
      isc.layout, SummationDensityTerm<D, FixedArithmetic>{kernel, isc.slot_mass, {}}, sums);
  const std::span<const std::uint32_t> slots = isc.movable_slots();
  density.resize(slots.size());
  for (std::size_t a = 0; a < slots.size(); ++a) {
    density[a] = sums.value(0, slots[a]);
  }
}

// The diagonal block of the Jacobian, J[a, a] = sum_b m_b w'(r_ab) e_ab (all b, fixed particles
// included), as a pair term: w'(r) e_ab = (w'(r) / r) x_ab, no division by r.
template <int D>
struct DensityGradientTerm {
  static constexpr int width = D;
  const WendlandQuintic<D>& kernel;
  std::span<const double> mass; // by slot

  void pair(const PairGeometry<D>& p, std::array<double, D>& to_a,
            std::array<double, D>& to_b) const {
    const double factor = kernel.derivative_over_r(p.r);
    for (int k = 0; k < D; ++k) {
      const double g = factor * p.x_ab[k];
      to_a[k] = mass[p.b] * g;
      to_b[k] = -mass[p.a] * g;
    }
  }
};

double max_relative_error(const std::vector<double>& density, double rest_density) {
  double largest = 0.0;
  for (const double rho : density) {
    const double error = std::abs(rho - rest_density) / rest_density;
    // Written so that a NaN density makes the residual NaN (never "converged").
    if (!(error <= largest)) {
      largest = error;
    }
  }
  return largest;
}

// The Jacobian J (rows: movable particles; columns: D per movable particle, axis fastest), in
// compressed rows, and M^-1 per column.
struct Jacobian {
  RowMatrix matrix;
  Eigen::VectorXd inverse_mass;
};

// J in compressed rows, each row's columns ascending. The diagonal blocks are exact sums (scale:
// rho0 / h with 40 bits below, 2^23 times that above); the off-diagonal entries come from the
// layout's pairs of two movable particles, each pair once, so the matrix is a function of the
// positions alone.
template <int D>
Jacobian assemble_jacobian(const WendlandQuintic<D>& kernel, const IscLayout<D>& isc,
                           std::span<const double> movable_mass, double rest_density) {
  const std::size_t n = movable_mass.size();
  const std::size_t pairs = isc.layout.pairs().pair_count();
  if (D * n > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      D * (n + 2 * pairs) > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::length_error("initial state correction: too many particles for one linear system");
  }
  PairSums<FixedArithmetic, D> diagonal(components_of<D>(
      "density gradient", fixedpoint::Scale::covering(rest_density / kernel.support_radius(), 40)));
  sum_pairs<FixedArithmetic>(isc.layout, DensityGradientTerm<D>{kernel, isc.slot_mass}, diagonal);

  Jacobian jacobian{RowMatrix(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(D * n)),
                    Eigen::VectorXd(static_cast<Eigen::Index>(D * n))};
  for (std::size_t c = 0; c < n; ++c) {
    for (int k = 0; k < D; ++k) {
      jacobian.inverse_mass[static_cast<Eigen::Index>(D * c + k)] = 1.0 / movable_mass[c];
    }
  }
  const std::span<const std::uint32_t> carrier = isc.layout.carrier_of_slot();
  const auto movable_pair = [&](const PairGeometry<D>& pair) {
    return carrier[pair.a] < n && carrier[pair.b] < n;
  };
  // Row lengths: the diagonal block and one block per movable neighbour.
  std::vector<int> row_start(n + 1, 0);
  for_each_pair<D>(isc.layout, [&](const PairGeometry<D>& pair) {
    if (movable_pair(pair)) {
      row_start[carrier[pair.a] + 1] += D;
      row_start[carrier[pair.b] + 1] += D;
    }
  });
  for (std::size_t a = 0; a < n; ++a) {
    row_start[a + 1] += row_start[a] + D;
  }
  RowMatrix& matrix = jacobian.matrix;
  matrix.resizeNonZeros(row_start[n]);
  std::copy(row_start.begin(), row_start.end(), matrix.outerIndexPtr());
  int* const columns = matrix.innerIndexPtr();
  double* const values = matrix.valuePtr();
  const std::span<const std::uint32_t> slots = isc.movable_slots();
  std::vector<int> next(n);
  for (std::size_t a = 0; a < n; ++a) {
    for (int k = 0; k < D; ++k) {
      columns[row_start[a] + k] = static_cast<int>(D * a + k);
      values[row_start[a] + k] = diagonal.value(k, slots[a]);
    }
    next[a] = row_start[a] + D;
  }
  // J[a, c] = -m_c w'(r_ac) e_ac and J[c, a] = -m_a w'(r_ca) e_ca = m_a w'(r_ac) e_ac.
  for_each_pair<D>(isc.layout, [&](const PairGeometry<D>& pair) {
    if (!movable_pair(pair)) {
      return;
    }
    const std::size_t a = carrier[pair.a];
    const std::size_t c = carrier[pair.b];
    const double factor = kernel.derivative_over_r(pair.r);
    for (int k = 0; k < D; ++k) {
      const double g = factor * pair.x_ab[k];
      columns[next[a] + k] = static_cast<int>(D * c + k);
      values[next[a] + k] = -movable_mass[c] * g;
      columns[next[c] + k] = static_cast<int>(D * a + k);
      values[next[c] + k] = movable_mass[a] * g;
    }
    next[a] += D;
    next[c] += D;
  });
  // Each row's blocks in ascending column order (the pairs came in slot order).
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const int blocks = (row_start[a + 1] - row_start[a]) / D;
    std::vector<int> order(static_cast<std::size_t>(blocks));
    std::iota(order.begin(), order.end(), 0);
    const int first = row_start[a];
    std::sort(order.begin(), order.end(),
              [&](int x, int y) { return columns[first + D * x] < columns[first + D * y]; });
    std::vector<int> sorted_columns(static_cast<std::size_t>(D * blocks));
    std::vector<double> sorted_values(sorted_columns.size());
    for (int i = 0; i < blocks; ++i) {
      for (int k = 0; k < D; ++k) {
        sorted_columns[D * i + k] = columns[first + D * order[i] + k];
        sorted_values[D * i + k] = values[first + D * order[i] + k];
      }
    }
    std::copy(sorted_columns.begin(), sorted_columns.end(), columns + first);
    std::copy(sorted_values.begin(), sorted_values.end(), values + first);
  }
  return jacobian;
}

// Eq. (6) in the symmetric form derived at the top of this file: (J M^-1 J^T) chi = deficit by
// conjugate gradients, preconditioned with the diagonal, until |residual|_2 <= forcing
// |deficit|_2 or `max_iterations`. Matrix-free: each product is J (M^-1 (J^T p)).
// Returns the iterations taken; `potential` is the last iterate (the best one in the A-norm).
int solve_normal_equations(const Jacobian& jacobian, const Eigen::VectorXd& deficit, double forcing,
                           int max_iterations, Eigen::VectorXd& potential) {
  const RowMatrix& j = jacobian.matrix;
  const auto apply = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return j * jacobian.inverse_mass.cwiseProduct(j.transpose() * v);
  };
  // diag(J M^-1 J^T), positive: the caller has excluded rows of J that are zero.
  const Eigen::VectorXd inverse_diagonal = (j.cwiseAbs2() * jacobian.inverse_mass).cwiseInverse();
  potential = Eigen::VectorXd::Zero(deficit.size());
  Eigen::VectorXd residual = deficit;
  Eigen::VectorXd preconditioned = inverse_diagonal.cwiseProduct(residual);
  Eigen::VectorXd direction = preconditioned;
  double residual_dot = residual.dot(preconditioned);
  const double target = forcing * deficit.norm();
  int iteration = 0;
  for (; iteration < max_iterations && residual.norm() > target; ++iteration) {
    const Eigen::VectorXd image = apply(direction);
    const double curvature = direction.dot(image);
    // Zero (or, by round-off, negative) curvature: a direction in the null space of the
    // semi-definite matrix, along which nothing more can be gained.
    if (!(curvature > 0.0)) {
      break;
    }
    const double step = residual_dot / curvature;
    potential += step * direction;
    residual -= step * image;
    preconditioned = inverse_diagonal.cwiseProduct(residual);
    const double next_dot = residual.dot(preconditioned);
    direction = preconditioned + (next_dot / residual_dot) * direction;
    residual_dot = next_dot;
  }
  return iteration;
}

// A particle whose row of J vanishes (no neighbour at 0 < r < h) makes eq. (6) singular: its
// density is fixed whatever the displacement.
std::optional<std::size_t> first_zero_row(const RowMatrix& jacobian) {
  for (Eigen::Index a = 0; a < jacobian.outerSize(); ++a) {
    bool zero = true;
    for (RowMatrix::InnerIterator entry(jacobian, a); entry; ++entry) {
      zero = zero && entry.value() == 0.0;
    }
    if (zero) {
      return static_cast<std::size_t>(a);
    }
  }
  return std::nullopt;
}

// Inexact Newton (Eisenstat-Walker): a linear solve to relative accuracy eta leaves a residual of
// about eta r next to the quadratic term C r^2, so eta proportional to r keeps the convergence
// quadratic while the first, far-from-converged steps take few conjugate-gradient iterations.
// 0.01 r: the same Newton iterations as an exact solve on the test patches at a third of the
// conjugate-gradient iterations (eta = r^2 took one Newton step more). The floor is near what
// conjugate gradients reach in double precision.
double forcing_term(double residual) {
  return std::clamp(0.01 * residual, 1e-12, 1e-3);
}

// About 7 times the most that the 30 x 30 to 200 x 400 patches of the tests and benchmarks
// needed (about 3000); the iterate is used even if this is reached, only slowing Newton down.
constexpr int kMaxLinearIterations = 20000;

} // namespace

template <int D>
IscReport correct_initial_state(CoordinateArrays<D>& movable, std::span<const double> movable_mass,
                                const CoordinateArrays<D>& fixed,
                                std::span<const double> fixed_mass, double support_radius,
                                double rest_density, const Box<D>& domain,
                                const IscSettings& settings) {
  validate(settings, support_radius, rest_density);
  const std::size_t n = count_of<D>(movable, movable_mass, "movable");
  count_of<D>(fixed, fixed_mass, "fixed");
  require_inside<D>(movable, domain, "movable", "is at");
  require_inside<D>(fixed, domain, "fixed", "is at");

  // Work on a copy so that an exception leaves the caller's positions as they were.
  CoordinateArrays<D> position = movable;
  apply_jitter<D>(position, settings);
  require_inside<D>(position, domain, "movable", "would be moved by the initial jitter to");

  const WendlandQuintic<D> kernel(support_radius);
  IscLayout<D> isc(domain, support_radius, n, fixed_mass.size());
  std::vector<double> density;
  IscReport report;
  for (;;) {
    // Step 4 of the paper.
    isc.build(position, movable_mass, fixed, fixed_mass, support_radius);
    compute_density<D>(kernel, isc, rest_density, density);
    report.residuals.push_back(max_relative_error(density, rest_density));
    if (report.residuals.back() <= settings.tolerance) {
      report.converged = true;
      break;
    }
    if (report.iterations == settings.max_iterations) {
      break;
    }
    if (!std::isfinite(report.residuals.back())) {
      report.stopped_early = "the density is not finite";
      break;
    }
    const Jacobian jacobian = assemble_jacobian<D>(kernel, isc, movable_mass, rest_density);
    if (const std::optional<std::size_t> stuck = first_zero_row(jacobian.matrix)) {
      report.stopped_early = "movable particle " + std::to_string(*stuck) +
                             " has no neighbour closer than the support radius, so no "
                             "displacement can change its density";
      break;
    }
    Eigen::VectorXd deficit(static_cast<Eigen::Index>(n));
    for (std::size_t a = 0; a < n; ++a) {
      deficit[static_cast<Eigen::Index>(a)] = rest_density - density[a];
    }
    Eigen::VectorXd potential;
    report.linear_iterations.push_back(solve_normal_equations(
        jacobian, deficit, forcing_term(report.residuals.back()), kMaxLinearIterations, potential));
    // Eq. (6b): dx = M^-1 J^T chi.
    Eigen::VectorXd displacement =
        jacobian.inverse_mass.cwiseProduct(jacobian.matrix.transpose() * potential);
    if (!displacement.allFinite()) {
      report.stopped_early = "the Newton step of eq. (6) is not finite";
      break;
    }
    if (settings.max_step > 0.0) {
      double longest_squared = 0.0;
      for (std::size_t a = 0; a < n; ++a) {
        double length_squared = 0.0;
        for (int k = 0; k < D; ++k) {
          const double d = displacement[static_cast<Eigen::Index>(D * a + k)];
          length_squared += d * d;
        }
        longest_squared = std::max(longest_squared, length_squared);
      }
      const double limit = settings.max_step * settings.spacing;
      if (longest_squared > limit * limit) {
        displacement *= limit / std::sqrt(longest_squared);
      }
    }
    for (int k = 0; k < D; ++k) {
      for (std::size_t a = 0; a < n; ++a) {
        position[k][a] += displacement[static_cast<Eigen::Index>(D * a + k)];
      }
    }
    ++report.iterations;
    require_inside<D>(position, domain, "movable",
                      "would be moved by iteration " + std::to_string(report.iterations) + " to");
  }
  movable = std::move(position);
  return report;
}

template IscReport correct_initial_state<1>(CoordinateArrays<1>&, std::span<const double>,
                                            const CoordinateArrays<1>&, std::span<const double>,
                                            double, double, const Box<1>&, const IscSettings&);
template IscReport correct_initial_state<2>(CoordinateArrays<2>&, std::span<const double>,
                                            const CoordinateArrays<2>&, std::span<const double>,
                                            double, double, const Box<2>&, const IscSettings&);
template IscReport correct_initial_state<3>(CoordinateArrays<3>&, std::span<const double>,
                                            const CoordinateArrays<3>&, std::span<const double>,
                                            double, double, const Box<3>&, const IscSettings&);

} // namespace revsph::wcsph
