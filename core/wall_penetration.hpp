#pragma once
// Which wall a moving particle has passed into (diagnostics.csv's particles_in_walls,
// docs/running.md). A wall's solid is what its particles stand for: the lattice cell around each
// of them (|x_k - w_k| <= period_k / 2 on every axis, the block's lattice periods), within the
// block's region (core/wall_regions.hpp). On a box or a container the cells fill the region
// exactly; on an stl surface or an outline they make a staircase, and a fluid resting in the
// staircase's notches (inside the smooth surface, outside every wall particle's cell) has passed
// into nothing. An annulus's rings fill it: its region alone decides.
//
// The wall particles are the fixed particles of the block's set that lie in its region, at their
// positions in the state.

#include "core/cell_list.hpp"
#include "core/geometry.hpp"
#include "core/state_snapshot.hpp"
#include "core/wall_regions.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace revsph {

template <int D>
class WallPenetration {
public:
  // The fixed particles of `state` whose set is a kind of `regions` (which must outlive this).
  WallPenetration(std::span<const WallRegion<D>> regions, const StateSnapshot& state);

  // The first region whose solid holds p, or regions.size(). NaN is in none.
  std::size_t region_holding(const Vec<D>& p) const;

private:
  bool in_a_cell(std::size_t region, const Vec<D>& p) const;

  std::span<const WallRegion<D>> regions_;
  CoordinateArrays<D> points_;     // the fixed particles of the regions' sets
  std::vector<std::string> sets_;  // their sets' names
  std::vector<std::uint32_t> set_; // per point: its set, an index into sets_
  std::optional<CellList<D>> cells_;
};

} // namespace revsph
