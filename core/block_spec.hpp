#pragma once
// One [[particles]] block as read from the case, before its particles are generated: its kind,
// shape and region (the keys: core/particle_blocks.hpp). What generates the particles
// (core/particle_blocks.cpp) and what asks where a block's solid lies (core/wall_regions.hpp) read
// a block the same way.

#include "core/case_file.hpp"
#include "core/geometry.hpp"
#include "core/particle_blocks.hpp"

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace revsph {

class Outline;
class StlRegion;

// The first D values of a case's list (min, max, centre) as a point.
template <int D>
Vec<D> vec_of(std::span<const double> values) {
  Vec<D> v{};
  for (int k = 0; k < D; ++k) {
    v[k] = values[k];
  }
  return v;
}

// Strictly inside `box`: a point on a face is not (nor NaN).
template <int D>
bool strictly_inside(const Box<D>& box, const Vec<D>& p) {
  bool inside = true;
  for (int k = 0; k < D; ++k) {
    inside = inside && p[k] > box.min[k] && p[k] < box.max[k];
  }
  return inside;
}

enum class BlockShape { box, container, annulus, outline, points, stl };

// shape = "annulus" (2D): inner_radius < |x - centre| < outer_radius.
struct AnnulusSpec {
  Vec<2> centre{};
  double inner_radius = 0.0;
  double outer_radius = 0.0;
};

template <int D>
struct BlockSpec {
  std::string key;  // "particles[2]"
  std::string kind; // as given: the model checks it (read_particle_blocks)
  Lattice lattice = Lattice::square;
  BlockShape shape = BlockShape::box;
  double spacing = 0.0;
  Box<D> region; // [min, max]; a container's hollow; the bounds of other shapes
  Box<D> outer;  // the region grown by a container's layers (the region itself otherwise)
  AnnulusSpec annulus;
  // An outline (2D): its region, the lattice origin its points continue, the shell thickness
  // (0: filled).
  std::shared_ptr<const Outline> outline;
  Vec<2> lattice_origin{};
  double shell = 0.0;
  // Blocks whose regions this block's particles leave out (indices into [[particles]]).
  std::vector<std::size_t> exclude;
  // A points block's particles, read from its file (core/point_file.hpp).
  std::vector<Vec<D>> points;
  double particle_volume = 0.0;
  // An stl block (3D): the surface, and where it goes: x = offset + scale * x_file.
  std::shared_ptr<const StlRegion> stl;
  double stl_scale = 1.0;
  Vec<D> stl_offset{};
};

// Reads block `index` ("particles[index]"), its kind unchecked; `default_spacing` is the case's
// dr. Throws CaseError (one line naming the key) for a bad shape, region, lattice or file.
template <int D>
BlockSpec<D> read_block_spec(const CaseFile& case_file, std::size_t index, double default_spacing);

// Whether `p` is strictly inside an stl block's surface, placed by its scale and offset.
template <int D>
bool inside_stl(const BlockSpec<D>& spec, const Vec<D>& p);

// Whether `p` lies in the region that `exclude_blocks = [i]` leaves out of another block: a
// box's [min, max] (strictly inside), an outline's filled inside (its layers or not), an stl
// surface's inside; false for the other shapes, which exclude nothing.
template <int D>
bool in_excluding_region(const BlockSpec<D>& region, const Vec<D>& p);

} // namespace revsph
