#include "models/two_fluid/hydrostatic_start.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/arithmetic.hpp"
#include "core/kernel_wendland.hpp"
#include "core/pair_sum.hpp"
#include "core/slot_layout.hpp"
#include "models/two_fluid/pair_terms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace revsph::two_fluid {

template <int D>
void hydrostatic_masses(const Parameters<D>& p, std::array<std::span<const Vec<D>>, 3> position,
                        std::array<std::span<double>, 3> mass) {
  // Per column (x in whole spacings from a fluid particle's: lattice columns are whole numbers
  // apart, while x / dr itself may sit on a half): the heights and rho_k g dr of its particles.
  const Vec<D> origin = position[0].empty() ? position[1][0] : position[0][0];
  std::map<long long, std::vector<std::pair<double, double>>> columns;
  const auto column_of = [&](const Vec<D>& x) {
    long long key = 0;
    for (int k = 0; k < D - 1; ++k) {
      key = key * 1000003 + std::llround((x[k] - origin[k]) / p.dr);
    }
    return key;
  };
  for (std::size_t f = 0; f < 2; ++f) {
    for (const Vec<D>& x : position[f]) {
      columns[column_of(x)].push_back({x[D - 1], p.rest_density(f == 0) * p.gravity * p.dr});
    }
  }
  const auto pressure_at = [&](long long column, double y) {
    double pressure = p.background_pressure;
    for (const auto& [height, weight] : columns.at(column)) {
      pressure += height > y ? weight : height == y ? 0.5 * weight : 0.0;
    }
    return pressure;
  };
  // A wall particle's column: its x in whole spacings, clamped to the fluid's columns (a side
  // wall takes the outermost one); the nearest fluid column by search only where that column is
  // empty (a fluid region that is not a box).
  std::array<long long, D> lowest{}, highest{};
  lowest.fill(std::numeric_limits<long long>::max());
  highest.fill(std::numeric_limits<long long>::min());
  for (std::size_t f = 0; f < 2; ++f) {
    for (const Vec<D>& x : position[f]) {
      for (int k = 0; k < D - 1; ++k) {
        const long long index = std::llround((x[k] - origin[k]) / p.dr);
        lowest[k] = std::min(lowest[k], index);
        highest[k] = std::max(highest[k], index);
      }
    }
  }
  const auto wall_column = [&](const Vec<D>& x) {
    long long key = 0;
    for (int k = 0; k < D - 1; ++k) {
      key = key * 1000003 +
            std::clamp(std::llround((x[k] - origin[k]) / p.dr), lowest[k], highest[k]);
    }
    if (columns.contains(key)) {
      return key;
    }
    long long nearest = columns.begin()->first;
    double distance = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < 2; ++f) {
      for (const Vec<D>& y : position[f]) {
        double d = 0.0;
        for (int k = 0; k < D - 1; ++k) {
          d += (x[k] - y[k]) * (x[k] - y[k]);
        }
        if (d < distance) {
          distance = d;
          nearest = column_of(y);
        }
      }
    }
    return nearest;
  };
  // Every particle's number density, superfluid, normal then wall.
  std::vector<const Vec<D>*> all;
  for (const std::span<const Vec<D>> kind : position) {
    for (const Vec<D>& x : kind) {
      all.push_back(&x);
    }
  }
  SlotLayout<D> layout(p.domain, p.support_radius, {{"particles", all.size()}});
  layout.build([&](int axis, std::size_t c) { return (*all[c])[axis]; }, p.support_radius);
  const WendlandQuintic<D> kernel(p.support_radius);
  PairSums<FixedArithmetic, 1> sums(SummedQuantity{"number_density", p.density_scale});
  sum_pairs<FixedArithmetic>(layout, NumberDensityTerm<D>{kernel}, sums);
  std::vector<double> number_density;
  layout.scatter(sums.values(0), number_density);
  // The interior's number density, the fluid's median (every fluid particle of a closed box has
  // its kernel full).
  const std::size_t fluid_count = position[0].size() + position[1].size();
  std::vector<double> fluid_n(number_density.begin(),
                              number_density.begin() + static_cast<std::ptrdiff_t>(fluid_count));
  std::nth_element(fluid_n.begin(), fluid_n.begin() + fluid_n.size() / 2, fluid_n.end());
  const double interior_n = fluid_n[fluid_n.size() / 2];
  std::size_t c = 0;
  for (std::size_t f = 0; f < 3; ++f) {
    const double rest = p.rest_density(f == 0);
    const double b = rest * p.sound_speed * p.sound_speed / p.tait_exponent;
    for (std::size_t i = 0; i < position[f].size(); ++i, ++c) {
      const Vec<D>& x = position[f][i];
      const long long column = f < 2 ? column_of(x) : wall_column(x);
      // A wall particle pushes on the fluid with p V^2 = p / n^2 (the variational pair force):
      // where its kernel is cut (the outer layers) its pressure is lowered by (n / n_0)^2 so
      // that it pushes as a full interior particle at the column's pressure would.
      const double cut = f < 2 ? 1.0 : number_density[c] / interior_n;
      const double pressure = pressure_at(column, x[D - 1]) * cut * cut;
      const double density =
          rest * dmath::pow(1.0 + (pressure - p.background_pressure) / b, 1.0 / p.tait_exponent);
      mass[f][i] = density / number_density[c];
    }
  }
}

template void hydrostatic_masses<2>(const Parameters<2>&, std::array<std::span<const Vec<2>>, 3>,
                                    std::array<std::span<double>, 3>);
template void hydrostatic_masses<3>(const Parameters<3>&, std::array<std::span<const Vec<3>>, 3>,
                                    std::array<std::span<double>, 3>);

} // namespace revsph::two_fluid
