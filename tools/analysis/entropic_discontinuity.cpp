#include "entropic_discontinuity.hpp"

#include "core/arithmetic.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/pair_system.hpp"
#include "core/slot_layout.hpp"
#include "models/entropic/pair_terms.hpp"

#include <cmath>
#include <stdexcept>

namespace revsph::analysis {

std::string_view name_of(DiscontinuityVolume volume) {
  static constexpr std::string_view names[] = {"mass", "entropic", "direct", "implicit", "mixed"};
  return names[static_cast<int>(volume)];
}

std::string_view name_of(RightEntropy right) {
  static constexpr std::string_view names[] = {"spacing", "left_value", "zero", "mass_volume"};
  return names[static_cast<int>(right)];
}

DiscontinuityProfiles entropic_discontinuity(RightEntropy right, double left_spacing,
                                             double support_radius) {
  // Particles at the centres of their spacing cells, continued 2 h beyond both ends (dummies).
  const double right_spacing = 0.5 * left_spacing;
  const double mass = left_spacing; // rho = 1 on the left
  std::vector<double> x, entropy;
  const double reach = 2.0 * support_radius;
  const auto left_count = static_cast<long>(std::lround((0.5 + reach) / left_spacing));
  for (long i = 0; i < left_count; ++i) {
    x.push_back(-reach + (static_cast<double>(i) + 0.5) * left_spacing);
    entropy.push_back(left_spacing);
  }
  const auto right_count = static_cast<long>(std::lround((0.5 + reach) / right_spacing));
  for (long i = 0; i < right_count; ++i) {
    x.push_back(0.5 + (static_cast<double>(i) + 0.5) * right_spacing);
    entropy.push_back(right == RightEntropy::spacing      ? right_spacing
                      : right == RightEntropy::left_value ? left_spacing
                                                          : 0.0);
  }
  const std::size_t n = x.size();
  const WendlandQuintic<1> kernel(support_radius);
  const Box<1> domain{{-1.0}, {2.0}};
  SlotLayout<1> layout(domain, support_radius, {{"particles", n}});
  layout.build([&](int, std::size_t c) { return x[c]; }, support_radius);
  std::vector<double> masses(n, mass);
  std::vector<double> slot_mass, slot_entropy;
  layout.gather(std::span<const double>(masses), slot_mass);
  layout.gather(std::span<const double>(entropy), slot_entropy);
  // Exact sums at 2^-52 of 1/spacing: far below any difference the figures show.
  const fixedpoint::Scale scale = fixedpoint::Scale::covering(2.0 / right_spacing, 52);
  PairSums<FixedArithmetic, 3> sums(std::array<SummedQuantity, 3>{
      SummedQuantity{"density", scale}, SummedQuantity{"entropy_density", scale},
      SummedQuantity{"number_density", scale}});
  // sum m W, sum S W, sum W (eqs. 28, 32a, 36a, 39): the model's own kernel-sum term.
  sum_pairs<FixedArithmetic>(layout, entropic::KernelSumsTerm<1>{kernel, slot_mass, slot_entropy},
                             sums);
  std::array<std::vector<double>, 3> by_carrier;
  for (int q = 0; q < 3; ++q) {
    layout.scatter(sums.values(q), by_carrier[q]);
  }
  if (right == RightEntropy::mass_volume) {
    // S_a = the mass volume m / sum m W (s = 1 through it), then the sums again with these S.
    for (std::size_t c = 0; c < n; ++c) {
      entropy[c] = mass / by_carrier[0][c];
    }
    layout.gather(std::span<const double>(entropy), slot_entropy);
    sum_pairs<FixedArithmetic>(layout, entropic::KernelSumsTerm<1>{kernel, slot_mass, slot_entropy},
                               sums);
    for (int q = 0; q < 3; ++q) {
      layout.scatter(sums.values(q), by_carrier[q]);
    }
  }
  // The implicit volume: W V = 1 over all particles.
  PairSystem w;
  w.assemble<1>(layout, [&](double r) { return kernel.value(r); }, n, {1e-12, 20000});
  std::vector<double> implicit(n);
  if (!w.solve_unknowns(std::vector<double>(n, 1.0), implicit)) {
    throw std::runtime_error("discontinuity test: W V = 1 did not converge");
  }

  DiscontinuityProfiles profiles;
  for (std::size_t c = 0; c < n; ++c) {
    if (x[c] <= 0.0 || x[c] >= 1.0) {
      continue; // a dummy particle
    }
    profiles.x.push_back(x[c]);
    const double mass_sum = by_carrier[0][c];
    const double entropy_sum = by_carrier[1][c];
    const double number_sum = by_carrier[2][c];
    const double s_c = entropy[c];
    // (rho, s) per volume: mass (32), entropic (36), direct (40), implicit (43), mixed (28).
    const std::array<std::array<double, 2>, 5> values = {{
        {mass_sum, s_c * mass_sum / mass},
        {mass * entropy_sum / s_c, entropy_sum},
        {mass * number_sum, s_c * number_sum},
        {mass / implicit[c], s_c / implicit[c]},
        {mass_sum, entropy_sum},
    }};
    for (std::size_t v = 0; v < values.size(); ++v) {
      profiles.density[v].push_back(values[v][0]);
      profiles.entropy_density[v].push_back(values[v][1]);
    }
  }
  return profiles;
}

} // namespace revsph::analysis
