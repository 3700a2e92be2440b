#pragma once
// Where the solid of a case's fixed particle blocks lies (walls, dummy and thermal layers): each
// block's region as an inside test, read from its [[particles]] block, so that a run can count the
// moving particles that have passed into a wall, which the pair forces do not stop by themselves
// when a wall's repulsion is too weak for the flow (diagnostics.csv's particles_in_walls,
// docs/running.md). The count asks the region and the cells of the block's particles
// (core/wall_penetration.hpp).
//
//   box        strictly inside [min, max]
//   container  inside its walls: strictly inside the box grown by its layers (with open_top not
//              grown upwards, so that above the box is outside) and not strictly inside [min, max]
//   annulus    inner_radius < |x - centre| < outer_radius
//   outline    inside the outline; with `layers`, only within layers * spacing of its boundary
//              (the shell its particles fill: the body inside the shell is no wall's)
//   stl        inside the closed surface
//   points     no region: a point file's particles bound nothing the case states; left out
// A block's exclude_blocks are left out of its region, as they are of its particles.

#include "core/block_spec.hpp"
#include "core/case_file.hpp"
#include "core/geometry.hpp"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace revsph {

template <int D>
class WallRegion {
public:
  WallRegion(BlockSpec<D> block, std::vector<BlockSpec<D>> excluded);

  const std::string& key() const { return block_.key; } // "particles[1]"
  const std::string& kind() const { return block_.kind; }
  // Whether p lies in the block's solid (see above). NaN is outside.
  bool contains(const Vec<D>& p) const;
  // The extents of the lattice cell each of the block's particles stands for (its lattice
  // periods), or nothing for an annulus, whose rings are no lattice (core/wall_penetration.hpp).
  std::optional<Vec<D>> particle_cell() const;

private:
  bool in_shape(const Vec<D>& p) const;

  BlockSpec<D> block_;
  std::vector<BlockSpec<D>> excluded_; // the blocks its exclude_blocks name
};

// The regions of the blocks whose kind is one of `kinds` (the names of the model's fixed particle
// sets: a block's kind is the set its particles join), in block order; `default_spacing` is the
// case's dr. The case must have been read by its model already (its errors are the model's).
template <int D>
std::vector<WallRegion<D>> read_wall_regions(const CaseFile& case_file, double default_spacing,
                                             std::span<const std::string> kinds);

} // namespace revsph
