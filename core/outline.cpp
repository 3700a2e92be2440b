#include "core/outline.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace revsph {

namespace {

Vec<2> minus(const Vec<2>& a, const Vec<2>& b) {
  return {a[0] - b[0], a[1] - b[1]};
}
double norm(const Vec<2>& a) {
  return dmath::hypot(a[0], a[1]);
}

double distance_to_segment(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b) {
  const Vec<2> ab = minus(b, a);
  const Vec<2> ap = minus(p, a);
  const double length_squared = ab[0] * ab[0] + ab[1] * ab[1];
  const double t = length_squared > 0.0
                       ? std::clamp((ap[0] * ab[0] + ap[1] * ab[1]) / length_squared, 0.0, 1.0)
                       : 0.0;
  return dmath::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1]);
}

} // namespace

Outline::Outline(const std::vector<Vec<2>>& vertices, const std::vector<double>& corner_radii) {
  const std::size_t n = vertices.size();
  if (n < 3) {
    throw std::invalid_argument("an outline needs at least three vertices");
  }
  if (!corner_radii.empty() && corner_radii.size() != n) {
    throw std::invalid_argument("corner_radii needs one radius per vertex (" + std::to_string(n) +
                                ")");
  }
  // The tangent length of each rounded corner: its arc starts r / tan(theta / 2) from the vertex
  // along both edges, theta the corner's angle; an edge must hold the arcs of both its ends.
  std::vector<double> tangent(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = corner_radii.empty() ? 0.0 : corner_radii[i];
    if (!(r >= 0.0) || !std::isfinite(r)) {
      throw std::invalid_argument("corner radius " + std::to_string(i) + " must be >= 0");
    }
    const Vec<2> in = minus(vertices[(i + n - 1) % n], vertices[i]);
    const Vec<2> out = minus(vertices[(i + 1) % n], vertices[i]);
    if (norm(in) == 0.0 || norm(out) == 0.0) {
      throw std::invalid_argument("vertex " + std::to_string(i) + " repeats its neighbour");
    }
    if (r == 0.0) {
      continue;
    }
    const double cosine = (in[0] * out[0] + in[1] * out[1]) / (norm(in) * norm(out));
    const double theta = dmath::acos(std::clamp(cosine, -1.0, 1.0));
    if (!(theta > 1e-9 && theta < std::numbers::pi - 1e-9)) {
      throw std::invalid_argument("vertex " + std::to_string(i) +
                                  " is straight or folded back: it cannot be rounded");
    }
    tangent[i] = r / dmath::tan(0.5 * theta);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (tangent[i] + tangent[j] > norm(minus(vertices[j], vertices[i])) * (1.0 + 1e-12)) {
      throw std::invalid_argument("corner radii " + std::to_string(i) + " and " +
                                  std::to_string(j) +
                                  " do not fit: their arcs overlap on the edge between them");
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<2>& vertex = vertices[i];
    if (tangent[i] == 0.0) {
      boundary_.push_back(vertex);
      continue;
    }
    const double r = corner_radii[i];
    const Vec<2> in = minus(vertices[(i + n - 1) % n], vertex);
    const Vec<2> out = minus(vertices[(i + 1) % n], vertex);
    const Vec<2> u{in[0] / norm(in), in[1] / norm(in)};
    const Vec<2> w{out[0] / norm(out), out[1] / norm(out)};
    const double theta = dmath::acos(std::clamp(u[0] * w[0] + u[1] * w[1], -1.0, 1.0));
    const Vec<2> start{vertex[0] + tangent[i] * u[0], vertex[1] + tangent[i] * u[1]};
    const Vec<2> end{vertex[0] + tangent[i] * w[0], vertex[1] + tangent[i] * w[1]};
    const Vec<2> bisector{u[0] + w[0], u[1] + w[1]};
    const double centre_distance = r / dmath::sin(0.5 * theta);
    const Vec<2> centre{vertex[0] + centre_distance * bisector[0] / norm(bisector),
                        vertex[1] + centre_distance * bisector[1] / norm(bisector)};
    const double a0 = dmath::atan2(start[1] - centre[1], start[0] - centre[0]);
    const double a1 = dmath::atan2(end[1] - centre[1], end[0] - centre[0]);
    // The short way round: the arc turns by pi - theta.
    double sweep = a1 - a0;
    while (sweep > std::numbers::pi) {
      sweep -= 2.0 * std::numbers::pi;
    }
    while (sweep < -std::numbers::pi) {
      sweep += 2.0 * std::numbers::pi;
    }
    const int chords =
        std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (std::numbers::pi / 90.0))));
    for (int c = 0; c <= chords; ++c) {
      const double angle = a0 + sweep * static_cast<double>(c) / chords;
      boundary_.push_back({centre[0] + r * dmath::cos(angle), centre[1] + r * dmath::sin(angle)});
    }
  }
  if (!(area() > 0.0)) {
    throw std::invalid_argument("the outline encloses no area");
  }
}

Outline Outline::transformed(bool mirror_x, const Vec<2>& offset) const {
  Outline out;
  out.boundary_.reserve(boundary_.size());
  for (const Vec<2>& p : boundary_) {
    out.boundary_.push_back({(mirror_x ? -p[0] : p[0]) + offset[0], p[1] + offset[1]});
  }
  return out;
}

bool Outline::contains(const Vec<2>& p) const {
  bool inside = false;
  const std::size_t n = boundary_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec<2>& a = boundary_[i];
    const Vec<2>& b = boundary_[j];
    if ((a[1] > p[1]) != (b[1] > p[1]) &&
        p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) {
      inside = !inside;
    }
  }
  return inside;
}

double Outline::distance_to_boundary(const Vec<2>& p) const {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = boundary_.size();
  for (std::size_t i = 0; i < n; ++i) {
    best = std::min(best, distance_to_segment(p, boundary_[i], boundary_[(i + 1) % n]));
  }
  return best;
}

Box<2> Outline::bounds() const {
  Box<2> box{boundary_.front(), boundary_.front()};
  for (const Vec<2>& p : boundary_) {
    for (int k = 0; k < 2; ++k) {
      box.min[k] = std::min(box.min[k], p[k]);
      box.max[k] = std::max(box.max[k], p[k]);
    }
  }
  return box;
}

double Outline::area() const {
  double twice = 0.0;
  const std::size_t n = boundary_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<2>& a = boundary_[i];
    const Vec<2>& b = boundary_[(i + 1) % n];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * std::abs(twice);
}

std::vector<Vec<2>> square_lattice_points(const Outline& outline, const Vec<2>& origin,
                                          double spacing, double shell) {
  const Box<2> bounds = outline.bounds();
  std::array<long, 2> first{}, last{};
  for (int k = 0; k < 2; ++k) {
    first[k] = static_cast<long>(std::floor((bounds.min[k] - origin[k]) / spacing - 0.5));
    last[k] = static_cast<long>(std::ceil((bounds.max[k] - origin[k]) / spacing - 0.5));
  }
  std::vector<Vec<2>> points;
  for (long j = first[1]; j <= last[1]; ++j) {
    for (long i = first[0]; i <= last[0]; ++i) {
      const Vec<2> p{origin[0] + (static_cast<double>(i) + 0.5) * spacing,
                     origin[1] + (static_cast<double>(j) + 0.5) * spacing};
      if (outline.contains(p) && (shell <= 0.0 || outline.distance_to_boundary(p) < shell)) {
        points.push_back(p);
      }
    }
  }
  return points;
}

} // namespace revsph
