#include "core/close_pairs.hpp"

#include "core/cell_list.hpp"
#include "core/distributed/processes.hpp"
#include "core/finite_positions.hpp"
#include "core/particle_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace revsph {

template <int D>
std::uint64_t count_close_pairs(const CoordinateView<D>& points, std::size_t moving,
                                double distance, const PeriodicBox& box) {
  const std::size_t n = points[0].size();
  if (n < 2 || moving == 0 || !(distance > 0.0)) {
    return 0;
  }
  // The points, then an image of each point within `distance` of a periodic face, shifted by a
  // period, so that a pair across that face is a pair of the cell list's.
  CoordinateArrays<D> all;
  std::vector<std::size_t> origin; // of each image
  for (int k = 0; k < D; ++k) {
    all[k].assign(points[k].begin(), points[k].end());
  }
  if (box.any()) {
    std::vector<ImageShift> shifts;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec<D> p = point_of<D>(points, i);
      image_shifts(p.data(), D, box, distance, shifts);
      for (const ImageShift& shift : shifts) {
        for (int k = 0; k < D; ++k) {
          all[k].push_back(p[k] + shift[k] * box.length(k));
        }
        origin.push_back(i);
      }
    }
  }
  const CoordinateView<D> view = view_of<D>(all);
  Box<D> bounds;
  for (int k = 0; k < D; ++k) {
    const auto [low, high] = std::minmax_element(all[k].begin(), all[k].end());
    bounds.min[k] = *low;
    bounds.max[k] = *high;
  }
  CellList<D> cells(bounds, distance, cell_budget(all[0].size()));
  cells.build(view);
  const double squared = distance * distance;
  std::uint64_t count = 0;
  // A sum of integers: the same in any order, for any thread count.
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (std::size_t i = 0; i < moving; ++i) {
    cells.for_each_candidate(point_of<D>(view, i), [&](std::uint32_t j) {
      const std::size_t o = j < n ? j : origin[j - n];
      // A pair of moving points once (from its higher index), a moving-fixed pair from its
      // moving point; an image pairs like the point it is of.
      if (o == i || (o < moving && o > i)) {
        return;
      }
      count += squared_distance<D>(view, i, j) < squared ? 1 : 0;
    });
  }
  return count;
}

template std::uint64_t count_close_pairs<1>(const CoordinateView<1>&, std::size_t, double,
                                            const PeriodicBox&);
template std::uint64_t count_close_pairs<2>(const CoordinateView<2>&, std::size_t, double,
                                            const PeriodicBox&);
template std::uint64_t count_close_pairs<3>(const CoordinateView<3>&, std::size_t, double,
                                            const PeriodicBox&);

namespace {

template <int D>
std::uint64_t count_own(const StateSnapshot& state, const std::vector<std::string>& moving_sets,
                        const std::vector<std::string>& fixed_sets, double distance,
                        const PeriodicBox& box) {
  CoordinateArrays<D> points;
  append_finite_positions<D>(state, moving_sets, points);
  const std::size_t moving = points[0].size();
  append_finite_positions<D>(state, fixed_sets, points);
  return count_close_pairs<D>(view_of<D>(points), moving, distance, box);
}

} // namespace

ClosePairCount::ClosePairCount(const CaseFile& case_file, const SimulationInfo& info,
                               double fraction)
    : dimension_(info.dimension) {
  if (dimension_ < 1 || dimension_ > 3) {
    throw std::invalid_argument("close pairs: dimension " + std::to_string(dimension_));
  }
  if (!case_file.has("discretisation.dr") || !(fraction > 0.0)) {
    return;
  }
  distance_ = fraction * case_file.positive_number("discretisation.dr");
  box_ = dimension_ == 1   ? read_periodic_box<1>(case_file)
         : dimension_ == 2 ? read_periodic_box<2>(case_file)
                           : read_periodic_box<3>(case_file);
  for (const ParticleCount& set : info.particles) {
    (set.moving ? moving_sets_ : fixed_sets_).push_back(set.particle_set);
  }
}

std::uint64_t ClosePairCount::count(const StateSnapshot& state) const {
  if (!active()) {
    return 0;
  }
  const std::uint64_t own =
      dimension_ == 1   ? count_own<1>(state, moving_sets_, fixed_sets_, distance_, box_)
      : dimension_ == 2 ? count_own<2>(state, moving_sets_, fixed_sets_, distance_, box_)
                        : count_own<3>(state, moving_sets_, fixed_sets_, distance_, box_);
  // Integers: the same sum in any order, on any number of processes.
  return static_cast<std::uint64_t>(
      distributed::sum_over_processes(static_cast<std::int64_t>(own)));
}

} // namespace revsph
