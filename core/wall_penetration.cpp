#include "core/wall_penetration.hpp"

#include "core/finite_positions.hpp"

#include <algorithm>
#include <cmath>

namespace revsph {

template <int D>
WallPenetration<D>::WallPenetration(std::span<const WallRegion<D>> regions,
                                    const StateSnapshot& state)
    : regions_(regions) {
  double reach = 0.0;
  for (const WallRegion<D>& region : regions) {
    const std::optional<Vec<D>> cell = region.particle_cell();
    if (!cell) {
      continue;
    }
    for (int k = 0; k < D; ++k) {
      reach = std::max(reach, (*cell)[k]);
    }
    if (std::find(sets_.begin(), sets_.end(), region.kind()) != sets_.end()) {
      continue;
    }
    if (state.find(region.kind(), "position") == nullptr) {
      continue;
    }
    sets_.push_back(region.kind());
    append_finite_positions<D>(state, {region.kind()}, points_);
    set_.resize(points_[0].size(), static_cast<std::uint32_t>(sets_.size() - 1));
  }
  if (set_.empty()) {
    return;
  }
  Box<D> bounds;
  for (int k = 0; k < D; ++k) {
    const auto [low, high] = std::minmax_element(points_[k].begin(), points_[k].end());
    bounds.min[k] = *low;
    bounds.max[k] = *high;
  }
  // Cells as wide as the widest lattice cell: the candidates around a point hold every particle
  // whose cell can reach it.
  cells_.emplace(bounds, reach, cell_budget(set_.size()));
  cells_->build(view_of<D>(points_));
}

template <int D>
bool WallPenetration<D>::in_a_cell(std::size_t region, const Vec<D>& p) const {
  const WallRegion<D>& wall = regions_[region];
  const Vec<D> cell = *wall.particle_cell();
  bool found = false;
  cells_->for_each_candidate(p, [&](std::uint32_t j) {
    if (found || sets_[set_[j]] != wall.kind()) {
      return;
    }
    bool near = true;
    for (int k = 0; k < D; ++k) {
      near = near && std::abs(p[k] - points_[k][j]) <= 0.5 * cell[k];
    }
    // The block's own particles (in its region): another block of the set has its own spacing.
    found = near && wall.contains(point_of<D>(points_, j));
  });
  return found;
}

template <int D>
std::size_t WallPenetration<D>::region_holding(const Vec<D>& p) const {
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    if (!regions_[r].contains(p)) {
      continue;
    }
    if (!regions_[r].particle_cell() || (cells_ && in_a_cell(r, p))) {
      return r;
    }
  }
  return regions_.size();
}

template class WallPenetration<1>;
template class WallPenetration<2>;
template class WallPenetration<3>;

} // namespace revsph
