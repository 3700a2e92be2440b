// Paper 4's quadrature test (§3.4, Fig. 2, eqs. 29-31) on small lattices
// (tools/analysis/entropic_quadrature.hpp).

#include "tools/analysis/entropic_quadrature.hpp"

#include "core/kernel_wendland.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using revsph::analysis::entropic_quadrature;
using revsph::analysis::quadrature_functions;
using revsph::analysis::QuadratureResult;
using revsph::analysis::QuadratureVolume;

constexpr QuadratureVolume volumes[] = {QuadratureVolume::mass, QuadratureVolume::implicit};

// N = 90, 360, 1400, 5520.
const std::vector<QuadratureResult>& results() {
  static const std::vector<QuadratureResult> r = [] {
    std::vector<QuadratureResult> out;
    for (const int columns : {9, 18, 35, 69}) {
      out.push_back(entropic_quadrature(columns));
    }
    return out;
  }();
  return r;
}

// The quadrature normalised by sum_a V_a (the quadrature of 1): what is left of the error once
// the lattice's kernel-sum bias is divided out.
double normalised_error(const QuadratureResult& r, QuadratureVolume volume, int f) {
  const int v = static_cast<int>(volume);
  const double exact = quadrature_functions()[f].exact;
  return std::abs(r.quadrature[v][f] / r.volume_sum[v] - exact) / exact;
}

TEST(EntropicQuadrature, ExactIntegrals) {
  // derivations.md §6.1.
  EXPECT_NEAR(quadrature_functions()[0].exact, 0.399576400894, 1e-12);
  EXPECT_NEAR(quadrature_functions()[1].exact, 1.26685728505, 1e-11);
  EXPECT_NEAR(quadrature_functions()[2].exact, 1.19444444444, 1e-11);
}

// The mass volume is uniform in the square (the dummies fill every support), so sum_a V_a is
// N / sum_b W_ab of the infinite lattice, summed here directly.
TEST(EntropicQuadrature, MassVolumeSumIsTheLatticeKernelSum) {
  const QuadratureResult& r = results()[1];
  const double dx = 1.0 / r.columns;
  const double dy = 1.0 / r.rows;
  const revsph::WendlandQuintic<2> kernel(3.0 * r.dr);
  double sum = 0.0;
  for (int j = -20; j <= 20; ++j) {
    for (int i = -20; i <= 20; ++i) {
      const double x = (i + 0.5 * (j & 1)) * dx;
      sum += kernel.value(std::hypot(x, j * dy));
    }
  }
  EXPECT_NEAR(r.volume_sum[0], r.particles / sum, 1e-12);
  // The bias of the paper's h = 3 dr on this lattice (2.79 nearest-neighbour spacings): -0.54 %.
  EXPECT_NEAR(r.volume_sum[0] - 1.0, -5.36e-3, 0.05e-3);
}

// At fixed h / dr the relative error does not vanish: it tends to the bias |sum_a V_a - 1|.
// What converges is the rest: the normalised error falls with N for every volume and function,
// and the distance of the relative error from the bias falls too.
TEST(EntropicQuadrature, ErrorsConvergeToTheLatticeBias) {
  const auto& r = results();
  for (const QuadratureVolume volume : volumes) {
    for (int f = 0; f < 3; ++f) {
      for (std::size_t k = 1; k < r.size(); ++k) {
        SCOPED_TRACE(testing::Message() << name_of(volume) << " " << quadrature_functions()[f].name
                                        << " N = " << r[k].particles);
        EXPECT_LT(normalised_error(r[k], volume, f), normalised_error(r[k - 1], volume, f));
        const double bias = std::abs(r.back().volume_sum[0] - 1.0);
        EXPECT_LT(std::abs(r[k].relative_error(volume, f) - bias),
                  std::abs(r[k - 1].relative_error(volume, f) - bias));
      }
    }
  }
}

// The paper: "the implicit volume is more precise in most cases". Measured here: in all 12 (N, f)
// pairs (and 30 of 30 in docs/figures/entropic_quadrature.csv); a band of dummies wider than h
// shrinks the implicit volume's advantage (entropic_quadrature.hpp), so ask for most, not all.
TEST(EntropicQuadrature, ImplicitMoreAccurateInMostCases) {
  int wins = 0;
  int cases = 0;
  for (const QuadratureResult& r : results()) {
    for (int f = 0; f < 3; ++f) {
      ++cases;
      wins += r.relative_error(QuadratureVolume::implicit, f) <
              r.relative_error(QuadratureVolume::mass, f);
    }
  }
  RecordProperty("implicit_wins", wins);
  EXPECT_GT(2 * wins, cases) << wins << " of " << cases;
}

// At N = 1400 the mass-volume error is below 1e-2 (measured 5.2e-3 to 5.3e-3, the bias plus
// a few 1e-4 of discretisation).
TEST(EntropicQuadrature, MassVolumeErrorSmallAtModerateN) {
  const QuadratureResult& r = results()[2];
  for (int f = 0; f < 3; ++f) {
    EXPECT_LT(r.relative_error(QuadratureVolume::mass, f), 1e-2);
  }
}

} // namespace
