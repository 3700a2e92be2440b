#include "models/shtc/distortion.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "fixedpoint/conversion.hpp"

#include <cmath>
#include <numbers>

namespace revsph::shtc {

namespace {

// Odd functions bit for bit: f(-t) == -f(t) whatever the implementation does with negative
// arguments.
double odd_tan(double t) {
  return std::copysign(dmath::tan(std::fabs(t)), t);
}
double odd_tanh(double t) {
  return std::copysign(dmath::tanh(std::fabs(t)), t);
}

// Lifting steps on the columns of U (right multiplication by a unit triangular matrix).
template <int D>
class ColumnLifts {
public:
  explicit ColumnLifts(std::array<std::int64_t, D * D>& u) : u_(u) {}

  // column j += round(c * column i): U <- U (I + c e_i e_j^T). The same step with -c undoes it
  // exactly, because column i is untouched and the rounding is odd-symmetric.
  bool shear(int i, int j, double c) {
    for (int row = 0; row < D; ++row) {
      const double product = c * static_cast<double>(u_[row * D + i]);
      if (!(std::fabs(product) < fixedpoint::two_to_the_63)) {
        return false;
      }
      if (__builtin_add_overflow(u_[row * D + j], std::llrint(product), &u_[row * D + j])) {
        return false;
      }
    }
    return true;
  }

  // U <- U R with R the rotation by theta in the (i, j) plane, R = [[cos, -sin], [sin, cos]] on
  // columns (i, j), as three shears [[1, a], [0, 1]] [[1, 0], [b, 1]] [[1, a], [0, 1]],
  // a = -tan(theta / 2), b = sin(theta) = 2 tan(theta / 2) / (1 + tan^2(theta / 2)): one
  // transcendental call, and b odd in a as the reversal needs.
  bool rotate(int i, int j, double theta) {
    const double half = odd_tan(0.5 * theta);
    return rotate_by(i, j, -half, 2.0 * half / (1.0 + half * half));
  }
  bool rotate_by(int i, int j, double a, double b) {
    return shear(i, j, a) && shear(j, i, b) && shear(i, j, a);
  }

  // U <- U B with B = [[cosh t, sinh t], [sinh t, cosh t]] on columns (i, j): the same three
  // shears with a = tanh(t / 2), b = sinh(t) = 2 tanh(t / 2) / (1 - tanh^2(t / 2)).
  bool boost(int i, int j, double t) {
    const double half = odd_tanh(0.5 * t);
    return rotate_by(i, j, half, 2.0 * half / (1.0 - half * half));
  }

  // U <- U diag(e^t, e^-t) on columns (i, j) = U R(-pi/4) B(t) R(pi/4). The two fixed rotations
  // use the same constants with opposite signs, so stretch(-t) is exactly the inverse sequence.
  bool stretch(int i, int j, double t) {
    static const double a = dmath::tan(std::numbers::pi / 8.0);
    static const double b = dmath::sin(std::numbers::pi / 4.0);
    return rotate_by(i, j, a, -b) && boost(i, j, t) && rotate_by(i, j, -a, b);
  }

private:
  std::array<std::int64_t, D * D>& u_;
};

enum class Generator { rotation, boost, stretch };

struct Factor {
  Generator kind;
  int i;
  int j;
  double parameter; // odd in h L
};

// Rotations and boosts, one per plane, and D - 1 stretches: 3 factors in 2D, 8 in 3D.
template <int D>
constexpr std::size_t factor_count = D*(D - 1) + (D - 1);

// tr(h L), summed in a fixed order so that -h L gives exactly the negative.
template <int D>
double trace_of(const Matrix<D>& h_l) {
  double trace = 0.0;
  for (int k = 0; k < D; ++k) {
    trace += h_l(k, k);
  }
  return trace;
}

// exp(M) for M = -dev(h L), split into plane generators: the antisymmetric part into rotations
// (exp of [[0, w], [-w, 0]] is the rotation by -w), the symmetric off-diagonal part into boosts,
// the traceless diagonal into stretches of the pairs (0, 1) and, in 3D, (1, 2).
template <int D>
std::array<Factor, factor_count<D>> factors_of(const Matrix<D>& h_l, double trace) {
  const double trace_part = trace / D;
  Matrix<D> m;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      m(r, c) = -(h_l(r, c) - (r == c ? trace_part : 0.0));
    }
  }
  // No allocation: this runs for every particle in every step.
  std::array<Factor, factor_count<D>> factors{};
  std::size_t next = 0;
  for (int i = 0; i < D; ++i) {
    for (int j = i + 1; j < D; ++j) {
      factors[next++] = {Generator::rotation, i, j, -(0.5 * (m(i, j) - m(j, i)))};
    }
  }
  for (int i = 0; i < D; ++i) {
    for (int j = i + 1; j < D; ++j) {
      factors[next++] = {Generator::boost, i, j, 0.5 * (m(i, j) + m(j, i))};
    }
  }
  factors[next++] = {Generator::stretch, 0, 1, m(0, 0)};
  if constexpr (D == 3) {
    factors[next++] = {Generator::stretch, 1, 2, -m(2, 2)};
  }
  return factors;
}

template <int D>
bool apply(ColumnLifts<D>& lifts, const Factor& factor, double fraction) {
  const double parameter = fraction * factor.parameter;
  switch (factor.kind) {
  case Generator::rotation:
    return lifts.rotate(factor.i, factor.j, parameter);
  case Generator::boost:
    return lifts.boost(factor.i, factor.j, parameter);
  case Generator::stretch:
    return lifts.stretch(factor.i, factor.j, parameter);
  }
  return false;
}

} // namespace

template <int D>
bool try_make_distortion(const Matrix<D>& a, const DistortionScales& scales,
                         ExactDistortion<D>& out) {
  const double determinant = a.determinant();
  if (!(determinant > 0.0) || !std::isfinite(determinant)) {
    return false;
  }
  const double log_det = dmath::log(determinant);
  const double unimodular_factor = dmath::exp(-log_det / D);
  if (!fixedpoint::try_to_fixed(log_det, scales.log_det, out.log_det)) {
    return false;
  }
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      if (!fixedpoint::try_to_fixed(a(r, c) * unimodular_factor, scales.unimodular,
                                    out.unimodular[r * D + c])) {
        return false;
      }
    }
  }
  return true;
}

template <int D>
Matrix<D> to_matrix(const ExactDistortion<D>& a, const DistortionScales& scales) {
  const double factor = dmath::exp(fixedpoint::to_real(a.log_det, scales.log_det) / D);
  Matrix<D> result;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) {
      result(r, c) = factor * fixedpoint::to_real(a.unimodular[r * D + c], scales.unimodular);
    }
  }
  return result;
}

template <int D>
bool try_update_distortion(ExactDistortion<D>& a, const Matrix<D>& h_l,
                           const DistortionScales& scales) {
  const double trace = trace_of<D>(h_l);
  // d(log det A)/dt = -tr L (eq. 47): exact and additive, hence exactly invertible.
  std::int64_t log_det_change = 0;
  if (!fixedpoint::try_to_fixed(-trace, scales.log_det, log_det_change) ||
      !fixedpoint::try_add(a.log_det, log_det_change, a.log_det)) {
    return false;
  }
  // Strang: half of every factor but the last, the last whole, the halves again in reverse.
  const auto factors = factors_of<D>(h_l, trace);
  ColumnLifts<D> lifts(a.unimodular);
  const std::size_t last = factors.size() - 1;
  for (std::size_t k = 0; k < last; ++k) {
    if (!apply(lifts, factors[k], 0.5)) {
      return false;
    }
  }
  if (!apply(lifts, factors[last], 1.0)) {
    return false;
  }
  for (std::size_t k = last; k-- > 0;) {
    if (!apply(lifts, factors[k], 0.5)) {
      return false;
    }
  }
  return true;
}

template <int D>
Matrix<D> cayley_update(const Matrix<D>& a, const Matrix<D>& h_l) {
  const Matrix<D> identity = Matrix<D>::Identity();
  return a * (identity - 0.5 * h_l) * (identity + 0.5 * h_l).inverse();
}

template bool try_make_distortion<2>(const Matrix<2>&, const DistortionScales&,
                                     ExactDistortion<2>&);
template bool try_make_distortion<3>(const Matrix<3>&, const DistortionScales&,
                                     ExactDistortion<3>&);
template Matrix<2> to_matrix<2>(const ExactDistortion<2>&, const DistortionScales&);
template Matrix<3> to_matrix<3>(const ExactDistortion<3>&, const DistortionScales&);
template bool try_update_distortion<2>(ExactDistortion<2>&, const Matrix<2>&,
                                       const DistortionScales&);
template bool try_update_distortion<3>(ExactDistortion<3>&, const Matrix<3>&,
                                       const DistortionScales&);
template Matrix<2> cayley_update<2>(const Matrix<2>&, const Matrix<2>&);
template Matrix<3> cayley_update<3>(const Matrix<3>&, const Matrix<3>&);

} // namespace revsph::shtc
