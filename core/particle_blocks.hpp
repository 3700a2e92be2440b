#pragma once
// Particle blocks of a case file ([[particles]]): regions filled with particles on a square or
// hexagonal lattice.
//
//   kind    = "fluid"            which particle set (the model says which kinds exist)
//   shape   = "box"              "box": the region [min, max] filled;
//                                "container": `layers` lattice layers around the box [min, max]
//                                (its walls), with `open_top = true` leaving the top open;
//                                "annulus" (2D): concentric rings filling inner_radius < |x -
//                                centre| < outer_radius (keys centre, inner_radius, outer_radius;
//                                no lattice, no min/max);
//                                "outline" (2D): a polygon with rounded corners
//                                (core/outline.hpp; keys vertices, corner_radii, mirror_x,
//                                offset, lattice_origin; layers: only a shell that thick),
//                                filled on a square lattice;
//                                "points": the particles of a point file (key file, relative to
//                                the case file's folder; core/point_file.hpp), each standing for
//                                particle_volume (default spacing^D); the file's other columns
//                                are initial values of the set's fields (core/state_fill.hpp);
//                                "stl" (3D): the inside of a closed STL surface (file, scale,
//                                offset; core/stl_region.hpp) filled with the lattice
//   exclude_blocks = [i, ...]    leave out the particles inside those blocks' regions (box or
//                                outline): a fluid around solid bodies
//   lattice = "square"           "square", "hexagonal" (2D: triangular; 3D: hexagonal close
//                                packed), "bcc" (3D: body-centred cubic, cube side `spacing`,
//                                two particles per cube) or "vogel" (2D: a Vogel spiral about
//                                the region's centre, one particle per spacing^2, no lattice
//                                directions)
//   min, max                     corners of the region (m)
//   spacing                      lattice spacing (m), default the case's dr
//
// Particles sit at lattice points at least half a lattice period inside the region, so that
// blocks placed side by side, and a container around a block, continue one lattice.

#include "core/case_file.hpp"
#include "core/geometry.hpp"
#include "core/periodic_box.hpp"
#include "core/point_file.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {

enum class Lattice { square, hexagonal, body_centred_cubic, vogel };

template <int D>
struct ParticleBlock {
  std::string key;  // "particles[2]", for messages
  std::string kind; // "fluid", "wall", …
  std::vector<Vec<D>> positions;
  double volume_per_particle = 0.0; // lattice cell volume (area in 2D)
  double spacing = 0.0;
};

// Lattice points inside `region` (see above). Deterministic order: the last axis slowest.
template <int D>
std::vector<Vec<D>> lattice_points(Lattice lattice, const Box<D>& region, double spacing);

// The lattice's period along each axis (the distance between its rows and layers).
template <int D>
Vec<D> lattice_periods(Lattice lattice, double spacing);

// Volume (2D: area) of one lattice cell, the volume each particle represents.
template <int D>
double lattice_cell_volume(Lattice lattice, double spacing);

// What the particles of a case may cost: a model's memory per particle (state, neighbour lists,
// derived arrays) and the memory available (0: what the machine has free now).
struct ParticleBudget {
  double bytes_per_particle = 0.0; // at the case's dr
  std::size_t memory_bytes = 0;
  // The part of bytes_per_particle that pays for neighbours: a block packed at a spacing s below
  // the case's dr gives each of its particles (dr / s)^D times as many within the kernel's reach.
  double neighbour_bytes_per_particle = 0.0;
};

// How many particles of a lattice at `spacing` lie within `radius` of one (the kernel's reach):
// the memory a model's neighbour lists need per particle scales with it.
double neighbours_within(int dimension, double radius_over_spacing);
// What a particle's neighbours cost in the pair loop's lists: 4 B per neighbour in the half list
// and as much again while it is built.
inline double neighbour_list_bytes(int dimension, double radius_over_spacing) {
  return 8.0 * neighbours_within(dimension, radius_over_spacing);
}

// The budget of a model whose particles cost `other_bytes` each besides their neighbour lists
// (state, slot gathers, sums: the model's estimate) at `radius_over_spacing` (the kernel's reach
// over dr).
inline ParticleBudget particle_budget(int dimension, double radius_over_spacing, double other_bytes,
                                      std::size_t memory_bytes) {
  const double neighbours = neighbour_list_bytes(dimension, radius_over_spacing);
  return {other_bytes + neighbours, memory_bytes, neighbours};
}

// Reads every [[particles]] block. Each generated particle must lie inside `domain`. Before any
// particle is generated, the count is estimated from the block volumes; a case that would not
// fit in memory (or exceeds 2^32 - 1 particles) is refused with the estimate in the message.
template <int D>
std::vector<ParticleBlock<D>>
read_particle_blocks(const CaseFile& case_file, double default_spacing, const Box<D>& domain,
                     std::span<const std::string_view> kinds, const ParticleBudget& budget);

// The file of block `block_key` ("particles[2]"): its key file, as the case's inputs hold it (a
// snapshot's copy) or else read from disk, relative to the case file's folder unless absolute.
const InputFile& block_input_file(const CaseFile& case_file, const std::string& block_key);

// The "points" blocks of `kind` whose files give field values besides positions, as read: what
// fill_set gives the set's fields (core/state_fill.hpp).
template <int D>
struct PointBlockValues {
  std::string key; // "particles[2]"
  PointFile<D> file;
};
template <int D>
std::vector<PointBlockValues<D>> point_blocks_with_values(const CaseFile& case_file,
                                                          std::string_view kind);

// Reads [domain] min/max and checks min < max on every axis: the region particles and their
// periodic images may occupy, grown by half the period on each side of a periodic axis.
template <int D>
Box<D> read_domain(const CaseFile& case_file);

// [domain] periodic ("x", "xy", ...) with the period's faces, domain.min and domain.max.
template <int D>
PeriodicBox read_periodic_box(const CaseFile& case_file);

} // namespace revsph
