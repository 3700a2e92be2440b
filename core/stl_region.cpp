#include "core/stl_region.hpp"

#include "core/stl_file_check.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <optional>
#include <sstream>

namespace revsph {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

namespace {

// One closed, connected component of the surface and the sense its triangles face: +1 outward,
// -1 inward (as the file gives them, the first triangle of the shell deciding for the rest).
struct Shell {
  Mesh mesh;
  int winding = 1;
  std::optional<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side; // points into `mesh`
};

} // namespace

struct StlRegion::Surface {
  Mesh mesh;                                  // every shell, as the file turned them
  std::vector<std::unique_ptr<Shell>> shells; // each in place: its `side` holds its mesh
};

StlRegion::StlRegion(const InputFile& file) : surface_(std::make_unique<Surface>()) {
  try {
    read(file);
  } catch (const CGAL::Failure_exception& failure) {
    // A precondition of CGAL's repair or orientation that this surface breaks.
    throw StlError(file.path + ": CGAL cannot use the surface (" + failure.expression() + ")");
  }
}

void StlRegion::read(const InputFile& file) {
  const std::string& path = file.path;
  if (const std::optional<std::string> fault = stl_file_fault(file.bytes)) {
    throw StlError(path + ": " + *fault);
  }
  // An STL file is a soup of triangles, each with its own copies of its corners: merged into
  // one mesh (repair), its faces turned consistently within each shell (orient, which keeps the
  // sense of a shell's first triangle), before anything asks inside.
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> triangles;
  std::istringstream bytes(file.bytes); // CGAL tells ASCII from binary by the first word
  if (!CGAL::IO::read_STL(bytes, points, triangles) || triangles.empty()) {
    throw StlError(path + ": not an STL file with triangles");
  }
  PMP::repair_polygon_soup(points, triangles);
  if (!PMP::orient_polygon_soup(points, triangles)) {
    throw StlError(path + ": the surface cannot be oriented (not a manifold)");
  }
  PMP::polygon_soup_to_polygon_mesh(points, triangles, surface_->mesh);
  if (!CGAL::is_closed(surface_->mesh)) {
    throw StlError(path + ": the surface is not closed (it encloses no volume)");
  }
  std::vector<Mesh> parts;
  PMP::split_connected_components(surface_->mesh, parts);
  for (Mesh& part : parts) {
    auto shell = std::make_unique<Shell>();
    shell->mesh = std::move(part);
    shell->winding = PMP::is_outward_oriented(shell->mesh) ? 1 : -1;
    shell->side.emplace(shell->mesh);
    surface_->shells.push_back(std::move(shell));
  }
  // Shells facing opposite ways that cross leave no sense to the inside (stl_region.hpp).
  const auto& shells = surface_->shells;
  for (std::size_t a = 0; a < shells.size(); ++a) {
    for (std::size_t b = a + 1; b < shells.size(); ++b) {
      if (shells[a]->winding != shells[b]->winding &&
          CGAL::do_overlap(PMP::bbox(shells[a]->mesh), PMP::bbox(shells[b]->mesh)) &&
          PMP::do_intersect(shells[a]->mesh, shells[b]->mesh)) {
        throw StlError(path + ": shells " + std::to_string(a + 1) + " and " +
                       std::to_string(b + 1) +
                       " face opposite ways and cross (a cavity must lie inside its solid)");
      }
    }
  }
}

StlRegion::~StlRegion() = default;
StlRegion::StlRegion(StlRegion&&) noexcept = default;
StlRegion& StlRegion::operator=(StlRegion&&) noexcept = default;

Box<3> StlRegion::bounds() const {
  const CGAL::Bbox_3 box = PMP::bbox(surface_->mesh);
  return Box<3>{{box.xmin(), box.ymin(), box.zmin()}, {box.xmax(), box.ymax(), box.zmax()}};
}

double StlRegion::volume() const {
  // Each shell's signed volume is its winding times its size: their sum is the winding count's
  // integral, which a cavity lowers.
  return std::abs(CGAL::to_double(PMP::volume(surface_->mesh)));
}

std::size_t StlRegion::triangle_count() const {
  return surface_->mesh.number_of_faces();
}

std::size_t StlRegion::shell_count() const {
  return surface_->shells.size();
}

bool StlRegion::contains(const Vec<3>& point) const {
  const Kernel::Point_3 p(point[0], point[1], point[2]);
  int winding = 0;
  for (const auto& shell : surface_->shells) {
    const CGAL::Bounded_side side = (*shell->side)(p);
    if (side == CGAL::ON_BOUNDARY) {
      return false;
    }
    winding += side == CGAL::ON_BOUNDED_SIDE ? shell->winding : 0;
  }
  return winding != 0;
}

std::vector<Vec<3>> StlRegion::inside(std::span<const Vec<3>> candidates) const {
  // Serial: the queries share the AABB trees, which CGAL builds lazily on the first one.
  std::vector<Vec<3>> kept;
  for (const Vec<3>& point : candidates) {
    if (contains(point)) {
      kept.push_back(point);
    }
  }
  return kept;
}

} // namespace revsph
