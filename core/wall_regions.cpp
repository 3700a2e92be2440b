#include "core/wall_regions.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/outline.hpp"

#include <algorithm>
#include <cmath>

namespace revsph {

template <int D>
WallRegion<D>::WallRegion(BlockSpec<D> block, std::vector<BlockSpec<D>> excluded)
    : block_(std::move(block)), excluded_(std::move(excluded)) {}

template <int D>
bool WallRegion<D>::in_shape(const Vec<D>& p) const {
  switch (block_.shape) {
  case BlockShape::box:
    return strictly_inside<D>(block_.region, p);
  case BlockShape::container:
    // `outer` is the box grown by the layers on every side but the top of an open container.
    return strictly_inside<D>(block_.outer, p) && !strictly_inside<D>(block_.region, p);
  case BlockShape::annulus:
    if constexpr (D == 2) {
      const double r =
          dmath::hypot(p[0] - block_.annulus.centre[0], p[1] - block_.annulus.centre[1]);
      return block_.annulus.inner_radius < r && r < block_.annulus.outer_radius;
    }
    return false;
  case BlockShape::outline:
    if constexpr (D == 2) {
      // As the shell's particles were chosen (square_lattice_points).
      return block_.outline->contains(p) &&
             (block_.shell <= 0.0 || block_.outline->distance_to_boundary(p) < block_.shell);
    }
    return false;
  case BlockShape::stl:
    return inside_stl<D>(block_, p);
  case BlockShape::points:
    return false;
  }
  return false;
}

template <int D>
bool WallRegion<D>::contains(const Vec<D>& p) const {
  // Every shape lies within `outer` (its bounds): a cheap test first, for the many particles far
  // from a wall (an stl surface's test is a tree search).
  return block_.outer.contains(p) && in_shape(p) &&
         std::none_of(excluded_.begin(), excluded_.end(),
                      [&](const auto& other) { return in_excluding_region<D>(other, p); });
}

template <int D>
std::optional<Vec<D>> WallRegion<D>::particle_cell() const {
  if (block_.shape == BlockShape::annulus) {
    return std::nullopt;
  }
  return lattice_periods<D>(block_.lattice, block_.spacing);
}

template <int D>
std::vector<WallRegion<D>> read_wall_regions(const CaseFile& case_file, double default_spacing,
                                             std::span<const std::string> kinds) {
  std::vector<WallRegion<D>> regions;
  for (std::size_t b = 0; b < case_file.table_count("particles"); ++b) {
    const std::string key = "particles[" + std::to_string(b) + "]";
    const std::string kind = case_file.string(key + ".kind");
    // A points block is skipped before it is read: its file is not needed.
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end() ||
        case_file.string_or(key + ".shape", "box") == "points") {
      continue;
    }
    BlockSpec<D> block = read_block_spec<D>(case_file, b, default_spacing);
    std::vector<BlockSpec<D>> excluded;
    for (const std::size_t other : block.exclude) {
      excluded.push_back(read_block_spec<D>(case_file, other, default_spacing));
    }
    regions.emplace_back(std::move(block), std::move(excluded));
  }
  return regions;
}

template class WallRegion<1>;
template class WallRegion<2>;
template class WallRegion<3>;
template std::vector<WallRegion<1>> read_wall_regions<1>(const CaseFile&, double,
                                                         std::span<const std::string>);
template std::vector<WallRegion<2>> read_wall_regions<2>(const CaseFile&, double,
                                                         std::span<const std::string>);
template std::vector<WallRegion<3>> read_wall_regions<3>(const CaseFile&, double,
                                                         std::span<const std::string>);

} // namespace revsph
