#pragma once
// A closed triangle surface read from an STL file (ASCII or binary) and the inside test of the
// volume it encloses, by CGAL (Side_of_triangle_mesh on an AABB tree): what a [[particles]]
// block of shape "stl" fills with lattice points (core/particle_blocks.hpp), as DualSPHysics'
// GenCase fills a closed surface.
//
// The surface may be several closed shells. A point is inside when its winding number is not 0:
// each shell whose inside holds the point adds +1 if its triangles face outward, -1 if inward
// (the nonzero rule). So shells facing the same way are united, overlapping or not, and a shell
// inside another that faces the other way is a cavity (a hollow body's inner surface); a file
// whose every shell faces inward reads as if they faced outward. Shells facing opposite ways
// must not cross: such a file is refused.

#include "core/case_inputs.hpp"
#include "core/geometry.hpp"

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace revsph {

// One line: the file and what is wrong with it.
class StlError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class StlRegion {
public:
  // Reads and checks the surface from the file's bytes: a file that cannot be read as STL or has a coordinate that is
  // not a finite number (an ASCII file's line or a binary file's triangle named by its number,
  // core/stl_file_check.hpp), holds no triangles, does not enclose a volume (not closed once
  // its duplicated vertices are merged) or has crossing shells of opposite sense is refused
  // (StlError).
  explicit StlRegion(const InputFile& file);
  ~StlRegion();
  StlRegion(StlRegion&&) noexcept;
  StlRegion& operator=(StlRegion&&) noexcept;

  Box<3> bounds() const;
  // The integral of the winding number (a cavity subtracts; where two shells facing the same way
  // overlap counts twice).
  double volume() const;
  std::size_t triangle_count() const;
  std::size_t shell_count() const;
  // Inside by the nonzero rule (a point on any shell is outside).
  bool contains(const Vec<3>& point) const;
  // The points of `candidates` inside, in their order.
  std::vector<Vec<3>> inside(std::span<const Vec<3>> candidates) const;

private:
  void read(const InputFile& file);
  struct Surface;
  std::unique_ptr<Surface> surface_;
};

} // namespace revsph
