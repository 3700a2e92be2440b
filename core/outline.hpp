#pragma once
// A 2D region bounded by a closed polygon whose corners may be rounded: each vertex with a
// radius r > 0 is replaced by the circular arc of radius r tangent to its two edges. The same
// construction rounds a convex corner (material removed) and fills a concave one (a fillet,
// material added). Arcs are kept as fine chords (at most 2 degrees each) for the inside test and
// the distance to the boundary. Used by particle blocks of shape "outline" (the glass bodies of
// the superfluid fountain, paper 3 Fig. 7).

#include "core/geometry.hpp"

#include <string>
#include <vector>

namespace revsph {

class Outline {
public:
  // `vertices` in order (either orientation), at least three; `corner_radii` empty or one per
  // vertex (0: a sharp corner). Throws std::invalid_argument with the reason when a radius does
  // not fit (the arcs at the two ends of an edge would overlap) or the polygon is degenerate.
  Outline(const std::vector<Vec<2>>& vertices, const std::vector<double>& corner_radii);

  // Reflected x -> -x (the mirror image about the y axis), then moved by `offset`.
  Outline transformed(bool mirror_x, const Vec<2>& offset) const;

  // Even-odd rule on the chords.
  bool contains(const Vec<2>& p) const;
  // Distance from p to the boundary (inside or outside).
  double distance_to_boundary(const Vec<2>& p) const;
  Box<2> bounds() const;
  // The enclosed area (shoelace formula on the chords).
  double area() const;
  const std::vector<Vec<2>>& boundary() const { return boundary_; }

private:
  Outline() = default;
  std::vector<Vec<2>> boundary_; // closed: the last point connects to the first
};

// The points origin + (i + 1/2, j + 1/2) spacing of a square lattice that lie inside `outline`;
// with shell > 0 only those within `shell` of its boundary (a wall's layers). Row by row, y
// slowest, like core's lattices.
std::vector<Vec<2>> square_lattice_points(const Outline& outline, const Vec<2>& origin,
                                          double spacing, double shell);

} // namespace revsph
