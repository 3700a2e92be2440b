#pragma once
// A closed triangle surface read from an STL file (ASCII or binary) and the inside test of the
// volume it encloses, by CGAL (Side_of_triangle_mesh on an AABB tree): what a [[particles]]
// block of shape "stl" fills with lattice points (core/particle_blocks.hpp), as DualSPHysics'
// GenCase fills a closed surface.

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
  // Reads and checks the surface from the file's bytes: a file that cannot be read as STL, holds
  // no triangles or does not enclose a volume (not closed once its duplicated vertices are
  // merged) is refused. Its triangles may face either way: the surface is oriented outward here.
  explicit StlRegion(const InputFile& file);
  ~StlRegion();
  StlRegion(StlRegion&&) noexcept;
  StlRegion& operator=(StlRegion&&) noexcept;

  Box<3> bounds() const;
  double volume() const;
  std::size_t triangle_count() const;
  // Strictly inside (a point on the surface is outside).
  bool contains(const Vec<3>& point) const;
  // The points of `candidates` inside, in their order.
  std::vector<Vec<3>> inside(std::span<const Vec<3>> candidates) const;

private:
  void read(const InputFile& file);
  struct Surface;
  std::unique_ptr<Surface> surface_;
};

} // namespace revsph
